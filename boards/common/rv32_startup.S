/* rv32_startup.S: reset for the emulated RISC-V boards (qemu-rv32, qemu-rv32-400k).
 * Stack pointer and global pointer, a trap vector that ends the run, the stack
 * painted for the high-water mark, .data copied, .bss zeroed, then main() and
 * board_exit() with its result. rv32_sections.ld provides the symbols. */
#include "stack_paint.h"

    .section .text.start, "ax"
    .globl _start
_start:
    .option push
    .option norelax
    la gp, __global_pointer$
    .option pop
    la sp, __stack_top
    la t0, trap_entry
    csrw mtvec, t0

    la t0, __stack_limit
    la t1, __stack_top
    li t2, STACK_PAINT
1:  bgeu t0, t1, 2f
    sw t2, 0(t0)
    addi t0, t0, 4
    j 1b
2:
    la t0, __data_load
    la t1, __data_start
    la t2, __data_end
3:  bgeu t1, t2, 4f
    lw t3, 0(t0)
    sw t3, 0(t1)
    addi t0, t0, 4
    addi t1, t1, 4
    j 3b
4:
    la t0, __bss_start
    la t1, __bss_end
5:  bgeu t0, t1, 6f
    sw zero, 0(t0)
    addi t0, t0, 4
    j 5b
6:
    call main
    call board_exit
7:  j 7b

    .align 4
trap_entry:
    la sp, __stack_top
    li a0, 3
    call board_exit
8:  j 8b
