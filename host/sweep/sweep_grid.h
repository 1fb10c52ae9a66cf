/* sweep_grid.h: which qualities the sweep renders.
 *
 * The full grid crosses the knobs that interact (perspective mode, reciprocal
 * steps, depth format, refraction apron, exp2 table, fog argument bits), two to
 * four values each, so that the front can combine them; then every other value
 * of every knob (subpixel bits, the other span lengths and table sizes, tile
 * size, bins...) one at a time around the balanced preset; then the three
 * presets. The quick grid (for tests) crosses perspective and depth only, and adds
 * three exp2 sizes. Every grid starts with the presets. Repeats are dropped. */
#ifndef TARN_HOST_SWEEP_GRID_H
#define TARN_HOST_SWEEP_GRID_H

#include "sweep.h"

typedef enum {
    TARN_SWEEP_GRID_FULL,
    TARN_SWEEP_GRID_QUICK,
    TARN_SWEEP_GRID_PRESETS /* the three presets alone: re-measuring the published table */
} tarn_sweep_grid;

/* Fills `points` (quality and preset set, no cost measured yet, everything else
 * cleared); returns the count, at most `max`. */
size_t tarn_sweep_grid_points(tarn_sweep_grid grid, tarn_sweep_point *points, size_t max);

/* One knob value applied to the balanced preset: the stability table's rows. */
typedef struct {
    const char *option, *value;
    tarn_quality quality;
} tarn_sweep_variant;

/* Every value of every knob, one at a time; returns the count, at most `max`. */
size_t tarn_sweep_variants(tarn_sweep_variant *variants, size_t max);

/* A points file (host/bake/bake_points.h's format, what tarn bake --points and the
 * host-cost workers read): `count` qualities, a line of every knob's option each. */
int tarn_sweep_write_points(const char *path, const tarn_quality *qualities, size_t count, tarn_error *err);

#endif
