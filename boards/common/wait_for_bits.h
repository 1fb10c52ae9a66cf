/* wait_for_bits.h: the real boards' bounded wait on a register, for the clock set-up.
 * Every wait on the hardware ends: a crystal, a regulator, a PLL or a clock switch
 * that never reports ready makes clock_init fail, and the board reset, rather than
 * hang. */
#ifndef TARN_WAIT_FOR_BITS_H
#define TARN_WAIT_FOR_BITS_H

#include <stdint.h>

/* Reads before giving up: far more than any of these takes (microseconds; about
 * 1 ms for the RP2040's crystal), and still an end. A read is a loop of five or six
 * instructions, so a million of them end within a second or two at the
 * 6 to 16 MHz the chips start on, which is what clock_init runs on. */
#define WAIT_FOR_BITS_POLLS 1000000u

/* Reads `reg` until its bits under `mask` equal `value`, at most WAIT_FOR_BITS_POLLS
 * times. Returns 0 when they did, 1 when the reads ran out. */
static inline int wait_for_bits(volatile uint32_t *reg, uint32_t mask, uint32_t value)
{
    for (uint32_t i = 0; i < WAIT_FOR_BITS_POLLS; i++)
        if ((*reg & mask) == value) return 0;
    return 1;
}

#endif
