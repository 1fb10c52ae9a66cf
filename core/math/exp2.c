/* exp2.c: 2^x for x <= 0 (fog and absorption factors), without a divider.
 *
 * With -x = whole + frac/65536, 2^x = 2^-whole * 2^-(frac/65536): the fraction indexes
 * the 257-entry table of 2^-(i/256), the whole part becomes a right shift. */
#include "tarn/tarn_math.h"
#include "math/math_tables_internal.h"

#define EXP2_TABLE_BITS 8u     /* log2(TARN_EXP2_TABLE_STEPS) */
#define EXP2_MIN_INDEX_BITS 3u /* log2(TARN_EXP2_ENTRIES_MIN) */
#define Q16_FRACTION_BITS 16u

/* log2 of the table size actually used. Sizes below TARN_EXP2_ENTRIES_MIN or above
 * TARN_EXP2_ENTRIES_MAX clamp to those limits, and sizes in between that are not a
 * power of two round down to one, so no configuration can index past the table. */
static unsigned exp2_index_bits(uint16_t entries)
{
    if (entries >= TARN_EXP2_ENTRIES_MAX) return EXP2_TABLE_BITS;
    if (entries <= TARN_EXP2_ENTRIES_MIN) return EXP2_MIN_INDEX_BITS;
    return 31u - tarn_clz32(entries);
}

uint32_t tarn_exp2_neg_q16(tarn_q16 x, tarn_exp2_config config)
{
    /* -x in unsigned arithmetic: exact for INT32_MIN too; positive x clamps to 0. */
    uint32_t neg_x = x > 0 ? 0u : 0u - (uint32_t)x;
    uint32_t whole = neg_x >> Q16_FRACTION_BITS;
    uint32_t frac = neg_x & 0xFFFFu;

    unsigned index_bits = exp2_index_bits(config.entries);
    unsigned weight_bits = Q16_FRACTION_BITS - index_bits; /* fraction bits below the index */
    unsigned stride_bits = EXP2_TABLE_BITS - index_bits;   /* a smaller table skips entries */
    uint32_t i = (frac >> weight_bits) << stride_bits;
    uint32_t upper = TARN_EXP2_TABLE_HALF_Q16 + tarn__exp2_over_half_q16[i]; /* 2^-(i/256) */
    uint32_t lower = TARN_EXP2_TABLE_HALF_Q16 + tarn__exp2_over_half_q16[i + (1u << stride_bits)]; /* the next */
    /* Nearest-below uses the entry as is: weight 0. */
    uint32_t weight = config.interpolate ? frac & ((1u << weight_bits) - 1u) : 0u;

    /* Q0.(16 + weight_bits), at most 2^29: the entry minus the weighted fall to the
     * next one. Kept unrounded so the only rounding is the final shift. */
    uint32_t mantissa = (upper << weight_bits) - (upper - lower) * weight;
    uint32_t shift = whole + weight_bits;
    /* mantissa < 2^30 rounds to 0 at these shifts; returning early also keeps every
     * shift below 32. */
    if (shift >= 31u) return 0u;
    return (mantissa + (1u << (shift - 1u))) >> shift;
}
