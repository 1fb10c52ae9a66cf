/* board.h: what the board-independent firmware needs from a board.
 *
 * Each folder in boards/ implements these functions for one board (board.c) and
 * provides the startup code that calls main() with .data copied and .bss zeroed.
 * There is no heap: firmware keeps its buffers in static storage. */
#ifndef TARN_BOARD_H
#define TARN_BOARD_H

#include <stddef.h>
#include <stdint.h>

/* The board's name, as make knows it ("qemu-m3"). */
extern const char board_name[];

/* Clocks, the instruction counter and the output channel. Returns 0, or
 * non-zero when the output channel could not be opened. */
int board_init(void);

/* Sends bytes to the host: the panel's byte stream on the emulated boards.
 * Returns 0, or non-zero when the link failed. */
int board_write(const void *bytes, size_t count);

/* Sends text to the host on a second channel: the run's report line. Returns 0, or
 * non-zero when the link failed. */
int board_report(const char *text, size_t count);

/* Instructions executed since board_init(), from the board's own counter (SysTick
 * on the Arm boards, minstret on RISC-V). Under QEMU with -icount shift=0 this is
 * exact and deterministic; on real hardware it counts cycles instead. */
uint64_t board_instructions(void);

/* Bytes of the stack ever used since reset: startup paints the stack region and
 * this finds the deepest word overwritten. */
size_t board_stack_peak(void);

/* Ends the program: the emulator exits with `status`. */
void board_exit(int status) __attribute__((noreturn));

#endif
