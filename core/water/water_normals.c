/* water_normals.c: step 1 of tarn_water.h, the surface normal from the two panning
 * normal maps (TARN_WATER_NORMALS). */
#include "water/water_internal.h"

#define Q15_ONE 32768

static void decode_normal(const uint8_t *texel, int32_t out[3])
{
    for (int k = 0; k < 3; k++) out[k] = tarn__water_normal_component(texel[k]);
}

/* A texel channel's code 2c - 255: the component times 255, exactly. */
static int32_t code_of(uint8_t c)
{
    return 2 * (int32_t)c - 255;
}


/* strength (Q16.16, 0..8) times a sum of two Q1.15 components (below 2^16), in
 * Q2.14 with all of the strength's bits: floor(sum * strength / 2^17), from the
 * strength's top and bottom bits in two 32-bit products (the floor of a floor is
 * the floor), where a 32x32-bit high product costs the M0 three times as much. */
static inline int32_t strength_times(int32_t sum, int32_t strength)
{
    const int32_t low = tarn_floor_shift(sum * (strength & 0xFF), 8); /* below 2^24 */
    return tarn_floor_shift(sum * (strength >> 8) + low, 9);           /* below 2^28 */
}

/* The texels of the two maps under the pixel, b NULL without a second map; 0
 * without normal maps. */
static int map_texels(const tarn_water_context *w, const tarn_water_input *in, const uint8_t **a,
                      const uint8_t **b)
{
    const tarn_water *water = w->water;
    if (water->normal_a == NULL) return 0;
    /* normal maps are R G B (the scene check refuses red alone) */
    *a = tarn__water_panned_texel(water->normal_a, 3u, &water->pan_a, w->pan_a, in);
    *b = water->normal_b != NULL ? tarn__water_panned_texel(water->normal_b, 3u, &water->pan_b, w->pan_b, in) : NULL;
    return 1;
}

/* The flat normal with the maps' own x components, which sparkles read. */
static void maps_x(const uint8_t *a, const uint8_t *b, tarn_water_normal *n)
{
    tarn__water_flat_normal(n);
    n->a_x = tarn__water_normal_component(a[0]);
    n->has_b = b != NULL;
    if (n->has_b) n->b_x = tarn__water_normal_component(b[0]);
}

/* x and y are strength (Q16.16, 0..8) times a sum of codes (|sum| <= 510), below
 * 2^28; z = a.z * b.z = P / 255^2 for the codes' product P is P * 2^16 / 255, which
 * is P * 257 + P / 255, the last rounded through P * 257 / 2^16 (1/255 less 1/2^24).
 * In units of 1 / (2^16 * 255), from the maps' texels a and b (b NULL without a
 * second map). */
static void exact_direction(const tarn_water_context *w, const uint8_t *a, const uint8_t *b, int32_t out[3])
{
    const int32_t strength = w->water->normal_strength;
    const int32_t bx = b != NULL ? code_of(b[0]) : 0, by = b != NULL ? code_of(b[1]) : 0;
    const int32_t bz = b != NULL ? code_of(b[2]) : 255;
    out[0] = strength * (code_of(a[0]) + bx);
    out[1] = strength * (code_of(a[1]) + by);
    const int32_t product = code_of(a[2]) * bz * 257;
    out[2] = product + tarn_floor_shift(product + 32768, 16);
}

/* 1 / |v| for an exact direction v, as a Q16.16 reciprocal square root
 * `inverse` (in (1/sqrt 2, sqrt 2]) and the power of two it leaves out: 1 / |v| =
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
    /* to [2^15, 2^17), Q16.16 in [1/2, 2), by an even shift */
    int even = 31 - (int)tarn_clz32(length2) - 16;
    even += even & 1;
    const uint32_t x = even >= 0 ? length2 >> even : length2 << -even;
    *scale = (int)cut + even / 2 + 8; /* |v| = sqrt(x / 2^16) * 2^(8 + even/2) * 2^cut */
    /* to 2^-15, as v's cut keeps it (tests/test_water.c holds N to Q1.15's units) */
    return tarn_rsqrt15_q16(x);
}

/* floor(v * inverse / 2^15) for |v| < 2^28 and inverse < 2^17: v's bits above and
 * below its 15th times inverse, each product within 32 bits, where the signed
 * 32x32-bit high product takes the Cortex-M0 four and a sign's correction. The
 * high part's share is a whole number of units, so the floor is the low part's. */
