/* sweep_host_cost.h: each point's host instructions per pixel, from callgrind.
 *
 * The sweep runs itself under valgrind's callgrind, as two workers (one per core)
 * that each render half the points: `tarn sweep-cost-worker SCENE POINTS_FILE`,
 * collecting only inside tarn_render_frame (the whole frame, tiles and all, with a
 * sink that keeps nothing) and dumping the count after each point. Instruction
 * counts, unlike times, do not move with the machine's load. */
#ifndef TARN_HOST_SWEEP_HOST_COST_H
#define TARN_HOST_SWEEP_HOST_COST_H

#include "sweep.h"

/* Fills cost[0] of every point; `work_dir` takes the points files, logs and
 * callgrind's dumps. 0, or -1 with `err` set (valgrind missing, a worker failed). */
int tarn_sweep_host_costs(tarn_sweep_scene *scene, const char *work_dir, tarn_error *err);

#endif
