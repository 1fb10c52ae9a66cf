/* sweep_error.h: each point's error on the host, on tarn's one yardstick
 * (yardstick.h). */
#ifndef TARN_HOST_SWEEP_ERROR_H
#define TARN_HOST_SWEEP_ERROR_H

#include "progress.h"
#include "scene_load.h"
#include "sweep.h"

/* The time every sweep frame is rendered at: the boards' second frame. */
#define TARN_SWEEP_TIME_MS 1000u

/* The scene's continuous reference at its own size and TARN_SWEEP_TIME_MS: one
 * truth for every point. */
int tarn_sweep_reference_render(const tarn_loaded_scene *loaded, tarn_continuous_reference *reference,
                                tarn_error *err);

/* Renders each of the scene's points with the core, measures it and fills error,
 * checksum and the knobs' own math errors, stepping `progress` a point at a time.
 * 0, or -1 with `err` set. */
int tarn_sweep_measure_errors(const tarn_loaded_scene *loaded, tarn_sweep_scene *scene, tarn_progress *progress,
                              tarn_error *err);

/* The error of one quality on one scene (the stability tables' cells). */
int tarn_sweep_error_of(const tarn_loaded_scene *loaded, const tarn_continuous_reference *reference,
                        const tarn_quality *quality, tarn_yardstick *error, tarn_error *err);

#endif
