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

/* Whether the opaque surface at near/d iz_q30 lies so far behind water at linear
 * depth `surface` (Q16.16) that tarn__water_depth_of(iz_q30) - surface is one unit
 * or more however its reciprocal rounds: its exact depth near * 2^30 / iz is at
 * least (surface + 1) * (1 + 2^-7) + 8, a margin over the reciprocal's error
 * without Newton steps (under 2^-8, tarn_math.h) and the floor after it. One
 * product where the depth takes a reciprocal; where it says no, the depth is found. */
static int surely_a_unit_below(const tarn_water_context *w, uint32_t iz_q30, uint32_t surface)
{
    const uint32_t unit_below = surface + Q16_ONE;
    const uint32_t bound = unit_below + (unit_below >> 7) + 8u;
    if (iz_q30 == 0u || bound > (uint32_t)INT32_MAX || surface > (uint32_t)INT32_MAX) return 0;
    const uint32_t near = w->linear.near_mantissa >> w->linear.near_shift; /* Q16.16, exactly */
    return tarn_mul_u32_wide(bound, iz_q30) <= (uint64_t)near << 30;
}

/* Step 2: the refracted sample, or the pixel's own when it would land in front.
 * The own background's depth sets how far the sample may move, saturate(db - ds),
 * which is 1 over water a unit deep or more: there it is found only if the sample
 * does not move or is not taken. */
tarn_water_sample tarn__water_refract(const tarn_water_context *w, int32_t i, int32_t j, tarn_water_normal *n,
                                     uint32_t surface_depth)
{
    const uint32_t own_q30 = tarn__water_background_q30(w, i, j);
    tarn_water_sample own = {i, j, 0u};
    uint32_t reach = Q16_ONE; /* saturate(db - ds), Q0.16 */
    const int deep = surely_a_unit_below(w, own_q30, surface_depth);
    if (!deep) {
        own.depth = tarn__water_depth_of(w, own_q30);
        reach = own.depth > surface_depth ? own.depth - surface_depth : 0u;
        if (reach > Q16_ONE) reach = Q16_ONE;
    }
    int32_t target[2];
    refracted_pixel(w, i, j, n, reach, target);
    if (target[0] != i || target[1] != j) {
        const tarn_water_sample shifted = tarn__water_moved_background(w, target[0], target[1]);
        if (shifted.depth >= surface_depth) return shifted;
    }
    if (deep) own.depth = tarn__water_depth_of(w, own_q30);
    return own;
}
