/* yardstick.h: the one way tarn states a frame's error (docs/sweep.md, "The
 * yardstick"). Three numbers, each isolating one thing:
 *  - whole: the core's frame against the continuous reference (doubles all the
 *    way, vertices on no grid): everything a viewer sees, edges included;
 *  - shading: against the reference drawing the core's own triangles (its
 *    subpixel grid, its coverage pixel for pixel): the per-pixel arithmetic alone;
 *  - panel: the core's frame and that same-triangle reference both through the
 *    panel's RGB565 conversion with its ordered dither, as a board shows them: the
 *    arithmetic's error as far as the panel can show it;
 * and coverage: the share of pixels whose surface (the object drawn there) differs
 * between the core's triangles and the continuous reference. */
#ifndef TARN_HOST_YARDSTICK_H
#define TARN_HOST_YARDSTICK_H

#include <stdint.h>
#include <stdio.h>

#include "compare.h"
#include "error.h"
#include "tarn/tarn_render.h"

/* The continuous reference of one scene, size and time: the same for every
 * quality, so a sweep renders it once. */
typedef struct {
    uint8_t *rgb;      /* width*height*3, R G B */
    uint32_t *surface; /* width*height: 0, or 1 + the object's index */
    int width, height;
    uint32_t time_ms;
} tarn_continuous_reference;

typedef struct {
    tarn_compare_metrics whole;
    tarn_compare_metrics shading;
    double panel_psnr_db;
    double coverage_share; /* 0..1 */
} tarn_yardstick;

/* 0, or -1 with `err` naming `scene_name`. */
int tarn_continuous_reference_render(const tarn_scene *scene, const char *scene_name, int width, int height,
                                     uint32_t time_ms, tarn_continuous_reference *out, tarn_error *err);
void tarn_continuous_reference_free(tarn_continuous_reference *reference);

/* Measures `rgb`, the core's frame of `scene` at `config` (its size and time must be
 * the reference's), on all three. `surface_differs` (width*height bytes, or NULL)
 * receives 1 where coverage counts the pixel. 0, or -1 with `err` set. */
int tarn_yardstick_measure(const tarn_scene *scene, const char *scene_name, const tarn_frame_config *config,
                           const uint8_t *rgb, const tarn_continuous_reference *reference,
                           tarn_yardstick *out, uint8_t *surface_differs, tarn_error *err);

/* An RGB888 image through the panel's RGB565 conversion with the boards' ordered
 * dither and back, as the glass shows it (`out` may be `rgb`). */
void tarn_as_panel_shows(const uint8_t *rgb, int width, int height, uint8_t *out);

/* The one line:
 *   compare scene=NAME size=WxH time=MS psnr=NN.NN maxerr=N over2=P% over8=P%
 *   shading_psnr=NN.NN shading_over2=P% panel_psnr=NN.NN coverage=P%
 * percentages to 3 decimals. */
void tarn_yardstick_print(FILE *out, const char *scene_name, const tarn_frame_config *config,
                          const tarn_yardstick *y);

#endif
