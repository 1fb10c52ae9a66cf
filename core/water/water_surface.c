/* water_surface.c: the surface's own colour and opacity: step 6's depth colour
 * (TARN_WATER_DEPTH_COLOUR: shallow to deep, or a colour ramp) and step 7's fresnel
 * raise of alpha (TARN_WATER_FRESNEL). */
#include "water/water_internal.h"

#define Q16_ONE 65536u
#define Q15_ONE 32768

void tarn__water_depth_colour(const tarn_water_context *w, uint32_t diff, uint32_t out[3])
{
    const tarn_water *water = w->water;
    uint32_t t = tarn__water_mul_q16(diff, w->inv_depth_scale);
    if (t > Q16_ONE) t = Q16_ONE;
    if (water->colour_ramp != NULL) {
        const tarn_texture *ramp = water->colour_ramp;
        const uint32_t x = (t * (uint32_t)(ramp->width - 1u) + 32768u) >> 16;
        for (int c = 0; c < 3; c++) out[c] = (uint32_t)ramp->rgb[3u * x + (uint32_t)c] << 8;
        return;
    }
    for (int c = 0; c < 3; c++) {
        const int32_t shallow = (int32_t)tarn__water_channel_q8(water->shallow_rgb, c);
        const int32_t deep = (int32_t)tarn__water_channel_q8(water->deep_rgb, c);
        out[c] = (uint32_t)(shallow + ((deep - shallow) * (int32_t)(t >> 1)) / Q15_ONE);
    }
}

uint32_t tarn__water_fresnel_alpha(const tarn_water_context *w, const tarn_water_input *in, uint32_t alpha)
{
    const uint32_t raise = ((uint32_t)w->water->fresnel >> 1) * in->fresnel >> 15; /* fresnel in [0, 1] */
    return alpha + (((32768u - alpha) * raise) >> 15);
}
