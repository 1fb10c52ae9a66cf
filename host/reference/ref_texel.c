/* ref_texel.c: the float reference's colours and texels (ref_texel.h). */
#include "ref_texel.h"

#include <math.h>
#include <stddef.h>

double tarn_ref_channel(uint32_t rgb, int c)
{
    return (double)((rgb >> (16 - 8 * c)) & 0xFFu);
}

static int is_power_of_two_up_to(unsigned v, unsigned max)
{
    return v >= 1 && v <= max && (v & (v - 1)) == 0;
}

int tarn_ref_texture_is_valid(const tarn_texture *t)
{
    return t == NULL || (t->rgb != NULL && is_power_of_two_up_to(t->width, TARN_TEXTURE_SIZE_MAX)
                         && is_power_of_two_up_to(t->height, TARN_TEXTURE_SIZE_MAX));
}

double tarn_ref_round_to_byte(double v)
{
    double r = floor(v + 0.5);
    return !(r >= 0) ? 0 : (r > 255 ? 255 : r); /* NaN to 0: never an undefined cast */
}

/* Scenes put texel edges exactly on pixel centres (round sizes, scales and frame
 * widths), where the true coordinate is a whole number of texels and the double
 * that interpolates it lands a few units in its last place to either side. A
 * coordinate this close to a whole number is taken as that number: the floor of an
 * exact tie is the tie. Anything nearer an edge than this by chance is a billion to
 * one, and the double itself is not that good there. */
#define TEXEL_TIE 0x1p-30

static double texel_floor(double x)
{
    double nearest = floor(x + 0.5);
    return fabs(x - nearest) <= TEXEL_TIE ? nearest : floor(x);
}

/* Texel = (floor(u*W) mod W, floor(v*H) mod H), wrapping negatives too. */
const uint8_t *tarn_ref_sample_texel(const tarn_texture *tex, const double uv[2])
{
    double tx = fmod(texel_floor(uv[0] * tex->width), tex->width);
    double ty = fmod(texel_floor(uv[1] * tex->height), tex->height);
    if (tx < 0) tx += tex->width;
    if (ty < 0) ty += tex->height;
    const size_t texel = (size_t)ty * tex->width + (size_t)tx;
    return tex->rgb + (tex->red_only ? texel : 3 * texel);
}
