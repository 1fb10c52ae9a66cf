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
    *a = tarn__water_panned_texel(water->normal_a, &water->pan_a, w->pan_a, in);
    *b = water->normal_b != NULL ? tarn__water_panned_texel(water->normal_b, &water->pan_b, w->pan_b, in) : NULL;
    return 1;
}

/* x and y are strength (Q16.16, 0..8) times a sum of codes (|sum| <= 510), below
 * 2^28; z = a.z * b.z = P / 255^2 for the codes' product P is P * 2^16 / 255, which
 * is P * 257 + P / 255, the last rounded through P * 257 / 2^16 (1/255 less 1/2^24). */
void tarn__water_exact_direction(const tarn_water_context *w, const tarn_water_input *in, int32_t out[3])
{
    const uint8_t *a, *b;
    if (!tarn__water_uses(w, TARN_WATER_NORMALS) || !map_texels(w, in, &a, &b)) {
        out[0] = out[1] = 0;
        out[2] = 65536 * 255;
        return;
    }
    const int32_t strength = w->water->normal_strength;
    const int32_t bx = b != NULL ? code_of(b[0]) : 0, by = b != NULL ? code_of(b[1]) : 0;
    const int32_t bz = b != NULL ? code_of(b[2]) : 255;
    out[0] = strength * (code_of(a[0]) + bx);
    out[1] = strength * (code_of(a[1]) + by);
    const int32_t product = code_of(a[2]) * bz * 257;
    out[2] = product + tarn_floor_shift(product + 32768, 16);
}

tarn_water_normal tarn__water_map_x(const tarn_water_context *w, const tarn_water_input *in)
{
    tarn_water_normal n = tarn__water_flat_normal();
    const uint8_t *a, *b;
    if (!map_texels(w, in, &a, &b)) return n;
    n.a_x = tarn__water_normal_component(a[0]);
    n.has_b = b != NULL;
    if (n.has_b) n.b_x = tarn__water_normal_component(b[0]);
    return n;
}

/* Step 1's direction, strength * (a.xy + b.xy), a.z * b.z, left unnormalised. */
tarn_water_normal tarn__water_surface_normal(const tarn_water_context *w, const tarn_water_input *in)
{
    const tarn_water *water = w->water;
    tarn_water_normal n = tarn__water_flat_normal();
    const uint8_t *texel_a, *texel_b;
    if (!map_texels(w, in, &texel_a, &texel_b)) return n;
    int32_t a[3], b[3] = {0, 0, Q15_ONE};
    decode_normal(texel_a, a);
    n.has_b = texel_b != NULL;
    if (n.has_b) decode_normal(texel_b, b);
    n.a_x = a[0];
    n.b_x = b[0];
    const int32_t strength = water->normal_strength;
    int32_t v[3] = {strength_times(a[0] + b[0], strength), strength_times(a[1] + b[1], strength),
                    (a[2] * b[2]) >> 16};
    /* the largest component to [2^13, 2^14): read as Q2.13, |v| is in [1, 2 sqrt 3) */
    int32_t largest = 0;
    for (int k = 0; k < 3; k++) largest |= v[k] < 0 ? -v[k] : v[k];
    if (largest == 0) return n;
    const int shift = (int)(31u - tarn_clz32((uint32_t)largest)) - 13;
    for (int k = 0; k < 3; k++) v[k] = shift >= 0 ? tarn_floor_shift(v[k], (unsigned)shift) : v[k] * (1 << -shift);
    n.x = v[0];
    n.y = v[1];
    n.z = v[2];
    n.length2 = (uint32_t)(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); /* Q4.26, < 2^30 */
    return n;
}

/* N = direction / |direction|, through the reciprocal square root. */
void tarn__water_normalise(tarn_water_normal *n)
{
    if (n->length2 == 0u) return;
    const int32_t inverse = (int32_t)tarn_rsqrt_q16(n->length2 >> 10); /* 1/|v|, Q16.16 <= 1 */
    n->x = (n->x * inverse) >> 14; /* Q2.13 * Q16.16 -> Q1.15 */
    n->y = (n->y * inverse) >> 14;
    n->z = (n->z * inverse) >> 14;
    n->length2 = 0u;
}
