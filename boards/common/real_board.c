/* real_board.c: board.h's real-board side, the same on every real Cortex-M board:
 * board_init brings the clocks up, starts the millisecond tick and sets up the
 * panel's link; board_milliseconds reads the tick (unless the board's clock.h sets
 * CLOCK_OWN_MILLISECONDS and its clock.c gives its own); board_exit (an exit or a fault)
 * resets the chip, since there is nobody to report to.
 *
 * What differs from board to board comes from the board's own folder (on the
 * include path through BOARD_INCLUDE): clock.h gives CLOCK_PROCESSOR_HZ, the clock
 * SysTick counts once clock_init() has run, and declares clock_init(); panel_spi.c
 * implements panel_spi_init() and the rest of firmware/panel_spi.h. */
#include "board.h"
#include "clock.h"
#include "cortex_m.h"
#include "panel_spi.h"

/* SysTick counts the processor clock (systick_start), CLOCK_PROCESSOR_HZ ticks a
 * second: 125,000 a millisecond at 125 MHz, 100,000 at 100 MHz. */
#define TICKS_PER_MS (CLOCK_PROCESSOR_HZ / 1000u)

/* The Application Interrupt and Reset Control Register, at the same address on
 * ARMv6-M and ARMv7-M (both Architecture Reference Manuals, B3.2): a write takes
 * effect only with 0x05FA in VECTKEY (bits 31:16), and SYSRESETREQ (bit 2) asks the
 * chip for a system reset, not only of the core. */
#define SCB_AIRCR (*(volatile uint32_t *)0xE000ED0Cu)
#define SCB_AIRCR_SYSRESETREQ (0x05FAu << 16 | 1u << 2)

int board_init(void)
{
    if (clock_init() != 0) return 1;
    systick_start();
    panel_spi_init();
    return 0;
}

#ifndef CLOCK_OWN_MILLISECONDS /* a board whose clock.c gives its own (clock.h says) */
uint32_t board_milliseconds(void)
{
    return (uint32_t)(systick_ticks() / TICKS_PER_MS);
}
#endif

/* The DSB before the request lets the writes in flight finish; the one after it
 * completes the request's own write before the loop that waits for the reset (the
 * order CMSIS's NVIC_SystemReset keeps). */
void board_exit(int status)
{
    (void)status;
    __asm__ volatile("dsb" ::: "memory");
    SCB_AIRCR = SCB_AIRCR_SYSRESETREQ;
    __asm__ volatile("dsb" ::: "memory");
    for (;;) {}
}
