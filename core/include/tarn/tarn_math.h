/* tarn_math.h: integer elementary functions with documented error bounds.
 *
 * None of these divide or use a 64-bit multiply, so each is usable per pixel on a
 * Cortex-M0. Every bound below is asserted by tests/test_math.c, which sweeps the
 * input range against libm on the host; `tarn accuracy --math` prints the measured
 * errors and costs (mean errors too), scripts/bench-math.sh instructions per call.
 * Errors are in LSBs: units of the last place of the result's format. */
#ifndef TARN_MATH_H
#define TARN_MATH_H

#include <stdint.h>
#include "tarn_fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- exp2 of a non-positive argument -------------------------------------------
 * Used by fog and absorption: f = exp2(-density * diff). The fraction part of the
 * argument indexes a table of 2^-f; the whole part shifts. The table size (8..256
 * entries, a power of two) and linear interpolation are runtime knobs: a smaller
 * table is a stride through the one 257-entry table in flash, so it costs no RAM.
 * A size below 8 or above 256 acts as 8 or 256; a size in between that is not a
 * power of two acts as the power of two below it (100 acts as 64). Any non-zero
 * `interpolate` means linear.
 *
 * Largest error over every x in [-18, 0] (Q0.16 LSBs; 2^x itself is 65536 at x = 0):
 *   entries       8      16      32     64    128    256
 *   nearest    5439    2778    1404    706    354    177
 *   linear       60    15.4     4.5    1.7    1.2    1.0
 * Nearest-below reads the entry at or before x's fraction, so it leans high (fog
 * comes out thinner) by up to one table step. More entries never make either mode
 * worse. */
#define TARN_EXP2_ENTRIES_MIN 8u
#define TARN_EXP2_ENTRIES_MAX 256u

typedef struct {
    uint16_t entries;    /* 8, 16, 32, 64, 128 or 256 */
    uint8_t interpolate; /* 0: nearest entry below, non-zero: linear between entries */
} tarn_exp2_config;

/* 2^x for x <= 0 in Q16.16; result in Q0.16 held in 32 bits: 65536 at x = 0,
 * falling to 0 as x goes to minus infinity. Positive x is clamped to 0 (result 65536).
 * Rounded to nearest once, after interpolating: 1 at x = -17 (half an LSB rounds
 * up), 0 for every x < -17 in linear mode and every x <= -18 in both modes. */
uint32_t tarn_exp2_neg_q16(tarn_q16 x, tarn_exp2_config config);

/* ---- reciprocal -------------------------------------------------------------------
 * 2^32 / x without a divider: a 256-entry table seeds the mantissa, then Newton
 * steps refine it. Steps are a knob; more than TARN_RECIP_STEPS_MAX act as
 * TARN_RECIP_STEPS_MAX. Largest relative error, beyond the final rounding to an
 * integer (|result - exact| <= 1/2 + eps * exact), over all 2^32 inputs:
 *   0 steps (table only)   eps = 1.96e-3 (2^-9: 9 good bits)
 *   1 step                 eps = 3.82e-6 (2^-18)
 *   2 steps                eps = 9.4e-10 (2^-30); tarn_recip_u32 is within 1 LSB
 * Newton steps approach from below, so errors lean low. */
#define TARN_RECIP_STEPS_MAX 2u

/* 2^32 / x rounded to nearest; x = 0 or 1 saturate to UINT32_MAX. */
uint32_t tarn_recip_u32(uint32_t x, unsigned newton_steps);

/* The same reciprocal before scaling, for callers that track the exponent: for a
 * mantissa m with its top bit set (m / 2^32 in [1/2, 1)), returns 2^62 / m, that is
 * 1/(m / 2^32) in Q2.30, exact value in (2^30, 2^31]. Keeps all 30 bits where
 * tarn_recip_u32 would round a large x's result to few bits. Same relative errors
 * as above, so the result may fall just outside that range: it lies in
 * [2^30 - 1022, 2^31 - 1] (2 steps: within 2 LSBs of exact). m without its top bit
 * set is shifted up until it has it; m = 0 saturates to UINT32_MAX. */
uint32_t tarn_recip_q30(uint32_t mantissa, unsigned newton_steps);

