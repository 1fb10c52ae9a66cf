/* trig.c: sine and cosine of an angle in turns, from a quarter-wave table.
 *
 * The angle's top two bits pick the quadrant; the other 14 bits index the 257-entry
 * table of the first quarter (64 angle units per step) with linear interpolation.
 * Odd quadrants walk the table backwards and the lower half of the turn negates, so
 * the result is exactly symmetric: sin(a) = sin(1/2 - a) = -sin(a + 1/2). */
#include "tarn/tarn_math.h"
#include "math/math_tables_internal.h"

#define QUADRANT_BITS 14u /* angle units per quadrant: 2^14 = 65536 / 4 */
#define STEP_BITS 6u      /* angle units per table step: 2^14 / 256 */
#define Q15_MAX 32767u

int32_t tarn_sin_q15(uint16_t angle_turns_q16)
{
    uint32_t quadrant = (uint32_t)angle_turns_q16 >> QUADRANT_BITS;
    uint32_t in_quadrant = angle_turns_q16 & ((1u << QUADRANT_BITS) - 1u);
    uint32_t step = in_quadrant >> STEP_BITS;
    uint32_t weight = in_quadrant & ((1u << STEP_BITS) - 1u);
    int backwards = (quadrant & 1u) != 0u;
    uint32_t from = backwards ? TARN_SIN_TABLE_STEPS - step : step;
    uint32_t to = backwards ? from - 1u : from + 1u;

    /* Q1.21: a weighted mean of two entries, so never negative and at most 2^21 */
    uint32_t blended = tarn__sin_quarter_q15[from] * ((1u << STEP_BITS) - weight) +
                       tarn__sin_quarter_q15[to] * weight;
    uint32_t magnitude = (blended + (1u << (STEP_BITS - 1u))) >> STEP_BITS;
    if (magnitude > Q15_MAX) magnitude = Q15_MAX; /* 1.0 itself is not a Q1.15 value */
    return quadrant >= 2u ? -(int32_t)magnitude : (int32_t)magnitude;
}

int32_t tarn_cos_q15(uint16_t angle_turns_q16)
{
    /* cos(a) = sin(a + 1/4 turn); the uint16_t conversion wraps the turn */
    return tarn_sin_q15((uint16_t)(angle_turns_q16 + (1u << QUADRANT_BITS)));
}

/* Horner form of the Taylor series: term k multiplies by -x^2 / ((2k)(2k+1)) for
 * sine, -x^2 / ((2k-1)(2k)) for cosine. Eight terms reach x^17/17!, below 2^-34
 * at pi/2; 64-bit products and constant divisions (tarn_divide, which the
 * Cortex-M0 build links anyway), once a frame at most. */
#define SERIES_TERMS 8

void tarn_sin_cos_q30(int32_t radians_q30, int32_t *sine_q30, int32_t *cosine_q30)
{
    const int64_t half_pi_q30 = 1686629713; /* pi/2 * 2^30, rounded */
    int64_t x = radians_q30 < -half_pi_q30 ? -half_pi_q30 : (radians_q30 > half_pi_q30 ? half_pi_q30 : radians_q30);
    const int64_t x2 = tarn_round_shift_i64(x * x, 30);
    int64_t sine = (int64_t)1 << 30, cosine = (int64_t)1 << 30;
    for (int64_t k = SERIES_TERMS; k >= 1; k--) {
        sine = ((int64_t)1 << 30) - tarn_divide_once_i64(tarn_round_shift_i64(x2 * sine, 30), (uint32_t)((2 * k) * (2 * k + 1)));
        cosine = ((int64_t)1 << 30) - tarn_divide_once_i64(tarn_round_shift_i64(x2 * cosine, 30), (uint32_t)((2 * k - 1) * (2 * k)));
    }
    *sine_q30 = (int32_t)tarn_round_shift_i64(x * sine, 30);
    *cosine_q30 = (int32_t)tarn_clamp_i32((int32_t)cosine, 0, 1 << 30);
}

void tarn_sin_cos_turns_q30(uint32_t turns_q32, int32_t *sine_q30, int32_t *cosine_q30)
{
    const int64_t half_pi_q32 = 6746518852; /* pi/2 * 2^32, rounded */
    /* the nearest quarter turn, and the rest within an eighth of a turn of it */
    const uint32_t shifted = turns_q32 + (1u << 29);
    const uint32_t quarter = shifted >> 30;
    const int32_t rest_q32 = (int32_t)(shifted & 0x3FFFFFFFu) - (1 << 29);
    int32_t s, c;
    tarn_sin_cos_q30((int32_t)tarn_round_shift_i64((int64_t)rest_q32 * half_pi_q32, 32), &s, &c);
    /* sin and cos of rest + quarter * pi/2 */
    const int32_t sines[4] = {s, c, -s, -c};
    *sine_q30 = sines[quarter];
    *cosine_q30 = sines[(quarter + 1u) & 3u];
}
