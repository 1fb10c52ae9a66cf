/* fixed.c: the helpers of tarn_fixed.h that are not inline. */
#include "tarn/tarn_fixed.h"

int64_t tarn_round_shift_i64(int64_t v, unsigned shift)
{
    if (shift == 0) return v;
    /* floor(v / 2^shift), then one more when the remainder is half or above, which
     * is bit shift - 1 of v's two's complement: the same as floor((v + half) /
     * 2^shift) without forming v + half, which overflows near INT64_MAX. A negative
     * v's floor is -1 - floor((-v - 1) / 2^shift), and -v - 1 is ~v: two shifts of
     * non-negative numbers, and no 64-bit negation or mask. */
    const uint64_t bits = (uint64_t)v;
    if (shift < 32u) { /* the usual case, shifted word by word: no 64-bit shifts */
        const uint32_t low = (uint32_t)bits, high = (uint32_t)(bits >> 32);
        const int64_t half_bit = (int64_t)((low >> (shift - 1u)) & 1u);
        /* the shifted magnitude of v, or of ~v for a negative v, as above */
        const uint32_t m_low = v >= 0 ? low : ~low, m_high = v >= 0 ? high : ~high;
        const uint64_t shifted = ((uint64_t)(m_high >> shift) << 32) | (m_high << (32u - shift)) | (m_low >> shift);
        return v >= 0 ? (int64_t)shifted + half_bit : -(int64_t)shifted - 1 + half_bit;
    }
    const int64_t half_bit = (int64_t)((bits >> (shift - 1u)) & 1u);
    if (v >= 0) return (int64_t)(bits >> shift) + half_bit;
    return -(int64_t)(~bits >> shift) - 1 + half_bit;
}

#if defined(__ARM_ARCH_6M__)
int64_t tarn_mul_i32_wide(int32_t a, int32_t b)
{
    /* A negative a is its bits less 2^32, so a * b is the product of the bits less
     * 2^32 * b, and the same for b: the corrections touch the high word only. */
    const uint64_t product = tarn_mul_u32_wide((uint32_t)a, (uint32_t)b);
    const uint32_t high = (uint32_t)(product >> 32) - (a < 0 ? (uint32_t)b : 0u) - (b < 0 ? (uint32_t)a : 0u);
    return (int64_t)(((uint64_t)high << 32) | (uint32_t)product);
}
#endif
