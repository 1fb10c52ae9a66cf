/* water_refraction.c: step 2 of tarn_water.h, the texel-snapped refracted sample
 * (TARN_WATER_REFRACTION). */
#include "water/water_internal.h"

#define Q16_ONE 65536u

/* Step 2: the refracted sample, or the pixel's own when it would land in front. */
tarn_water_sample tarn__water_refract(const tarn_water_context *w, int32_t i, int32_t j,
                                     tarn_water_normal *n, tarn_water_sample own, uint32_t surface_depth)
{
    tarn__water_normalise(n);
    uint32_t reach = own.depth > surface_depth ? own.depth - surface_depth : 0u;
    if (reach > Q16_ONE) reach = Q16_ONE; /* saturate(db - ds), Q0.16 */
    const int32_t normal[2] = {n->x, n->y};
    int32_t target[2] = {i, j};
    for (int k = 0; k < 2; k++) {
        /* N (Q1.15) * pixels per unit normal (Q16.16) / 2^18 -> pixels, Q18.14 */
        int32_t offset_q14 = tarn_mul_hi_s32_u32(normal[k] * (1 << 15), w->refraction_px);
        offset_q14 = tarn_clamp_i32(offset_q14, -(64 << 14), 64 << 14);
        /* times saturate(db - ds): (offset * 2^10) * (reach * 2^6) / 2^32 */
        offset_q14 = tarn_mul_hi_s32_u32(offset_q14 * (1 << 10), reach << 6);
        target[k] += tarn_clamp_i32(tarn_floor_shift(offset_q14 + (1 << 13), 14), -w->offset_limit, w->offset_limit);
    }
    target[0] = tarn_clamp_i32(target[0], w->sample_rect.x0, w->sample_rect.x1 - 1);
    target[1] = tarn_clamp_i32(target[1], w->sample_rect.y0, w->sample_rect.y1 - 1);
    if (target[0] == i && target[1] == j) return own; /* read already */
    tarn_water_sample shifted = tarn__water_background(w, target[0], target[1]);
    return shifted.depth < surface_depth ? own : shifted;
}