static int32_t times_inverse(int32_t v, uint32_t inverse)
{
    const int32_t high = tarn_floor_shift(v, 15); /* -2^13 .. 2^13: |high * inverse| < 2^30 */
    const uint32_t low = (uint32_t)v & 0x7FFFu;   /* low * inverse < 2^32 */
    return high * (int32_t)inverse + (int32_t)((low * inverse) >> 15);
}

/* N found once from the exact direction, for the quality's EXACT refraction normal:
 * N.xy in Q1.30 for refraction, which scales it by tens of pixels and rounds, and
 * N rounded to Q1.15 for the highlight. One reciprocal square root and one read of
 * each map serve both. */
static void exact_normal(const tarn_water_context *w, const uint8_t *a, const uint8_t *b, tarn_water_normal *n)
{
    maps_x(a, b, n);
    int32_t v[3], unit[3];
    exact_direction(w, a, b, v);
    int scale;
    const uint32_t inverse = exact_inverse_length(v, &scale);
    const int up = 29 - scale; /* v * inverse = product * 2^15 */
    for (int k = 0; k < 3; k++) {
        /* v * inverse / 2^15 (|v| < 2^28, inverse < 2^17), then to Q1.30 */
        const int32_t product = times_inverse(v[k], inverse);
        unit[k] = up >= 0 ? product * (1 << up) : tarn_floor_shift(product, (unsigned)-up);
    }
    n->xy_q30[0] = unit[0];
    n->xy_q30[1] = unit[1];
    n->x = tarn_floor_shift(unit[0] + (1 << 14), 15);
    n->y = tarn_floor_shift(unit[1] + (1 << 14), 15);
    n->z = tarn_floor_shift(unit[2] + (1 << 14), 15);
}

void tarn__water_map_x(const tarn_water_context *w, const tarn_water_input *in, tarn_water_normal *n)
{
    const uint8_t *a, *b;
    if (map_texels(w, in, &a, &b)) maps_x(a, b, n); else tarn__water_flat_normal(n);
}

/* Step 1's direction from the maps' texels, strength * (a.xy + b.xy), a.z * b.z,
 * left unnormalised. */
static void direction_normal(const tarn_water_context *w, const uint8_t *texel_a, const uint8_t *texel_b,
                             tarn_water_normal *n)
{
    const tarn_water *water = w->water;
    int32_t a[3], b[3] = {0, 0, Q15_ONE};
    decode_normal(texel_a, a);
    if (texel_b != NULL) decode_normal(texel_b, b);
    tarn__water_flat_normal(n);
    n->a_x = a[0];
    n->b_x = b[0];
    n->has_b = texel_b != NULL;
    const int32_t strength = water->normal_strength;
    int32_t v[3] = {strength_times(a[0] + b[0], strength), strength_times(a[1] + b[1], strength),
                    (a[2] * b[2]) >> 16};
    /* the largest component to [2^13, 2^14): read as Q2.13, |v| is in [1, 2 sqrt 3) */
    int32_t largest = 0;
    for (int k = 0; k < 3; k++) largest |= v[k] < 0 ? -v[k] : v[k];
    if (largest == 0) return;
    const int shift = (int)(31u - tarn_clz32((uint32_t)largest)) - 13;
    for (int k = 0; k < 3; k++) v[k] = shift >= 0 ? tarn_floor_shift(v[k], (unsigned)shift) : v[k] * (1 << -shift);
    n->x = v[0];
    n->y = v[1];
    n->z = v[2];
    n->length2 = (uint32_t)(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); /* Q4.26, < 2^30 */
}

void tarn__water_surface_normal(const tarn_water_context *w, const tarn_water_input *in, tarn_water_normal *n)
{
    const uint8_t *a, *b;
    if (!map_texels(w, in, &a, &b))
        tarn__water_flat_normal(n);
    else if (TARN_LINK_REFRACTION_EXACT && w->exact_normal)
        exact_normal(w, a, b, n);
    else
        direction_normal(w, a, b, n);
}

/* N = direction / |direction|, through the reciprocal square root. */
void tarn__water_normalise(tarn_water_normal *n)
{
    if (n->length2 == 0u) return;
    const int32_t inverse = (int32_t)tarn_rsqrt15_q16(n->length2 >> 10); /* 1/|v|, Q16.16 <= 1; v holds Q2.13 */
    n->x = (n->x * inverse) >> 14; /* Q2.13 * Q16.16 -> Q1.15 */
    n->y = (n->y * inverse) >> 14;
    n->z = (n->z * inverse) >> 14;
    n->length2 = 0u;
}
