/* divide.c: exact division of 64-bit numbers by a prepared 32-bit divisor, with
 * multiplies only (tarn_math.h). */
#include <stddef.h>
#include "tarn/tarn_math.h"

tarn_divisor tarn_divisor_of(uint32_t divisor)
{
    tarn_divisor d;
    d.divisor = divisor == 0u ? 1u : divisor;
    d.shift = tarn_clz32(d.divisor);
    /* two Newton steps land within 2 of 2^62/m; 3 less is never above it */
    const uint32_t recip = tarn_recip_q30(d.divisor << d.shift, TARN_RECIP_STEPS_MAX);
    d.recip = recip > 3u ? recip - 3u : 0u;
    return d;
}

/* n * recip / 2^(62 - shift), the low product's bits below 2^32 dropped (worth
 * less than one unit of the result); divisor > 1, so shift <= 30. At most
 * n / divisor, short of it by about 2^-28 of it plus one. */
static uint64_t times_reciprocal(uint64_t n, const tarn_divisor *d)
{
    const uint64_t high = tarn_mul_u32_wide((uint32_t)(n >> 32), d->recip);
    /* of the low product only its high word counts */
    return (high + tarn_mul_hi_u32((uint32_t)n, d->recip)) >> (30u - d->shift);
}

static uint64_t times_divisor(uint64_t q, uint32_t divisor)
{
    return (tarn_mul_u32_wide((uint32_t)(q >> 32), divisor) << 32) + tarn_mul_u32_wide((uint32_t)q, divisor);
}

uint64_t tarn_divide_u64(uint64_t n, const tarn_divisor *d, uint32_t *remainder)
{
    uint64_t quotient = 0;
    if (d->divisor == 1u) {
        quotient = n;
        n = 0;
    }
    while (n >= d->divisor) {
        uint64_t step = times_reciprocal(n, d);
        uint64_t product = times_divisor(step, d->divisor);
        if (step == 0u || product > n) { /* the second cannot happen; if it did, a 1 is safe */
            step = 1u;
            product = d->divisor;
        }
        quotient += step;
        n -= product;
    }
    if (remainder != NULL) *remainder = (uint32_t)n;
    return quotient;
}

static uint64_t magnitude(int64_t n)
{
    return n < 0 ? (uint64_t)0 - (uint64_t)n : (uint64_t)n;
}

int64_t tarn_divide_floor_i64(int64_t n, const tarn_divisor *d, uint32_t *remainder)
{
    uint32_t r;
    const uint64_t q = tarn_divide_u64(magnitude(n), d, &r);
    if (n >= 0) {
        if (remainder != NULL) *remainder = r;
        return (int64_t)q;
    }
    if (remainder != NULL) *remainder = r != 0u ? d->divisor - r : 0u;
    return -(int64_t)q - (r != 0u);
}

int64_t tarn_divide_trunc_i64(int64_t n, const tarn_divisor *d)
{
    const uint64_t q = tarn_divide_u64(magnitude(n), d, NULL);
    return n < 0 ? -(int64_t)q : (int64_t)q;
}

int64_t tarn_divide_once_i64(int64_t n, uint32_t divisor)
{
    const tarn_divisor d = tarn_divisor_of(divisor);
    return tarn_divide_trunc_i64(n, &d);
}
