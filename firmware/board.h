/* board.h: what the board-independent firmware needs from a board.
 *
 * Each folder in boards/ implements these functions for one board (board.c) and
 * provides the startup code that calls main() with .data copied and .bss zeroed.
 * There is no heap: firmware keeps its buffers in static storage.
 *
 * Two programs use them. The emulated boards run firmware/main.c, the measured run,
 * and send the panel the byte stream of firmware/stream_transport.c. The real
 * boards run firmware/display_main.c, frames forever, and send the panel SPI through
 * DMA (firmware/dma_transport.c over the board's panel_spi.h functions).
 * firmware/firmware.mk picks by whether board.mk gives a BOARD_RUN. */
#ifndef TARN_BOARD_H
#define TARN_BOARD_H

#include <stddef.h>
#include <stdint.h>
#include "tarn/tarn_panel.h"

/* Clocks, the counter and the panel's link (emulated boards: the output channel;
 * real boards: pins, SPI and DMA). Returns 0, or non-zero when the output channel
 * could not be opened or a clock did not start. */
int board_init(void);

/* The link to the panel, for tarn_panel_init and tarn_panel_send_tile:
 * stream_transport.c on the emulated boards, dma_transport.c on the real ones. */
const tarn_panel_transport *board_panel_transport(void);

/* Ends the program: the emulator exits with `status`; a real board resets itself
 * (a fault ends here too). */
void board_exit(int status) __attribute__((noreturn));

/* ---- Emulated boards (firmware/main.c) ---- */

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

/* ---- Real boards (firmware/display_main.c) ---- */

/* Milliseconds since board_init(), from the board's tick: the animation clock and
 * the transport's delays and timeouts. Wraps after 49 days. */
uint32_t board_milliseconds(void);

#endif
