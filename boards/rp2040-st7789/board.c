/* rp2040-st7789: an RP2040 (Cortex-M0+ at 125 MHz; core 1 stays asleep in the
 * bootrom) driving an ST7789 240x240 panel on SPI0 with DMA channel 0. board.h's
 * real-board side: clocks, the millisecond tick, the panel's link, and a reset for
 * an exit or a fault. README.md gives the wiring. */
#include "board.h"
#include "clock.h"
#include "cortex_m.h"
#include "rp2040.h"

void panel_spi_init(void);

#define TICKS_PER_MS (CLOCK_SYS_HZ / 1000u)

int board_init(void)
{
    if (clock_init() != 0) return 1;
    systick_start(); /* SysTick on the processor clock: 125 MHz */
    panel_spi_init();
    return 0;
}

uint32_t board_milliseconds(void)
{
    return (uint32_t)(systick_ticks() / TICKS_PER_MS);
}

/* There is nobody to report to: start again from reset (SCB AIRCR SYSRESETREQ,
 * which on the RP2040 resets the cores and reruns the bootrom and boot2). */
void board_exit(int status)
{
    (void)status;
    __asm__ volatile("dsb" ::: "memory");
    SCB_AIRCR = SCB_AIRCR_SYSRESETREQ;
    __asm__ volatile("dsb" ::: "memory");
    for (;;) {}
}
