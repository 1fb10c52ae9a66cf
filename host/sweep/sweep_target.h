/* sweep_target.h: each point's instructions per pixel on the emulated boards.
 *
 * For each board, the points that fit its RAM are written to a points file, each
 * with the largest tile that fits (tile size never changes the image), and one
 * boot renders them all: make firmware-sweep (firmware/sweep_main.c) under QEMU
 * with -icount shift=0. Each point's report line gives its instructions per pixel
 * and the checksum of its frame, which must equal the host's: a point the board
 * drew differently is an error, not a figure. The presets among them are then
 * measured again in a boot of their own, linking only what they use, as a board
 * that bakes one builds it. Points the board cannot hold keep a negative cost.
 * Run from the top of the tarn tree (it calls make there). */
#ifndef TARN_HOST_SWEEP_TARGET_H
#define TARN_HOST_SWEEP_TARGET_H

#include "sweep.h"

/* The renderer memory a board leaves for a frame: its RAM less the stack and the
 * firmware's own data (boards/NAME/board.mk); 0 for a board the sweep does not
 * know. */
size_t tarn_sweep_board_memory(const char *board);

/* Fills cost[source] and tile[source] of the points `board` can hold. `work_dir`
 * takes the points file and the firmware build. 0, or -1 with `err` set. */
int tarn_sweep_target_costs(tarn_sweep_scene *scene, const tarn_scene *core_scene, const char *board,
                            size_t source, const char *work_dir, tarn_error *err);

#endif
