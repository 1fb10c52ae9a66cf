/* sweep_error.h: each point's error against the float reference, on the host. */
#ifndef TARN_HOST_SWEEP_ERROR_H
#define TARN_HOST_SWEEP_ERROR_H

#include "scene_load.h"
#include "sweep.h"

/* The time every sweep frame is rendered at: the boards' second frame. */
#define TARN_SWEEP_TIME_MS 1000u

/* One truth for every point: the scene's unsnapped reference on the finest subpixel
 * grid it has, at TARN_SWEEP_TIME_MS. A reference on each point's own grid would
 * round positions as the point does, and a coarser grid would then read as more
 * accurate. */
typedef struct {
    uint8_t *rgb, *covered; /* R G B, and 1 where a triangle drew */
    int width, height;      /* the scene's own frame */
} tarn_sweep_reference;

int tarn_sweep_reference_render(const tarn_loaded_scene *loaded, tarn_sweep_reference *reference,
                                tarn_error *err);
void tarn_sweep_reference_free(tarn_sweep_reference *reference);

/* Renders each of the scene's points with the core, compares it with the scene's
 * reference and fills error, panel error, checksum and the knobs' own math errors.
 * 0, or -1 with `err` set. */
int tarn_sweep_measure_errors(const tarn_loaded_scene *loaded, tarn_sweep_scene *scene, tarn_error *err);

/* The error of one quality on one scene against its reference (the stability
 * table's cells). */
int tarn_sweep_error_of(const tarn_loaded_scene *loaded, const tarn_sweep_reference *reference,
                        const tarn_quality *quality, tarn_compare_metrics *metrics, tarn_error *err);

#endif
