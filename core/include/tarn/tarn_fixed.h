/* tarn_fixed.h: the fixed-point number formats of tarn and their helpers.
 *
 * Formats (Qm.n: m integer bits including sign where signed, n fraction bits):
 *   tarn_q16   Q16.16 signed   world coordinates, matrices, scene scalars (1.0 = 65536)
 *   Q1.15      signed          sin/cos results, unit-vector components per pixel
 *   Q0.16      unsigned        exp2 results and blend factors (1.0 = 65536, held in 32 bits)
 *   Q1.30      unsigned        inverse depth near/depth (1.0 = 1 << 30, at the near plane)
 *   Q8.8       unsigned        8-bit colour channels with 8 fraction bits (255.0 = 65280)
 *
 * Rounding is to nearest, ties away from zero, unless a name says otherwise.
 * Saturation clamps to the representable range instead of wrapping. */
#ifndef TARN_FIXED_H
#define TARN_FIXED_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef int32_t tarn_q16; /* Q16.16 */

#define TARN_Q16_ONE ((tarn_q16)65536)
#define TARN_Q16_MAX ((tarn_q16)INT32_MAX)
#define TARN_Q16_MIN ((tarn_q16)INT32_MIN)

static inline int32_t tarn_sat_i64_to_i32(int64_t v)
{
    if (v > INT32_MAX) return INT32_MAX;
    if (v < INT32_MIN) return INT32_MIN;
    return (int32_t)v;
}

static inline int32_t tarn_clamp_i32(int32_t v, int32_t lo, int32_t hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

static inline int32_t tarn_min3_i32(int32_t a, int32_t b, int32_t c)
{
    const int32_t ab = a < b ? a : b;
    return ab < c ? ab : c;
}

static inline int32_t tarn_max3_i32(int32_t a, int32_t b, int32_t c)
{
    const int32_t ab = a > b ? a : b;
    return ab > c ? ab : c;
}

/* Arithmetic shift right of a signed 64-bit value, rounding to nearest (ties up),
 * for shift < 64, over the whole int64_t range. Written with division-free
 * operations so the result does not depend on how a compiler treats >> of negative
 * values. A function of its own (core/math/fixed.c) rather than inline: it runs per
 * vertex, not per pixel, and inlined into every caller it cost the Cortex-M0 image
 * half a kilobyte. */
int64_t tarn_round_shift_i64(int64_t v, unsigned shift);

/* Q16.16 product, rounded and saturated. Uses a 64-bit multiply: per vertex or
 * per frame only, never per pixel (Cortex-M0 has no 32x32->64 multiplier). */
static inline tarn_q16 tarn_q16_mul(tarn_q16 a, tarn_q16 b)
{
    return tarn_sat_i64_to_i32(tarn_round_shift_i64((int64_t)a * b, 16));
}

/* Saturating Q16.16 sum. */
static inline tarn_q16 tarn_q16_add(tarn_q16 a, tarn_q16 b)
{
    return tarn_sat_i64_to_i32((int64_t)a + b);
}

/* Q16.16 from a whole number, saturated. */
static inline tarn_q16 tarn_q16_from_int(int32_t v)
{
    return tarn_sat_i64_to_i32((int64_t)v * 65536);
}

/* floor(v / 2^s), s < 32, without >> of a negative number, which C99 leaves to
 * the implementation: the same number on every compiler. */
static inline int32_t tarn_floor_shift_portable(int32_t v, unsigned s)
{
    if (s == 0u) return v; /* below, INT32_MIN's magnitude would not fit an int32_t */
    return v >= 0 ? (v >> s) : -(int32_t)((((uint32_t)0 - (uint32_t)v) + ((1u << s) - 1u)) >> s);
}

/* floor(v / 2^s), s < 32. GCC and Clang define >> of a negative number as the
 * arithmetic shift, which is this floor in one instruction where the portable
 * form branches (it runs about ten times a water pixel); another compiler takes
 * the portable form, the same number. */
static inline int32_t tarn_floor_shift(int32_t v, unsigned s)
{
#if defined(__GNUC__)
    return v >> s;
#else
    return tarn_floor_shift_portable(v, s);
#endif
}

/* The low 32 bits of tarn_round_shift_i64(v, shift) (ties up), for v's 64-bit
 * two's complement `bits` and shift < 64: for results wanted modulo 2^32 (a
 * triangle's plane steps), in 32-bit words, where the whole 64-bit shift cost the
 * Cortex-M0 a call and about 35 instructions. Below 32 the low word of the floor is
 * the same for either sign; above it, the high word's floor. */
static inline uint32_t tarn_round_shift_low32(uint64_t bits, unsigned shift)
{
    const uint32_t low = (uint32_t)bits, high = (uint32_t)(bits >> 32);
    if (shift == 0u) return low;
    if (shift < 32u) return ((low >> shift) | (high << (32u - shift))) + ((low >> (shift - 1u)) & 1u);
    const uint32_t half = shift == 32u ? low >> 31 : (high >> (shift - 33u)) & 1u;
    return (uint32_t)tarn_floor_shift((int32_t)high, shift - 32u) + half;
}

static inline int tarn_is_power_of_two(uint32_t v)
{
    return v != 0u && (v & (v - 1u)) == 0u;
}

/* Leading zero bits of each byte value, 8 for 0 (core/math/math_tables.c). */
extern const uint8_t tarn_clz8[256];

/* Number of leading zero bits of a 32-bit value (32 for 0), for a core without a
 * CLZ instruction (the Cortex-M0, RISC-V without Zbb): two tests find the highest
 * non-zero byte and a table counts its zeros. It runs about a dozen times a pixel
 * (reciprocals, depth encoding, normalisation), where a five-step binary search
 * cost the M0 twice the instructions. */
static inline unsigned tarn_clz32_by_table(uint32_t v)
{
    if (v >> 16) return v >> 24 ? tarn_clz8[v >> 24] : 8u + tarn_clz8[v >> 16];
    return v >> 8 ? 16u + tarn_clz8[v >> 8] : 24u + tarn_clz8[v];
}

/* 1 where the compiler counts leading zeros in an instruction or two: the
 * Cortex-M3/M4 (CLZ), RISC-V with Zbb, a PC. */
#if defined(__GNUC__) && (defined(__ARM_FEATURE_CLZ) || defined(__riscv_zbb) || defined(__x86_64__) || \
                          defined(__i386__) || defined(__aarch64__))
