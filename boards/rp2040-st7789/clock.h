/* clock.h: the RP2040's clocks for this board (boards/common/real_board.c reads
 * CLOCK_PROCESSOR_HZ for its millisecond tick). */
#ifndef TARN_RP2040_CLOCK_H
#define TARN_RP2040_CLOCK_H

#define CLOCK_PROCESSOR_HZ 125000000u /* clk_sys: the cores and SysTick */
#define CLOCK_PERI_HZ 125000000u      /* clk_peri: SPI0 */

/* Brings the blocks this board uses out of reset and sets XOSC (12 MHz) -> PLL_SYS
 * -> clk_sys at 125 MHz, clk_ref on XOSC, clk_peri from clk_sys. Returns 0, or
 * non-zero when the crystal, the PLL or a clock switch did not become ready in time. */
int clock_init(void);

#endif
