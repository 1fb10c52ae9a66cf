/* stm32f411-st7789: an STM32F411 (Cortex-M4, 100 MHz) driving an ST7789 240x240
 * panel on SPI1 with DMA2. board.h's real-board side: clocks, the millisecond tick,
 * the panel's link, and a reset for an exit or a fault. README.md gives the wiring. */
#include "board.h"
#include "clock.h"
#include "cortex_m.h"
#include "stm32f411.h"

void panel_spi_init(void);

#define TICKS_PER_MS (CLOCK_HCLK_HZ / 1000u)

int board_init(void)
{
    if (clock_init() != 0) return 1;
    systick_start(); /* on the 100 MHz core clock */
    panel_spi_init();
    return 0;
}

uint32_t board_milliseconds(void)
{
    return (uint32_t)(systick_ticks() / TICKS_PER_MS);
}

/* There is nobody to report to: start again from reset (SCB AIRCR SYSRESETREQ). */
void board_exit(int status)
{
    (void)status;
    __asm__ volatile("dsb" ::: "memory");
    SCB_AIRCR = SCB_AIRCR_SYSRESETREQ;
    __asm__ volatile("dsb" ::: "memory");
    for (;;) {}
}
