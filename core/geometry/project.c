/* project.c: view space to the snapped screen grid.
 *
 * No division: each vertex takes one reciprocal of its depth (table seed and two
 * Newton steps, tarn_recip_q30) and every quotient is a product of mantissas with
 * its power of two kept aside, like a small float. On a Cortex-M0, which has no
 * divider, a 64-bit division costs several hundred instructions and a vertex needed
 * three; this costs about a tenth. The relative error is below 2^-27, so a screen
 * coordinate (below 2^15 subpixels inside the guard band) is off by less than
 * 2^-12 subpixel before it is rounded. */
#include "geometry/geometry_internal.h"

/* A positive number as mantissa * 2^-shift, the mantissa's top bit set. */
typedef struct {
    uint32_t mantissa;
    unsigned shift;
} normalised;

/* A positive Q16.32 number (a view coordinate with the 16 bits below its Q16.16
 * that a clipped vertex keeps), below 2^48, as mantissa * 2^-shift in Q16.16 units:
 * the mantissa's top bit set, the shift up to 47. */
#if defined(__GNUC__)
__attribute__((noinline)) /* clipped vertices only: kept out of the common path */
#endif
static normalised normalise_fine(uint64_t v) /* v > 0 */
{
    const uint32_t high = (uint32_t)(v >> 32), low = (uint32_t)v; /* in words: the M0 has no 64-bit shifts */
    normalised n;
    if (high == 0u) {
        const unsigned lz = tarn_clz32(low);
        n.mantissa = low << lz;
        n.shift = lz + 16u;
    } else {
        const unsigned lz = tarn_clz32(high);
        n.mantissa = lz == 0u ? high : (high << lz) | (low >> (32u - lz));
        n.shift = lz - 16u;
    }
    return n;
}

/* |v + low / 2^16| (v Q16.16, low the 16 bits below it: a view coordinate), not 0,
 * normalised; *negative its sign. A mesh's own vertex has no bits below: one 32-bit
 * normalisation, as before the clipper kept them, and most vertices are such. */
static inline normalised normalise_coordinate(tarn_q16 v, uint16_t low, int *negative)
{
    if (low != 0u) {
        const int64_t fine = (int64_t)v * 65536 + low;
        *negative = fine < 0;
        return normalise_fine(fine < 0 ? (uint64_t)0 - (uint64_t)fine : (uint64_t)fine);
    }
    *negative = v < 0;
    const uint32_t magnitude = v < 0 ? (uint32_t)0 - (uint32_t)v : (uint32_t)v;
    normalised n;
    n.shift = tarn_clz32(magnitude);
    n.mantissa = magnitude << n.shift;
    return n;
}

/* round(m * 2^exponent) for the projection's ranges, saturated to INT32_MAX. */
static int32_t scale_rounded(uint32_t m, int exponent)
{
    if (exponent >= 0) return m == 0u ? 0 : INT32_MAX;
    if (exponent < -32) return 0;
    const unsigned k = (unsigned)-exponent;
    const uint32_t half_bit = (m >> (k - 1u)) & 1u;
    const uint32_t whole = k == 32u ? 0u : m >> k;
    return whole > (uint32_t)INT32_MAX - 1u ? INT32_MAX : (int32_t)(whole + half_bit);
}

/* offset * focal / depth in subpixels, rounded: `offset` view units (Q16.16, and
 * `low` the 16 bits below it), the depth given by its normalised reciprocal `recip`
 * (2^62 / mantissa). */
static int32_t subpixels_from_centre(const tarn_view *view, tarn_q16 offset, uint16_t low, normalised depth,
                                     uint32_t recip)
{
    if (offset == 0 && low == 0u) return 0;
    int negative;
    const normalised x = normalise_coordinate(offset, low, &negative);
    /* |offset| / depth = mul_hi(x, recip) * 2^(depth.shift - x.shift - 30) */
    const uint32_t ratio = tarn_mul_hi_u32(x.mantissa, recip);
    /* times focal (Q20.12) and 2^subpixel_bits, back from Q12 */
    const uint32_t product = tarn_mul_hi_u32(ratio << 1, view->focal_mantissa);
    const int exponent = 1 + (int)depth.shift - (int)x.shift - (int)view->focal_shift +
                         (int)view->subpixel_bits - 12;
    const int32_t along = scale_rounded(product, exponent);
    return negative ? -along : along;
}

