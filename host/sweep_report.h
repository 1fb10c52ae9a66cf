/* sweep_report.h: what tarn sweep writes.
 *
 *   sweep.csv   one row a point and scene: its knobs, its error against the float
 *               reference, the knobs' own math errors, and each source's
 *               instructions per pixel (empty where not measured) and tile
 *   front.md    per scene, the presets' figures, then each source's Pareto front
 *               (PSNR against instructions per pixel)
 *   SCENE.png   per scene, PSNR against instructions per pixel, one panel a source:
 *               every point, the front as a line, the presets named (gnuplot) */
#ifndef TARN_HOST_SWEEP_REPORT_H
#define TARN_HOST_SWEEP_REPORT_H

#include "sweep.h"

int tarn_sweep_write_csv(const char *path, const tarn_sweep_scene *scenes, size_t scene_count,
                         const tarn_sweep_sources *sources, tarn_error *err);
int tarn_sweep_write_fronts(const char *path, const tarn_sweep_scene *scenes, size_t scene_count,
                            const tarn_sweep_sources *sources, tarn_error *err);
/* Writes the plot's data and script into `work_dir` and runs gnuplot. */
int tarn_sweep_plot(const char *out_dir, const char *work_dir, const tarn_sweep_scene *scene,
                    const tarn_sweep_sources *sources, tarn_error *err);

#endif