#define TARN_NATIVE_CLZ 1
#else
#define TARN_NATIVE_CLZ 0
#endif

/* Number of leading zero bits of a 32-bit value (32 for 0): the same number on
 * every target, through the instruction where the core has one. */
#if TARN_NATIVE_CLZ
static inline unsigned tarn_clz32(uint32_t v)
{
    return v == 0u ? 32u : (unsigned)__builtin_clz(v);
}
#else
#define tarn_clz32 tarn_clz32_by_table
#endif

/* 1 where the core multiplies 32x32 to a 64-bit product's high word in an
 * instruction (RISC-V with M: mulhu; the Cortex-M3/M4: umull; a PC), 0 on the
 * Cortex-M0 and RISC-V without M, whose products are 32-bit only. */
#if defined(__ARM_ARCH_6M__) || (defined(__riscv) && !defined(__riscv_mul))
#define TARN_NATIVE_MUL_HI 0
#else
#define TARN_NATIVE_MUL_HI 1
#endif

/* High 32 bits of an unsigned 32x32 product from four 16x16 partial products,
 * summed in 32-bit words: for a core without a high-word multiply (the Cortex-M0,
 * a RISC-V core without M), about 20 instructions where libgcc's 64x64 multiply
 * costs twice that. Exactly (a*b) >> 32. */
static inline uint32_t tarn_mul_hi_u32_by_halves(uint32_t a, uint32_t b)
{
    const uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    const uint32_t cross = ah * bl;
    /* al*bh plus the low product's high half stays below 2^32; adding the other
     * cross product may carry, which is worth 2^16 in the result */
    const uint32_t middle = al * bh + ((al * bl) >> 16) + cross;
    return ah * bh + ((uint32_t)(middle < cross) << 16) + (middle >> 16);
}

/* The same for a and b below 2^31 + 2^16 (their high halves at most 2^15): each
 * cross product is then below 2^31 and their sum with the low product's high half
 * below 2^32, so no carry is counted (five instructions fewer on the Cortex-M0). */
static inline uint32_t tarn_mul_hi_u32_small_by_halves(uint32_t a, uint32_t b)
{
    const uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    return ah * bh + ((al * bh + ah * bl + ((al * bl) >> 16)) >> 16);
}

/* Exactly (a*b) >> 32 for a and b below 2^31 + 2^16: the native product, or the
 * halves without a carry. */
static inline uint32_t tarn_mul_hi_u32_small(uint32_t a, uint32_t b)
{
#if TARN_NATIVE_MUL_HI
    return (uint32_t)(((uint64_t)a * b) >> 32);
#else
    return tarn_mul_hi_u32_small_by_halves(a, b);
#endif
}

/* High 32 bits of an unsigned 32x32 product: exactly (a*b) >> 32. A core with a
 * high-word multiply (RISC-V's mulhu, the Cortex-M3/M4's umull, every PC) takes
 * the native product, one instruction; the others the partial products. */
static inline uint32_t tarn_mul_hi_u32(uint32_t a, uint32_t b)
{
#if TARN_NATIVE_MUL_HI
    return (uint32_t)(((uint64_t)a * b) >> 32);
#else
    return tarn_mul_hi_u32_by_halves(a, b);
#endif
}

/* The whole 64-bit product of two unsigned 32-bit values. The Cortex-M0 has no
 * 32x32->64 multiply, and the compiler's general 64x64 routine costs about twice
 * these four 16x16 products, summed in 32-bit words with their carries; elsewhere
 * the native product is the same number. */
