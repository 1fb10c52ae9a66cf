/* water_refraction.c: step 2 of tarn_water.h, the texel-snapped refracted sample
 * (TARN_WATER_REFRACTION). */
#include "water/water_internal.h"

#define Q16_ONE 65536u

/* The shift in pixels (Q.14) along one axis: N (Q1.30) * pixels per unit normal
 * (Q16.16), cut to +-64 pixels, times saturate(db - ds) (Q0.16). */
static int32_t refracted_shift_q14(const tarn_water_context *w, int32_t normal_q30, uint32_t reach)
{
    const int32_t limit = 64 << 14;
    const int32_t shift = tarn_clamp_i32(tarn_mul_hi_s32_u32(normal_q30, w->refraction_px), -limit, limit);
    return reach >= Q16_ONE ? shift : tarn_mul_hi_s32_u32(shift, reach << 16);
}

/* tarn__water_refracted_pixel's body, inline in tarn__water_refract: a call there
 * cost the M3's balanced pond 9 instructions a pixel. */
static TARN_ALWAYS_INLINE void refracted_pixel(const tarn_water_context *w, int32_t i, int32_t j,
                                              tarn_water_normal *n, uint32_t reach, int32_t target[2])
{
    int32_t normal[2] = {n->xy_q30[0], n->xy_q30[1]};
    if (!TARN_LINK_REFRACTION_EXACT || !w->exact_normal) {
        tarn__water_normalise(n); /* for the steps after this one */
        normal[0] = n->x * 32768;  /* Q1.15 to Q1.30 */
        normal[1] = n->y * 32768;
    }
    target[0] = i;
    target[1] = j;
    for (int k = 0; k < 2; k++) {
        const int32_t shift = refracted_shift_q14(w, normal[k], reach); /* rounded: floor(o + 1/2) */
        target[k] += tarn_clamp_i32(tarn_floor_shift(shift + (1 << 13), 14), -w->offset_limit, w->offset_limit);
    }
    target[0] = tarn_clamp_i32(target[0], w->sample_rect.x0, w->sample_rect.x1 - 1);
    target[1] = tarn_clamp_i32(target[1], w->sample_rect.y0, w->sample_rect.y1 - 1);
}

void tarn__water_refracted_pixel(const tarn_water_context *w, int32_t i, int32_t j, tarn_water_normal *n,
                                 uint32_t reach, int32_t target[2])
{
    refracted_pixel(w, i, j, n, reach, target);
}

/* Step 2: the refracted sample, or the pixel's own when it would land in front. */
tarn_water_sample tarn__water_refract(const tarn_water_context *w, int32_t i, int32_t j, tarn_water_normal *n,
                                     tarn_water_sample own, uint32_t surface_depth)
{
    uint32_t reach = own.depth > surface_depth ? own.depth - surface_depth : 0u;
    if (reach > Q16_ONE) reach = Q16_ONE; /* saturate(db - ds), Q0.16 */
    int32_t target[2];
    refracted_pixel(w, i, j, n, reach, target);
    if (target[0] == i && target[1] == j) return own; /* read already */
    tarn_water_sample shifted = tarn__water_moved_background(w, target[0], target[1]);
    return shifted.depth < surface_depth ? own : shifted;
}
