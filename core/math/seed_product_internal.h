/* seed_product_internal.h: the first Newton step's products, shared by the
 * reciprocal (recip.c) and the reciprocal square root (sqrt.c), internal to core/. */
#ifndef TARN_SEED_PRODUCT_INTERNAL_H
#define TARN_SEED_PRODUCT_INTERNAL_H

#include "tarn/tarn_fixed.h"

/* mul_hi(x, seed << 15) = floor(x * seed / 2^17), exactly, for a 16-bit table seed
 * (Q1.15). Without a native high word, from x's halves times the seed (each below
 * 2^32) joined by nested floors: two 16x16 products where the general high product
 * takes four, which is why a first Newton step from a seed is cheaper than the
 * steps after it. */
static inline uint32_t tarn__times_seed(uint32_t x, uint32_t seed)
{
#if TARN_NATIVE_MUL_HI
    return tarn_mul_hi_u32(x, seed << 15);
#else
    return ((x >> 16) * seed + (((x & 0xFFFFu) * seed) >> 16)) >> 1;
#endif
}

#endif
