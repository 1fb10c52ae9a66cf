/* qemu_microbit.c: the instruction counter on QEMU's microbit, an nRF51 (Cortex-M0)
 * whose SysTick runs on the 16 MHz processor clock. Under -icount shift=0 one
 * instruction takes 1 ns of virtual time, so one tick is 62.5 instructions: the count
 * has a resolution of 62.5 instructions (tests/check_firmware.sh checks the ratio
 * with a loop of known length). Boards on this machine: qemu-m0 and the two built
 * on it. */
#include "board.h"
#include "cortex_m.h"

uint64_t board_instructions(void)
{
    return systick_ticks() * 125u / 2u;
}
