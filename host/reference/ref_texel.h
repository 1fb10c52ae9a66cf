/* ref_texel.h: the float reference's colours and texels, in doubles: what
 * reference.c and reference_water.c both read a texture and round a channel with,
 * so that opaque and water pixels sample and round by one definition. */
#ifndef TARN_HOST_REF_TEXEL_H
#define TARN_HOST_REF_TEXEL_H

#include <stdint.h>
#include "tarn/tarn_scene.h"

/* Channel c (0 red, 1 green, 2 blue) of a 0xRRGGBB colour, 0..255. */
double tarn_ref_channel(uint32_t rgb, int c);
/* Nearest integer (halves up), clamped to 0..255; NaN gives 0. */
double tarn_ref_round_to_byte(double v);
/* Texel = (floor(u*W) mod W, floor(v*H) mod H), wrapping negatives too. */
const uint8_t *tarn_ref_sample_texel(const tarn_texture *tex, const double uv[2]);
/* NULL, or texels present and power-of-two sizes within TARN_TEXTURE_SIZE_MAX. */
int tarn_ref_texture_is_valid(const tarn_texture *tex);

#endif
