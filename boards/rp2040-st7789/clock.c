/* clock.c: the RP2040's clocks, from the datasheet:
 *
 * - Resets (§2.14): every block this board uses (PLL_SYS, IO_BANK0, PADS_BANK0,
 *   SPI0, DMA, TIMER) is taken out of reset here, and used only once RESET_DONE says so.
 * - XOSC (§2.16): FREQ_RANGE 1_15MHZ for the 12 MHz crystal; STARTUP.DELAY counts
 *   256-cycle units, and 47 of them (about 1 ms) is the crystal's settling time
 *   (§2.16.3); then ENABLE, and STABLE before anything uses it.
 * - clk_sys leaves the PLL (its glitchless SRC to clk_ref) while the PLL is set up,
 *   clk_ref goes to the XOSC (§2.15.3.2).
 * - PLL_SYS (§2.18.2): REFDIV 1, FBDIV 125: VCO 12 MHz * 125 = 1500 MHz; POSTDIV1 6,
 *   POSTDIV2 2: 1500 / 12 = 125 MHz. Power the PLL and VCO up, wait for LOCK, set the
 *   post dividers, then power them up (the order of §2.18.2.1).
 * - clk_sys: AUXSRC clksrc_pll_sys, then SRC to the aux source; clk_peri: enabled,
 *   from clk_sys (§2.15.7).
 * - The TIMER (§4.6): its microsecond tick is the watchdog's, clk_ref / 12 (§4.7.2).
 *
 * Every wait is a bounded loop: a clock that does not come up makes board_init fail
 * (the board then resets) rather than hang. */
#include "board.h"
#include "clock.h"
#include "rp2040.h"
#include "wait_for_bits.h"

#define XOSC_STARTUP_DELAY 47u /* ((12 MHz / 1000) + 128) / 256: 1 ms */
#define PLL_REFDIV 1u
#define PLL_FBDIV 125u
#define PLL_POSTDIV1 6u
#define PLL_POSTDIV2 2u
#define USED_BLOCKS (RESETS_PLL_SYS | RESETS_IO_BANK0 | RESETS_PADS_BANK0 | RESETS_SPI0 | RESETS_DMA | RESETS_TIMER)

int clock_init(void)
{
    XOSC_CTRL = XOSC_CTRL_FREQ_RANGE_1_15MHZ;
    XOSC_STARTUP = XOSC_STARTUP_DELAY;
    XOSC_CTRL = XOSC_CTRL_FREQ_RANGE_1_15MHZ | XOSC_CTRL_ENABLE_VALUE << XOSC_CTRL_ENABLE_Pos;
    if (wait_for_bits(&XOSC_STATUS, XOSC_STATUS_STABLE, XOSC_STATUS_STABLE) != 0) return 1;

    CLK_SYS_CTRL &= ~CLK_SYS_CTRL_SRC_AUX; /* clk_sys from clk_ref while the PLL changes */
    if (wait_for_bits(&CLK_SYS_SELECTED, 1u, 1u) != 0) return 1;
    CLK_REF_CTRL = CLK_REF_CTRL_SRC_XOSC;
    if (wait_for_bits(&CLK_REF_SELECTED, 1u << CLK_REF_CTRL_SRC_XOSC,
                      1u << CLK_REF_CTRL_SRC_XOSC) != 0)
        return 1;

    /* a PLL left running by a warm start is reset too, so it starts from its defaults */
    RESETS_RESET_SET = RESETS_PLL_SYS;
    RESETS_RESET_CLR = USED_BLOCKS;
    if (wait_for_bits(&RESETS_RESET_DONE, USED_BLOCKS, USED_BLOCKS) != 0) return 1;

    PLL_CS = PLL_REFDIV;
    PLL_FBDIV_INT = PLL_FBDIV;
    PLL_PWR &= ~(PLL_PWR_PD | PLL_PWR_VCOPD);
    if (wait_for_bits(&PLL_CS, PLL_CS_LOCK, PLL_CS_LOCK) != 0) return 1;
    PLL_PRIM = PLL_POSTDIV1 << PLL_PRIM_POSTDIV1_Pos | PLL_POSTDIV2 << PLL_PRIM_POSTDIV2_Pos;
    PLL_PWR &= ~PLL_PWR_POSTDIVPD;

    CLK_SYS_CTRL &= ~CLK_SYS_CTRL_AUXSRC_Msk; /* 0: clksrc_pll_sys */
    CLK_SYS_CTRL |= CLK_SYS_CTRL_SRC_AUX;
    if (wait_for_bits(&CLK_SYS_SELECTED, 2u, 2u) != 0) return 1;

    CLK_PERI_CTRL = CLK_PERI_CTRL_ENABLE | CLK_PERI_CTRL_AUXSRC_CLK_SYS;
    WATCHDOG_TICK = WATCHDOG_TICK_ENABLE | CLOCK_REF_HZ / 1000000u;
    return 0;
}

/* The TIMER's microseconds in milliseconds: the high word read again until the low
 * one was read within it. */
uint32_t board_milliseconds(void)
{
    uint32_t high, low;
    do {
        high = TIMER_TIMERAWH;
        low = TIMER_TIMERAWL;
    } while (high != TIMER_TIMERAWH);
    return (uint32_t)((((uint64_t)high << 32) | low) / 1000u);
}
