/* water_highlights.c: light glinting off the normal-mapped surface: step 8's
 * specular (TARN_WATER_SPECULAR) and step 10's sparkles (TARN_WATER_SPARKLES). */
#include "water.h"

#define Q15_ONE 32768

/* max(0, N.h)^power, Q1.15. */
static uint32_t specular_term(const tarn_water_context *w, const tarn_water_normal *n)
{
    /* each product is at most 2^30 (both vectors' components within +-1), their sum
     * can pass 2^31 when h is not a unit vector: summed in 64 bits, adds only */
    const int64_t dot = (int64_t)(n->x * w->half_vector[0]) + (int64_t)(n->y * w->half_vector[1]) +
                        (int64_t)(n->z * w->half_vector[2]);
    if (dot <= 0) return 0u;
    const uint64_t cosine = (uint64_t)dot >> 15;
    uint32_t base = (uint32_t)(cosine > Q15_ONE ? Q15_ONE : cosine), result = Q15_ONE;
    for (unsigned power = w->water->specular_power; power != 0u; power >>= 1) {
        if (power & 1u) result = (result * base) >> 15;
        base = (base * base) >> 15;
    }
    return result;
}

void tarn_water_specular(const tarn_water_context *w, const tarn_water_normal *n, uint32_t colour[3])
{
    /* the intensity is within 0..4 (the scene check), which keeps the products in 32 bits */
    const uint32_t amount = (specular_term(w, n) * ((uint32_t)w->water->specular >> 2)) >> 15; /* Q2.14 */
    for (int c = 0; c < 3; c++) colour[c] += (w->light_q8[c] * (amount >> 2)) >> 12;
}

void tarn_water_sparkles(const tarn_water_context *w, const tarn_water_normal *n, uint32_t colour[3])
{
    const uint32_t ax2 = (uint32_t)(n->a_x * n->a_x), bx2 = (uint32_t)(n->b_x * n->b_x);
    if (ax2 <= w->sparkle_threshold || (n->has_b && bx2 <= w->sparkle_threshold)) return;
    for (int c = 0; c < 3; c++) colour[c] += tarn_water_channel_q8(w->water->sparkle_rgb, c);
}
