/* qemu-m3: QEMU's mps2-an385, a Cortex-M3 whose SysTick runs on the 25 MHz system
 * clock. Under -icount shift=0 one instruction takes 1 ns of virtual time, so one
 * tick is exactly 40 instructions (tests/check_firmware.sh checks the ratio with a
 * loop of known length). */
#include "board.h"
#include "cortex_m.h"

uint64_t board_instructions(void)
{
    return systick_ticks() * 40u;
}
