/* trig.c: sine and cosine of an angle in turns, from a quarter-wave table.
 *
 * The angle's top two bits pick the quadrant; the other 14 bits index the 257-entry
 * table of the first quarter (64 angle units per step) with linear interpolation.
 * Odd quadrants walk the table backwards and the lower half of the turn negates, so
 * the result is exactly symmetric: sin(a) = sin(1/2 - a) = -sin(a + 1/2). */
#include "tarn_math.h"
#include "math_tables.h"

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
    uint32_t blended = tarn_sin_quarter_q15[from] * ((1u << STEP_BITS) - weight) +
                       tarn_sin_quarter_q15[to] * weight;
    uint32_t magnitude = (blended + (1u << (STEP_BITS - 1u))) >> STEP_BITS;
    if (magnitude > Q15_MAX) magnitude = Q15_MAX; /* 1.0 itself is not a Q1.15 value */
    return quadrant >= 2u ? -(int32_t)magnitude : (int32_t)magnitude;
}

int32_t tarn_cos_q15(uint16_t angle_turns_q16)
{
    /* cos(a) = sin(a + 1/4 turn); the uint16_t conversion wraps the turn */
    return tarn_sin_q15((uint16_t)(angle_turns_q16 + (1u << QUADRANT_BITS)));
}
