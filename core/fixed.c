/* fixed.c: the helpers of tarn_fixed.h that are not inline. */
#include "tarn_fixed.h"

int64_t tarn_round_shift_i64(int64_t v, unsigned shift)
{
    if (shift == 0) return v;
    /* floor(v / 2^shift), then one more when the remainder is half or above: the same
     * as floor((v + half) / 2^shift) without forming v + half, which overflows near
     * INT64_MAX */
    const uint64_t bits = (uint64_t)v; /* its low bits are v mod 2^shift, also for v < 0 */
    const uint64_t mask = ((uint64_t)1 << shift) - 1u;
    const int64_t below = v >= 0 ? (int64_t)(bits >> shift) : -(int64_t)((((uint64_t)0 - bits) + mask) >> shift);
    return below + ((bits & mask) >= ((uint64_t)1 << (shift - 1)));
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
