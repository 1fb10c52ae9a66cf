/* sqrt.c: integer square root and reciprocal square root, without a divider. */
#include "tarn/tarn_math.h"
#include "math/math_tables_internal.h"
#include "math/seed_product_internal.h"

uint32_t tarn_isqrt_u32(uint32_t x)
{
    /* Digit by digit in base 4, as in long division: `bit` walks down the even powers
     * of two from the highest one not above x; `root` holds the root's bits found so
     * far, scaled so that root + bit is what the next digit would subtract from x. */
    uint32_t root = 0u;
    uint32_t bit = (uint32_t)1 << 30;
    while (bit > x) bit >>= 2;
    while (bit != 0u) {
        if (x >= root + bit) {
            x -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    return root;
}

uint64_t tarn_isqrt_u64(uint64_t x)
{
    /* With e the least whole number for which q = floor(x / 4^e) fits 32 bits (0 for
     * an x below 2^32) and r = isqrt(q): r^2 <= q <= x / 4^e and (r + 1)^2 >= q + 1 >
     * x / 4^e, so the root R of x lies in [r 2^e, (r + 1) 2^e), below 2^32 (r < 2^16,
     * e <= 16). Its last e bits are then found from the top down, each kept when the
     * square of the root with it is not above x: a 32-bit root, 64-bit squares only
     * for the last bits. */
    const uint32_t top = (uint32_t)(x >> 32);
    const unsigned e = top == 0u ? 0u : (33u - tarn_clz32(top)) >> 1; /* 2e: top's bit length or one more */
    uint32_t root = tarn_isqrt_u32((uint32_t)(x >> (2u * e))) << e;
    for (unsigned b = e; b-- > 0u;) {
        const uint32_t candidate = root | ((uint32_t)1 << b);
        if (tarn_mul_u32_wide(candidate, candidate) <= x) root = candidate;
    }
    return root;
}

/* The first Newton step takes the seed's relative error of 2^-8 to 2^-15, the
 * second to the arithmetic's 2^-28. */
#define ONE_Q28 (1u << 28)

/* A Newton step for 1/sqrt(m) is y' = y + y (1 - m y^2) / 2, from m y^2 (Q4.28,
 * close to 1). In Q2.30, y (1 - m y^2) / 2 is y * |1 - m y^2| / 2^29 =
 * mul_hi(y, |1 - m y^2| << 3); from the seed on |1 - m y^2| < 2^-6, so the shift
 * cannot overflow. */
static uint32_t rsqrt_error(uint32_t m_y_y)
{
    return (m_y_y <= ONE_Q28 ? ONE_Q28 - m_y_y : m_y_y - ONE_Q28) << 3;
}

/* y', given m y^2 and the product y * rsqrt_error(m y^2) / 2^32. */
static uint32_t rsqrt_corrected(uint32_t y, uint32_t m_y_y, uint32_t change)
{
    return m_y_y <= ONE_Q28 ? y + change : y - change;
}

/* One Newton step for 1/sqrt(m). m in Q0.32, y in Q2.30 (1/sqrt(m) is in (1, 2]). */
static uint32_t rsqrt_newton_step(uint32_t m, uint32_t y)
{
    const uint32_t m_y_y = tarn_mul_hi_u32(tarn_mul_hi_u32(m, y), y); /* m y: Q2.30, about sqrt(m) */
    return rsqrt_corrected(y, m_y_y, tarn_mul_hi_u32(y, rsqrt_error(m_y_y)));
}

/* rsqrt_newton_step(m, seed << 15), the same number, by the seed's products: the
 * water normal takes one reciprocal square root a pixel. */
static uint32_t rsqrt_first_step(uint32_t m, uint32_t seed)
{
    const uint32_t m_y_y = tarn__times_seed(tarn__times_seed(m, seed), seed);
    return rsqrt_corrected(seed << 15, m_y_y, tarn__times_seed(rsqrt_error(m_y_y), seed));
}

/* 1/sqrt(x) after the seed's first Newton step, in Q2.30 for x's mantissa m (Q0.32 in
 * [1/4, 1), `*m`), and the shift from Q2.30 to the Q16.16 result (`*shift`); x > 0. */
static uint32_t rsqrt_first_of(uint32_t x_q16, uint32_t *m, unsigned *shift)
{
    /* x = m * 2^(32 - lz) with lz even, so sqrt halves the exponent exactly:
     * 1/sqrt(x / 2^16) in Q16.16 is (1/sqrt(m)) * 2^(8 + lz/2). */
    const unsigned even_lz = tarn_clz32(x_q16) & ~1u; /* 0..30 */
    *m = x_q16 << even_lz;
    *shift = 22u - (even_lz >> 1); /* 7..22 */
    return rsqrt_first_step(*m, tarn__rsqrt_seed_q15[(*m >> 24) - TARN_RSQRT_SEED_FIRST]);
}

/* y (Q2.30) to Q16.16 by `shift`, rounded to nearest. */
static uint32_t rsqrt_result(uint32_t y, unsigned shift)
{
    return (y + (1u << (shift - 1u))) >> shift;
}

uint32_t tarn_rsqrt_q16(uint32_t x_q16)
{
    if (x_q16 == 0u) return 0u;
    uint32_t m;
    unsigned shift;
    const uint32_t y = rsqrt_first_of(x_q16, &m, &shift);
    return rsqrt_result(rsqrt_newton_step(m, y), shift);
}

uint32_t tarn_rsqrt15_q16(uint32_t x_q16)
{
    if (x_q16 == 0u) return 0u;
    uint32_t m;
    unsigned shift;
    const uint32_t y = rsqrt_first_of(x_q16, &m, &shift);
    return rsqrt_result(y, shift);
}
