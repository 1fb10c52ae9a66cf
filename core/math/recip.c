/* recip.c: reciprocals without a divider, for the per-pixel perspective divide.
 *
 * x is normalised to a mantissa m in [1/2, 1) (x = m * 2^(32 - lz)), so
 * 2^32 / x = (1/m) * 2^lz. A table indexed by the top bits of m seeds 1/m, and each
 * Newton step y' = y + y (1 - m y) roughly doubles the number of correct bits. */
#include "tarn/tarn_math.h"
#include "math/math_tables_internal.h"
#include "math/seed_product_internal.h"

#define ONE_Q30 (1u << 30)
#define TOP_BIT 0x80000000u

/* A Newton step for 1/m is y' = y + y (1 - m y), from m y (Q2.30, close to 1). In
 * Q2.30, y (1 - m y) is y * |1 - m y| / 2^30 = mul_hi(y, |1 - m y| << 2); the seed
 * keeps |1 - m y| below 2^-8, so the shift cannot overflow. */
static uint32_t newton_error(uint32_t m_y)
{
    return (m_y <= ONE_Q30 ? ONE_Q30 - m_y : m_y - ONE_Q30) << 2;
}

/* y', given m y and the product y * newton_error(m y) / 2^32. */
static uint32_t newton_corrected(uint32_t y, uint32_t m_y, uint32_t change)
{
    return m_y <= ONE_Q30 ? y + change : y - change;
}

/* One Newton step for 1/m. m in Q0.32, y in Q2.30 (1/m is in (1, 2]). */
static uint32_t recip_newton_step(uint32_t m, uint32_t y)
{
    const uint32_t m_y = tarn_mul_hi_u32(m, y);
    return newton_corrected(y, m_y, tarn_mul_hi_u32(y, newton_error(m_y)));
}

/* recip_newton_step(m, seed << 15), the same number, by the seed's products. */
static uint32_t recip_first_step(uint32_t m, uint32_t seed)
{
    const uint32_t m_y = tarn__times_seed(m, seed);
    return newton_corrected(seed << 15, m_y, tarn__times_seed(newton_error(m_y), seed));
}

/* 1/m in Q2.30 for m in Q0.32 with its top bit set. */
static uint32_t recip_normalised_q30(uint32_t m, unsigned newton_steps)
{
    uint32_t seed_index = (m >> (31u - TARN_RECIP_SEED_BITS)) & ((1u << TARN_RECIP_SEED_BITS) - 1u);
    const uint32_t seed = tarn__recip_seed_q15[seed_index];
    if (newton_steps == 0u) return seed << 15;
    uint32_t y = recip_first_step(m, seed);
    /* more steps than the maximum gain nothing; clamping also bounds the time */
    unsigned steps = newton_steps < TARN_RECIP_STEPS_MAX ? newton_steps : TARN_RECIP_STEPS_MAX;
    for (unsigned step = 1; step < steps; step++) y = recip_newton_step(m, y);
    return y;
}

uint32_t tarn_recip_q30(uint32_t mantissa, unsigned newton_steps)
{
    if (mantissa == 0u) return UINT32_MAX;
    if ((mantissa & TOP_BIT) == 0u) mantissa <<= tarn_clz32(mantissa);
    return recip_normalised_q30(mantissa, newton_steps);
}

uint32_t tarn_recip_u32(uint32_t x, unsigned newton_steps)
{
    if (x <= 1u) return UINT32_MAX;
    unsigned lz = tarn_clz32(x); /* 0..30 */
    uint32_t y = recip_normalised_q30(x << lz, newton_steps);
    /* (1/m) * 2^lz from Q2.30, rounded to nearest */
    unsigned shift = 30u - lz;
    if (shift == 0u) return y;
    return (y + (1u << (shift - 1u))) >> shift;
}
