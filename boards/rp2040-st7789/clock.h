/* clock.h: the RP2040's clocks for this board. Its millisecond clock is the chip's
 * TIMER, which both cores read alike, not SysTick (boards/common/real_board.c's),
 * which each core has its own of and only core 0 starts. */
#ifndef TARN_RP2040_CLOCK_H
#define TARN_RP2040_CLOCK_H

#define CLOCK_PROCESSOR_HZ 125000000u /* clk_sys: the cores and SysTick */
#define CLOCK_PERI_HZ 125000000u      /* clk_peri: SPI0 */
#define CLOCK_REF_HZ 12000000u        /* clk_ref: the crystal, the TIMER's tick source */
#define CLOCK_OWN_MILLISECONDS 1      /* clock.c gives board_milliseconds */

/* Brings the blocks this board uses out of reset and sets XOSC (12 MHz) -> PLL_SYS
 * -> clk_sys at 125 MHz, clk_ref on XOSC, clk_peri from clk_sys, and the TIMER's
 * microsecond tick from clk_ref. Returns 0, or
 * non-zero when the crystal, the PLL or a clock switch did not become ready in time. */
int clock_init(void);

#endif
