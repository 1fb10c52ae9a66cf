/* water_highlights.c: light glinting off the normal-mapped surface: step 8's
 * specular (TARN_WATER_SPECULAR) and step 10's sparkles (TARN_WATER_SPARKLES). */
#include "water/water_internal.h"

#define Q15_ONE 32768
/* How far the cosine taken from the normalised N may lie above the exact one, in
 * Q1.15 units: each component of N is within 3 units of its exact value (the
 * square root's rounding and the final shift), and h has three components of at
 * most 1. */
#define COSINE_ERROR_MAX 16

/* base^power in Q1.15, by squaring; never decreasing in the base. */
static uint32_t power_q15(uint32_t base, unsigned power)
{
    uint32_t result = Q15_ONE;
    for (; power != 0u; power >>= 1) {
        if (power & 1u) result = (result * base) >> 15;
        base = (base * base) >> 15;
    }
    return result;
}

/* The highlight's strength from its power term (Q1.15), in Q2.14; the intensity is
 * within 0..4 (the scene check), which keeps the product in 32 bits. */
static uint32_t specular_amount(const tarn_water *water, uint32_t term)
{
    return (term * ((uint32_t)water->specular >> 2)) >> 15;
}

/* Below 4, amount >> 2 adds nothing to any channel. */
static int adds_nothing(const tarn_water *water, uint32_t cosine)
{
    return specular_amount(water, power_q15(cosine, water->specular_power)) < 4u;
}

int32_t tarn__water_dark_cosine(const tarn_water *water)
{
    if (!adds_nothing(water, 0u)) return -1;
    uint32_t dark = 0u, lit = Q15_ONE + 1u; /* dark adds nothing; lit adds, or is past the top */
    while (lit - dark > 1u) {
        const uint32_t middle = (dark + lit) / 2u;
        if (adds_nothing(water, middle)) dark = middle; else lit = middle;
    }
    return (int32_t)dark;
}

/* 1 when N.h, taken exactly from N's direction v, is so far below the dark cosine
 * that the one from the normalised N cannot pass it: v.h <= 0, or
 * (v.h)^2 < bound^2 |v|^2. Then the square root and the power are not needed. The
 * squares are compared in their top bits, rounded so that the test stays
 * conservative: the left side up, the right side down. */
static int highlight_cannot_show(const tarn_water_context *w, const tarn_water_normal *n)
{
    if (n->length2 == 0u || w->dark_cosine < COSINE_ERROR_MAX) return 0;
    /* Q2.13 times Q1.15: each term below 2^29, the sum below 2^31 */
    const int32_t dot = n->x * w->half_vector[0] + n->y * w->half_vector[1] + n->z * w->half_vector[2];
    if (dot <= 0) return 1;
    const uint32_t bound = (uint32_t)(w->dark_cosine - COSINE_ERROR_MAX);
    const uint32_t dot_high = ((uint32_t)dot >> 16) + 1u;                /* at most 2^15 */
    return dot_high * dot_high < ((bound * bound) >> 16) * (n->length2 >> 16); /* both below 2^31 */
}

/* max(0, N.h)^power, Q1.15 (0 where N.h <= 0). */
static uint32_t specular_term(const tarn_water_context *w, const tarn_water_normal *n)
{
    /* each product is at most 2^30 (both vectors' components within +-1), their sum
     * can pass 2^31 when h is not a unit vector: summed in 64 bits, adds only */
    const int64_t dot = (int64_t)(n->x * w->half_vector[0]) + (int64_t)(n->y * w->half_vector[1]) +
                        (int64_t)(n->z * w->half_vector[2]);
    if (dot <= 0) return 0u;
    const int64_t cosine = dot >> 15;
    /* at or below the dark cosine the power adds nothing: spared where N came
     * normalised, so highlight_cannot_show could not look */
    if (cosine <= w->dark_cosine) return 0u;
    return power_q15((uint32_t)(cosine > Q15_ONE ? Q15_ONE : cosine), w->water->specular_power);
}

int tarn__water_specular(const tarn_water_context *w, tarn_water_normal *n, uint32_t highlight[3])
{
    if (highlight_cannot_show(w, n)) return 0;
    tarn__water_normalise(n);
    const uint32_t amount = specular_amount(w->water, specular_term(w, n)); /* Q2.14 */
    for (int c = 0; c < 3; c++) highlight[c] = (w->light_q8[c] * (amount >> 2)) >> 12;
    return 1;
}

int tarn__water_sparkles(const tarn_water_context *w, const tarn_water_normal *n)
{
    const uint32_t ax2 = (uint32_t)(n->a_x * n->a_x), bx2 = (uint32_t)(n->b_x * n->b_x);
    return ax2 > w->sparkle_threshold && (!n->has_b || bx2 > w->sparkle_threshold);
}
