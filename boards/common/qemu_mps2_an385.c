/* qemu_mps2_an385.c: the instruction counter on QEMU's mps2-an385, whose SysTick
 * runs on the 25 MHz system clock. Under -icount shift=0 one instruction takes 1 ns
 * of virtual time, so one tick is exactly 40 instructions (tests/check_firmware.sh
 * checks the ratio with a loop of known length). The machine's CPU is a Cortex-M3;
 * qemu-m3 runs Cortex-M3 code on it, qemu-m0-264k Cortex-M0 code (ARMv6-M is a
 * subset of ARMv7-M), and the counter is the same for both. */
#include "board.h"
#include "cortex_m.h"

uint64_t board_instructions(void)
{
    return systick_ticks() * 40u;
}
