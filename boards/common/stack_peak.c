/* stack_peak.c: board_stack_peak for the emulated boards, whose startup paints the
 * stack with STACK_PAINT (stack_paint.h) between the linker script's __stack_limit
 * and __stack_top (cortex_m_sections.ld, qemu-rv32/link.ld). The stack grows down
 * from __stack_top, so the lowest word no longer painted is the deepest one used. */
#include "board.h"
#include "stack_paint.h"

extern uint32_t __stack_limit[], __stack_top[];

size_t board_stack_peak(void)
{
    const uint32_t *p = __stack_limit;
    while (p < __stack_top && *p == STACK_PAINT) p++;
    return (size_t)((const uint8_t *)__stack_top - (const uint8_t *)p);
}