/* ---- exact division by a 32-bit divisor ------------------------------------------
 * For per-triangle and per-vertex work on CPUs without a divide instruction (the
 * Cortex-M0), where the compiler's 64-bit division costs several hundred
 * instructions. Prepare a divisor once, then divide any number of numerators by
 * it: the quotient is estimated from the divisor's reciprocal (tarn_recip_q30, two
 * Newton steps, lowered so that it never overshoots), and each round divides what
 * is left, 28 bits at a time, until the remainder is below the divisor. The result
 * is exact: the same quotient and remainder as the / and % operators. |n| < 2^63
 * for the signed forms. Linking these instead of the compiler's 64-bit division
 * also keeps that (about 1.2 KB on the Cortex-M0) out of the firmware. */
typedef struct {
    uint32_t divisor;
    uint32_t recip;  /* at most 2^62 / (divisor << shift) */
    unsigned shift;  /* leading zeros of divisor */
} tarn_divisor;

/* divisor > 0 (0 acts as 1). */
tarn_divisor tarn_divisor_of(uint32_t divisor);
/* floor(n / divisor), and n mod divisor into *remainder when it is not NULL. */
uint64_t tarn_divide_u64(uint64_t n, const tarn_divisor *d, uint32_t *remainder);
/* floor(n / divisor) for a signed n, with the remainder in [0, divisor) into
 * *remainder when it is not NULL. */
int64_t tarn_divide_floor_i64(int64_t n, const tarn_divisor *d, uint32_t *remainder);
/* n / divisor truncated toward zero, as C's / operator. */
int64_t tarn_divide_trunc_i64(int64_t n, const tarn_divisor *d);
/* The same for a divisor used once: prepares it, then divides. */
int64_t tarn_divide_once_i64(int64_t n, uint32_t divisor);

/* ---- sine and cosine --------------------------------------------------------------
 * Angle in turns as Q0.16 wrapped (65536 = one full turn, so any uint16_t is valid);
 * result Q1.15 in [-32767, 32767]. Quarter-wave table (257 entries) with linear
 * interpolation. Within 1.001 LSB of 32768 * sin, clamped to +-32767, at every
 * angle; exact at multiples of a quarter turn; exactly symmetric:
 * sin(a) = sin(1/2 - a) = -sin(a + 1/2), cos(a) = sin(a + 1/4). */
int32_t tarn_sin_q15(uint16_t angle_turns_q16);
int32_t tarn_cos_q15(uint16_t angle_turns_q16);

/* Sine and cosine of an angle in radians, Q2.30, clamped to [-pi/2, pi/2]; results
 * Q2.30 within a few units of 2^-30 (tests/test_math.c asserts 4). A Taylor series
 * with 64-bit products and constant divisions: for per-frame work such as the focal
 * length, where the table's 2^-15 would shift the frame edge by a hundredth of a pixel. */
void tarn_sin_cos_q30(int32_t radians_q30, int32_t *sine_q30, int32_t *cosine_q30);
/* The same for any angle in turns, Q0.32 wrapped (2^32 = one turn): the series at
 * the nearest quarter turn's remainder, so within the same few units of 2^-30. For
 * motion (tarn_motion.h), a few calls a frame. */
void tarn_sin_cos_turns_q30(uint32_t turns_q32, int32_t *sine_q30, int32_t *cosine_q30);

/* ---- square roots -----------------------------------------------------------------*/
/* floor(sqrt(x)), exact for every 32-bit input. */
uint32_t tarn_isqrt_u32(uint32_t x);
/* The same for 64-bit inputs; 64-bit shifts and adds only, for per-frame work such
 * as normalising the camera basis. */
uint64_t tarn_isqrt_u64(uint64_t x);

/* 1/sqrt(x) for x in Q16.16, result Q16.16 rounded to nearest, 0 at x = 0 ("no
 * direction"). Used to normalise vectors. Results run from 2^24 (256.0, at the
 * smallest x, 2^-16) down to 256 (1/256), so nothing needs to saturate. A table
 * seeds it and two Newton steps refine it: within 0.501 LSB at every input;
 * relative error beyond the rounding at most 2.5e-9. */
uint32_t tarn_rsqrt_q16(uint32_t x_q16);
/* The same after one Newton step: relative error beyond the rounding below 2^-15.
 * A per-pixel normal, whose direction holds 15 bits, loses nothing to it, and the
 * Cortex-M0 saves the second step's three high products (about 55 instructions) and
 * their code. */
uint32_t tarn_rsqrt15_q16(uint32_t x_q16);
/* v / |v| in Q1.30, for a vector of 64-bit integers of any common scale (each below
 * 2^62 in magnitude): to about 2^-16 of each component. Returns 0 for the zero
 * vector, leaving out unchanged. Once a frame: the camera's axes, a moving light. */
int tarn_normalise_q30(const int64_t v[3], int32_t out[3]);

#ifdef __cplusplus
}
#endif

#endif
