/* tarn_math.h: integer elementary functions with documented error bounds.
 *
 * None of these divide or use a 64-bit multiply, so each is usable per pixel on a
 * Cortex-M0. Every bound below is asserted by tests/test_math.c, which sweeps the
 * input range against libm on the host; `tarn accuracy --math` prints the measured
 * errors and costs. */
#ifndef TARN_MATH_H
#define TARN_MATH_H

#include <stdint.h>
#include "tarn_fixed.h"

/* ---- exp2 of a non-positive argument -------------------------------------------
 * Used by fog and absorption: f = exp2(-density * diff). The fraction part of the
 * argument indexes a table of 2^-f; the whole part shifts. The table size (8..256
 * entries, a power of two) and linear interpolation are runtime knobs: a smaller
 * table is a stride through the one 257-entry table in flash, so it costs no RAM. */
#define TARN_EXP2_ENTRIES_MIN 8u
#define TARN_EXP2_ENTRIES_MAX 256u

typedef struct {
    uint16_t entries;    /* 8, 16, 32, 64, 128 or 256 */
    uint8_t interpolate; /* 0: nearest entry below, 1: linear between entries */
} tarn_exp2_config;

/* 2^x for x <= 0 in Q16.16; result in Q0.16 held in 32 bits: 65536 at x = 0,
 * falling to 0 as x goes to minus infinity. Positive x is clamped to 0 (result 65536). */
uint32_t tarn_exp2_neg_q16(tarn_q16 x, tarn_exp2_config config);

/* ---- reciprocal -------------------------------------------------------------------
 * 2^32 / x without a divider: a 256-entry table seeds the mantissa, then Newton
 * steps refine it. Steps are a knob: 0 (table only, about 8 good bits), 1 (about 16),
 * 2 (full precision, error at most 2 units of the result's last place).
 * x = 0 or 1 saturate to UINT32_MAX. */
#define TARN_RECIP_STEPS_MAX 2u
uint32_t tarn_recip_u32(uint32_t x, unsigned newton_steps);

/* The same reciprocal before scaling, for callers that track the exponent: for a
 * mantissa m with its top bit set (m / 2^32 in [1/2, 1)), returns 2^62 / m, that is
 * 1/(m / 2^32) in Q2.30, in (2^30, 2^31]. Keeps all 30 bits where tarn_recip_u32
 * would round a large x's result to few bits. m without its top bit set is
 * normalised first. */
uint32_t tarn_recip_q30(uint32_t mantissa, unsigned newton_steps);

/* ---- sine and cosine --------------------------------------------------------------
 * Angle in turns as Q0.16 wrapped (65536 = one full turn, so any uint16_t is valid);
 * result Q1.15 in [-32767, 32767]. Quarter-wave table with interpolation. */
int32_t tarn_sin_q15(uint16_t angle_turns_q16);
int32_t tarn_cos_q15(uint16_t angle_turns_q16);

/* ---- square roots -----------------------------------------------------------------*/
/* floor(sqrt(x)), exact for every 32-bit input. */
uint32_t tarn_isqrt_u32(uint32_t x);

/* 1/sqrt(x) for x in Q16.16 (x > 0), result Q16.16, saturated to INT32_MAX for tiny x
 * and 0 at x = 0 ("no direction"). Used to normalise vectors. */
uint32_t tarn_rsqrt_q16(uint32_t x_q16);

#endif
