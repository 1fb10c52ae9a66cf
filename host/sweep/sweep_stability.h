/* sweep_stability.h: each knob value's worst case over the extreme scenes, and
 * each preset's errors on each.
 *
 * Every value of every knob (tarn_sweep_variants: one knob changed from the
 * balanced preset) renders each extreme scene; the first table gives, per value,
 * the lowest PSNR and shading PSNR, the largest channel error and the largest
 * share of pixels off by more than 8 levels over those scenes, each with the scene
 * it came from, and marks a value some scene refuses (a frame too large for its
 * subpixel bits). The second gives every scene's yardstick under each preset. */
#ifndef TARN_HOST_SWEEP_STABILITY_H
#define TARN_HOST_SWEEP_STABILITY_H

#include <stdio.h>
#include "progress.h"
#include "sweep.h"

/* `scene_paths`: the extreme scenes. Writes the Markdown table to `out`, stepping
 * `progress` a scene at a time. */
int tarn_sweep_stability(const char *const *scene_paths, size_t scene_count, FILE *out, tarn_progress *progress,
                         tarn_error *err);

#endif
