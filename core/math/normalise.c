/* normalise.c: the unit vector along a vector of 64-bit integers, once a frame (the
 * camera's axes, a moving light): firmware compiles it for size. */
#include "tarn/tarn_math.h"

static int64_t largest_magnitude(const int64_t c[3])
{
    int64_t largest = 0;
    for (int i = 0; i < 3; i++) {
        const int64_t magnitude = c[i] < 0 ? -c[i] : c[i];
        if (magnitude > largest) largest = magnitude;
    }
    return largest;
}

int tarn_normalise_q30(const int64_t v[3], int32_t out[3])
{
    int64_t c[3] = {v[0], v[1], v[2]};
    int64_t largest = largest_magnitude(c);
    if (largest == 0) return 0;
    /* A power of two brings the largest component into [2^16, 2^31): below 2^31 the
     * squares and their sum fit 64 bits, and from 2^16 the integer square root is
     * good to 2^-16. (The root of (1, 0, 1)'s 2 is 1, which made a vector of length
     * 1.41: found by fuzz_core, through a camera a hair from its target.) */
    for (; largest >= ((int64_t)1 << 31); largest /= 2)
        for (int i = 0; i < 3; i++) c[i] /= 2;
    for (; largest < ((int64_t)1 << 16); largest *= 2)
        for (int i = 0; i < 3; i++) c[i] *= 2;
    uint64_t sum = 0;
    for (int i = 0; i < 3; i++) sum += (uint64_t)(c[i] * c[i]);
    int64_t length = (int64_t)tarn_isqrt_u64(sum); /* from 2^16 to below 2^32 */
    const tarn_divisor divisor = tarn_divisor_of((uint32_t)length);
    for (int i = 0; i < 3; i++)
        out[i] = (int32_t)tarn_divide_trunc_i64(c[i] * ((int64_t)1 << 30), &divisor);
    return 1;
}
