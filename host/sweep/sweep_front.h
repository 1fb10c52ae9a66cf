/* sweep_front.h: the Pareto front of a scene's points for one cost source. */
#ifndef TARN_HOST_SWEEP_FRONT_H
#define TARN_HOST_SWEEP_FRONT_H

#include "sweep.h"

/* Writes into `front` the indices of the points measured by `source` that no other
 * point beats (one costing no more with a PSNR no lower, better in one of the two),
 * cheapest first, and returns how many; `front` has room for scene->count. */
size_t tarn_sweep_front(const tarn_sweep_scene *scene, size_t source, size_t *front);

#endif
