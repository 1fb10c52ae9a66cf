/* water_refraction.c: step 2 of tarn_water.h, the texel-snapped refracted sample
 * (TARN_WATER_REFRACTION). */
#include "water/water_internal.h"

#define Q16_ONE 65536u

/* 1 / |v| for an exact direction v, as a Q16.16 reciprocal square root
 * `inverse` (in (1/2, 1]) and the power of two it leaves out: 1 / |v| =
 * inverse * 2^-(16 + scale). |v| is found from v cut to 15 bits, so to 2^-15 of
 * itself; the direction's own bits are kept whole for the product. */
static uint32_t exact_inverse_length(const int32_t v[3], int *scale)
{
    uint32_t largest = 1u;
    for (int k = 0; k < 3; k++) largest |= (uint32_t)(v[k] < 0 ? -v[k] : v[k]);
    const int bits = 32 - (int)tarn_clz32(largest);
    const unsigned cut = bits > 15 ? (unsigned)(bits - 15) : 0u;
    uint32_t length2 = 0u; /* below 3 * 2^30 */
    for (int k = 0; k < 3; k++) {
        const int32_t c = tarn_floor_shift(v[k], cut);
        length2 += (uint32_t)(c * c);
    }
    /* to [2^16, 2^18), Q16.16 in [1, 4), by an even shift */
    int even = 31 - (int)tarn_clz32(length2) - 16;
    even += even & 1;
    const uint32_t x = even >= 0 ? length2 >> even : length2 << -even;
    *scale = (int)cut + even / 2 + 8; /* |v| = sqrt(x / 2^16) * 2^(8 + even/2) * 2^cut */
    return tarn_rsqrt_q16(x);
}

/* N.x and N.y in Q1.30 from the exact direction (tarn__water_exact_direction). */
static void exact_normal_xy(const tarn_water_context *w, const tarn_water_input *in, int32_t out[2])
{
    int32_t v[3];
    tarn__water_exact_direction(w, in, v);
    int scale;
    const uint32_t inverse = exact_inverse_length(v, &scale);
    for (int k = 0; k < 2; k++) {
        /* v * inverse / 2^15 (|v| < 2^28, inverse <= 2^16), then to Q1.30 */
        const int32_t product = tarn_mul_hi_s32_u32(v[k] * 4, inverse << 15);
        const int up = 29 - scale; /* v * inverse = product * 2^15 */
        out[k] = up >= 0 ? product * (1 << up) : tarn_floor_shift(product, (unsigned)-up);
    }
}

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
                                              const tarn_water_input *in, tarn_water_normal *n, uint32_t reach,
                                              int32_t target[2])
{
    tarn__water_normalise(n); /* for the steps after this one */
    int32_t normal[2] = {n->x * 32768, n->y * 32768}; /* Q1.15 to Q1.30 */
    if (TARN_LINK_REFRACTION_EXACT && w->refraction_exact) exact_normal_xy(w, in, normal);
    target[0] = i;
    target[1] = j;
    for (int k = 0; k < 2; k++) {
        const int32_t shift = refracted_shift_q14(w, normal[k], reach); /* rounded: floor(o + 1/2) */
        target[k] += tarn_clamp_i32(tarn_floor_shift(shift + (1 << 13), 14), -w->offset_limit, w->offset_limit);
    }
    target[0] = tarn_clamp_i32(target[0], w->sample_rect.x0, w->sample_rect.x1 - 1);
    target[1] = tarn_clamp_i32(target[1], w->sample_rect.y0, w->sample_rect.y1 - 1);
}

void tarn__water_refracted_pixel(const tarn_water_context *w, int32_t i, int32_t j, const tarn_water_input *in,
                                 tarn_water_normal *n, uint32_t reach, int32_t target[2])
{
    refracted_pixel(w, i, j, in, n, reach, target);
}

/* Step 2: the refracted sample, or the pixel's own when it would land in front. */
tarn_water_sample tarn__water_refract(const tarn_water_context *w, int32_t i, int32_t j,
                                     const tarn_water_input *in, tarn_water_normal *n, tarn_water_sample own,
                                     uint32_t surface_depth)
{
    uint32_t reach = own.depth > surface_depth ? own.depth - surface_depth : 0u;
    if (reach > Q16_ONE) reach = Q16_ONE; /* saturate(db - ds), Q0.16 */
    int32_t target[2];
    refracted_pixel(w, i, j, in, n, reach, target);
    if (target[0] == i && target[1] == j) return own; /* read already */
    tarn_water_sample shifted = tarn__water_moved_background(w, target[0], target[1]);
    return shifted.depth < surface_depth ? own : shifted;
}
