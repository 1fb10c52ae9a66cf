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

/* ---- Real boards of two cores (BOARD_CORES := 2: firmware/display_main.c) ----
 * Core 0 runs main(); these let it draw each frame with core 1: a part each
 * (tarn_render_frame_part), both sending their tiles to the one panel, or a strip
 * pipeline's two workers (tarn_strip_pipeline_begin, BOARD_CORE_SPLIT := pipeline),
 * core 0 sending the strips. */

/* Starts `entry` on core 1, on the stack that ends at `stack_top` (8-byte aligned),
 * with the vector table core 0 runs on. Returns 0, or non-zero when core 1 did not
 * answer within a second. */
int board_second_core_start(void (*entry)(void), uint32_t *stack_top);

/* A word to the other core, waiting while its queue is full; and the next word from
 * it, waiting until one comes. */
void board_core_send(uint32_t word);
uint32_t board_core_receive(void);

/* Between a core's writes to memory the other core reads and the word that tells
 * it they are done: the writes first, as the other core sees them. */
void board_cores_order(void);

/* The strips' lock: a core holds it while it takes the next strip of a strip
 * pipeline, waiting while the other holds it. */
void board_strips_lock(void);
void board_strips_unlock(void);

/* The panel's lock: a core holds it while it sends a tile (its window and pixels
 * must not mix with the other core's), waiting while the other holds it. */
void board_panel_lock(void);
void board_panel_unlock(void);

#endif
