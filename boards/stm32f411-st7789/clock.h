/* clock.h: the STM32F411's clocks for this board (boards/common/real_board.c reads
 * CLOCK_PROCESSOR_HZ for its millisecond tick). */
#ifndef TARN_STM32F411_CLOCK_H
#define TARN_STM32F411_CLOCK_H

#include <stdint.h>

/* SYSCLK and HCLK after clock_init(): the core and SysTick run at this. */
#define CLOCK_PROCESSOR_HZ 100000000u
/* APB2, the clock of SPI1 */
#define CLOCK_PCLK2_HZ 100000000u

/* HSI (16 MHz) through the main PLL to 100 MHz, APB1 at 50 MHz (its maximum), APB2
 * at 100 MHz. Returns 0, or non-zero when the regulator, the PLL or the switch did
 * not become ready in time (the clock is then still the HSI). */
int clock_init(void);

#endif