static inline uint64_t tarn_mul_u32_wide(uint32_t a, uint32_t b)
{
#if defined(__ARM_ARCH_6M__)
    const uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    const uint32_t low = al * bl, cross = al * bh, middle = cross + ah * bl; /* may carry out */
    const uint32_t result_low = low + (middle << 16);
    const uint32_t high = ah * bh + ((uint32_t)(middle < cross) << 16) + (middle >> 16) + (result_low < low);
    return ((uint64_t)high << 32) | result_low;
#else
    return (uint64_t)a * b;
#endif
}

/* The whole 64-bit product of two signed 32-bit values, for the per-vertex and
 * per-triangle code whose operands fit 32 bits: on the Cortex-M0 a function of its
 * own (core/math/fixed.c) from tarn_mul_u32_wide, about half of libgcc's 64x64 multiply
 * and small enough to call from everywhere; elsewhere the native product. */
#if defined(__ARM_ARCH_6M__)
int64_t tarn_mul_i32_wide(int32_t a, int32_t b);
#else
static inline int64_t tarn_mul_i32_wide(int32_t a, int32_t b)
{
    return (int64_t)a * b;
}
#endif

/* The 64-bit product of a and b for |a| <= 2^15, such as a coordinate difference
 * inside the guard box. On the Cortex-M0 two 32-bit products of a with b's 16-bit
 * halves, each of which fits 32 bits, where tarn_mul_i32_wide needs four and a
 * call; elsewhere the native product. */
static inline int64_t tarn_mul_i16_i32_wide(int32_t a, int32_t b)
{
#if defined(__ARM_ARCH_6M__)
    const int32_t low = (int32_t)((uint32_t)b & 0xFFFFu);
    const int32_t high = (b - low) / 65536; /* exact: b - low is a multiple of 2^16 */
    return (int64_t)(a * high) * 65536 + a * low;
#else
    return (int64_t)a * b;
#endif
}

/* a1 * b1 + a2 * b2 for factors within +-2^30 (the sum below 2^61), from the
 * factors' 16-bit halves, whose cross products then sum within 32 bits: eight
 * 32-bit products and the words' adds, about half of what two tarn_mul_i32_wide
 * calls cost the Cortex-M0. */
static inline int64_t tarn_dot2_i30_wide_by_halves(int32_t a1, int32_t b1, int32_t a2, int32_t b2)
{
    const int32_t al1 = (int32_t)((uint32_t)a1 & 0xFFFFu), ah1 = tarn_floor_shift(a1, 16);
    const int32_t bl1 = (int32_t)((uint32_t)b1 & 0xFFFFu), bh1 = tarn_floor_shift(b1, 16);
    const int32_t al2 = (int32_t)((uint32_t)a2 & 0xFFFFu), ah2 = tarn_floor_shift(a2, 16);
    const int32_t bl2 = (int32_t)((uint32_t)b2 & 0xFFFFu), bh2 = tarn_floor_shift(b2, 16);
    const int32_t high = ah1 * bh1 + ah2 * bh2; /* high halves within +-2^14: below 2^29 */
    const int32_t middle1 = ah1 * bl1 + al1 * bh1, middle2 = ah2 * bl2 + al2 * bh2; /* below 2^31 */
    const uint64_t low = (uint64_t)((uint32_t)al1 * (uint32_t)bl1) + (uint32_t)al2 * (uint32_t)bl2;
    return (int64_t)high * 4294967296 + ((int64_t)middle1 + middle2) * 65536 + (int64_t)low;
}

/* a1 * b1 + a2 * b2 for factors within +-2^30, such as a plane's weighted sums: the
 * halves on the Cortex-M0, the native products elsewhere. */
static inline int64_t tarn_dot2_i30_wide(int32_t a1, int32_t b1, int32_t a2, int32_t b2)
{
#if defined(__ARM_ARCH_6M__)
    return tarn_dot2_i30_wide_by_halves(a1, b1, a2, b2);
#else
    return (int64_t)a1 * b1 + (int64_t)a2 * b2;
#endif
}

/* Signed x unsigned high product: floor((a * b) / 2^32) for a signed a. */
static inline int32_t tarn_mul_hi_s32_u32(int32_t a, uint32_t b)
{
    if (a >= 0) return (int32_t)tarn_mul_hi_u32((uint32_t)a, b);
    /* -(|a|*b) >> 32 with floor semantics: -ceil(|a|*b / 2^32) */
    uint32_t mag = (uint32_t)0 - (uint32_t)a;
    uint32_t hi = tarn_mul_hi_u32(mag, b);
    uint32_t lo = mag * b;
    return (int32_t)-(int64_t)(hi + (lo != 0u)); /* fits: |result| <= 2^31 */
}

#ifdef __cplusplus
}
#endif

#endif