/* centre + along, clamped to the guard band (in subpixels). The band's ends are
 * within 2^15 subpixels of each other (tarn__config_check), so the clamp is taken
 * on `along` against the ends less the centre, all in 32 bits. */
static int32_t screen_coordinate(const tarn_view *view, int32_t along, int32_t frame_extent)
{
    const unsigned s = view->subpixel_bits;
    const int32_t centre = frame_extent << (s - 1u);
    const int32_t low = -((view->guard_pixels + 1) << s) - centre;
    const int32_t high = ((frame_extent + view->guard_pixels + 1) << s) - centre;
    return centre + (along < low ? low : (along > high ? high : along));
}

/* near / depth in Q1.30 (1 << 30 on the near plane), at least 1; `beyond_near`
 * whether the depth lies past the near plane. */
static uint32_t inverse_depth_q30(const tarn_view *view, int beyond_near, normalised depth, uint32_t recip)
{
    if (!beyond_near) return (uint32_t)1 << 30;
    /* near / depth = mul_hi(near, recip) * 2^(depth.shift - near_shift - 30) */
    const uint32_t ratio_q30 = tarn_mul_hi_u32(view->near_mantissa, recip);
    const unsigned down = view->near_shift - depth.shift; /* depth > near */
    const uint32_t inverse = down >= 32u ? 0u : ratio_q30 >> down;
    return inverse < 1u ? 1u : (inverse > ((uint32_t)1 << 30) ? (uint32_t)1 << 30 : inverse);
}

void tarn__project_position(const tarn_view *view, const tarn_view_vertex *in, tarn_screen_vertex *out)
{
    /* the depth, at least near (where d = near exactly, no bits below) */
    const int beyond_near = in->d > view->near || (in->d == view->near && in->d_low != 0u);
    int positive;
    const normalised depth = beyond_near ? normalise_coordinate(in->d, in->d_low, &positive)
                                         : normalise_coordinate(view->near, 0u, &positive);
    const uint32_t recip = tarn_recip_q30(depth.mantissa, TARN_RECIP_STEPS_MAX);
    out->x = screen_coordinate(view, subpixels_from_centre(view, in->x, in->x_low, depth, recip), view->width);
    /* screen y runs down; |along| <= INT32_MAX, so negating it is safe */
    out->y = screen_coordinate(view, -subpixels_from_centre(view, in->y, in->y_low, depth, recip), view->height);
    out->inv_depth = inverse_depth_q30(view, beyond_near, depth, recip);
}

void tarn__project_attributes(const tarn_view_vertex *in, tarn_screen_vertex *out)
{
    out->uv = in->uv;
    out->uv_low[0] = in->uv_low[0];
    out->uv_low[1] = in->uv_low[1];
    for (int c = 0; c < 3; c++)
        out->lit[c] = (uint16_t)tarn_clamp_i32(in->lit[c], 0, 65280);
    out->fresnel = (uint16_t)tarn_clamp_i32(in->fresnel, 0, 32768);
}

tarn_pixel_box tarn__bounds_pixels(const tarn_subpixel_bounds *b, unsigned s)
{
    const int32_t half = (int32_t)1 << (s - 1);
    tarn_pixel_box box;
    box.x0 = -tarn_floor_shift(half - b->x0, s); /* ceil((min - half) / 2^s) */
    box.y0 = -tarn_floor_shift(half - b->y0, s);
    box.x1 = tarn_floor_shift(b->x1 - half, s);
    box.y1 = tarn_floor_shift(b->y1 - half, s);
    return box;
}

int64_t tarn__drawn_area2(const tarn_screen_vertex in[3], uint8_t cull)
{
    /* coordinates inside the guard box differ by less than 2^15 */
    int64_t area2 = tarn_mul_i16_i32_wide(in[1].x - in[0].x, in[2].y - in[0].y) -
                    tarn_mul_i16_i32_wide(in[1].y - in[0].y, in[2].x - in[0].x);
    int front = area2 < 0; /* counter-clockwise in the y-up world */
    if ((cull == TARN_CULL_BACK && !front) || (cull == TARN_CULL_FRONT && front)) return 0;
    return area2;
}
