/* sweep_error.h: each point's error against the float reference, on the host. */
#ifndef TARN_HOST_SWEEP_ERROR_H
#define TARN_HOST_SWEEP_ERROR_H

#include "scene_load.h"
#include "sweep.h"

/* The time every sweep frame is rendered at: the boards' second frame. */
#define TARN_SWEEP_TIME_MS 1000u

/* Renders each of the scene's points with the core, compares it with the
 * unsnapped reference on the finest subpixel grid (TARN_SUBPIXEL_BITS_MAX, the
 * same truth for every point) and fills error, checksum and the knobs' own math
 * errors. 0, or -1 with `err` set. */
int tarn_sweep_measure_errors(const tarn_loaded_scene *loaded, tarn_sweep_scene *scene, tarn_error *err);

/* The error of one quality on one scene (the stability table's cells), against
 * the same reference; it renders the reference each time. */
int tarn_sweep_error_of(const tarn_loaded_scene *loaded, const tarn_quality *quality,
                        tarn_compare_metrics *metrics, tarn_error *err);

#endif
