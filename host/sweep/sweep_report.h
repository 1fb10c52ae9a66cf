/* sweep_report.h: what tarn sweep writes.
 *
 *   sweep.csv   one row a point and scene: its knobs, its error against the float
 *               reference, the knobs' own math errors, and each source's
 *               instructions per pixel (empty where not measured) and tile
 *   front.md    per scene, the presets' figures, then each source's Pareto front
 *               (PSNR against instructions per pixel)
 *   SCENE.png   per scene, PSNR against instructions per pixel, one panel a source:
 *               every point, the front as a line, the presets named (gnuplot)
 * The text goes to files the caller opened (host/sweep/sweep.c writes them all or none). */
#ifndef TARN_HOST_SWEEP_REPORT_H
#define TARN_HOST_SWEEP_REPORT_H

#include <stdio.h>
#include "sweep.h"

void tarn_sweep_write_csv(FILE *f, const tarn_sweep_scene *scenes, size_t scene_count,
                          const tarn_sweep_sources *sources);
void tarn_sweep_write_fronts(FILE *f, const tarn_sweep_scene *scenes, size_t scene_count,
                             const tarn_sweep_sources *sources);
/* Writes the plot's data, script and work_dir/SCENE.png (gnuplot). */
int tarn_sweep_plot(const char *work_dir, const tarn_sweep_scene *scene, const tarn_sweep_sources *sources,
                    tarn_error *err);

#endif
