#include "sweep_report.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "child_process.h"
#include "quality_text.h"
#include "sweep_front.h"
#include "sweep_grid.h"

#define PATH_MAX_BYTES 4096

static FILE *open_for_writing(const char *path, tarn_error *err)
{
    FILE *f = fopen(path, "w");
    if (f == NULL) tarn_fail(err, "%s: cannot write: %s", path, strerror(errno));
    return f;
}

static int close_written(FILE *f, const char *path, tarn_error *err)
{
    const int failed = ferror(f) != 0;
    if (fclose(f) != 0 || failed) return tarn_fail(err, "%s: cannot write: %s", path, strerror(errno));
    return 0;
}

/* ---- sweep.csv -------------------------------------------------------------------- */

static void csv_header(FILE *f, const tarn_sweep_sources *sources)
{
    fprintf(f, "scene,preset,perspective,recip_steps,depth_bits,apron,exp2_entries,exp2_mode,fog_bits,"
               "subpixel_bits,tile,bins,water_block,depth_interpolation,psnr_db,max_error,over2_pct,over8_pct,"
               "shading_psnr_db,shading_over2_pct,panel_psnr_db,coverage_pct,exp2_max_lsb,recip_max_rel");
    for (size_t s = 0; s < sources->count; s++)
        fprintf(f, ",%s_insn_per_pixel,%s_tile", sources->names[s], sources->names[s]);
    for (size_t s = 1; s < sources->count; s++)
        fprintf(f, ",%s_rgb565_insn_per_pixel,%s_rgb565_dither_insn_per_pixel", sources->names[s], sources->names[s]);
    fprintf(f, ",options\n");
}

static void csv_row(FILE *f, const tarn_sweep_scene *scene, const tarn_sweep_point *p,
                    const tarn_sweep_sources *sources)
{
    const tarn_quality *q = &p->quality;
    char span[16], apron[16], options[TARN_SWEEP_OPTIONS_MAX];
    fprintf(f, "%s,%s,%s,%u,%u,%s,%u,%s,%u,%u,%u,%s,%u,%s,%.2f,%d,%.3f,%.3f,%.2f,%.3f,%.2f,%.3f,%.2f,%.3g", scene->name,
            p->preset ? p->preset : "", tarn_quality_perspective_text(q, span, sizeof span),
            (unsigned)q->recip_newton_steps, (unsigned)q->depth_bits, tarn_quality_apron_text(q, apron, sizeof apron),
            (unsigned)q->exp2.entries, q->exp2.interpolate ? "linear" : "nearest", (unsigned)q->fog_argument_bits,
            (unsigned)q->subpixel_bits, (unsigned)q->tile_size, q->cluster_bins ? "on" : "off",
            (unsigned)q->water_block, tarn_quality_depth_text(q), p->error.whole.psnr_db,
            p->error.whole.max_channel_error, 100.0 * p->error.whole.share_over2, 100.0 * p->error.whole.share_over8,
            p->error.shading.psnr_db, 100.0 * p->error.shading.share_over2, p->error.panel_psnr_db,
            100.0 * p->error.coverage_share, p->exp2_max_lsb, p->recip_max_rel);
    for (size_t s = 0; s < sources->count; s++) {
        if (p->cost[s] < 0) fprintf(f, ",,");
        else fprintf(f, ",%.0f,%u", p->cost[s], (unsigned)(s == 0 ? q->tile_size : p->tile[s]));
    }
    for (size_t s = 1; s < sources->count; s++) {
        if (p->convert[s][0] < 0) fprintf(f, ",,");
        else fprintf(f, ",%.0f,%.0f", p->convert[s][0], p->convert[s][1]);
    }
    tarn_quality_text(q, options, sizeof options);
    fprintf(f, ",%s\n", options);
}

void tarn_sweep_write_csv(FILE *f, const tarn_sweep_scene *scenes, size_t scene_count,
                          const tarn_sweep_sources *sources)
{
    csv_header(f, sources);
    for (size_t k = 0; k < scene_count; k++)
        for (size_t i = 0; i < scenes[k].count; i++) csv_row(f, &scenes[k], &scenes[k].points[i], sources);
}

/* ---- front.md --------------------------------------------------------------------- */

static void cost_cell(FILE *f, const tarn_sweep_point *p, size_t source)
{
    if (p->cost[source] < 0) fprintf(f, " does not fit |");
    else if (source == 0) fprintf(f, " %.0f |", p->cost[source]);
    else fprintf(f, " %.0f (tile %u) |", p->cost[source], (unsigned)p->tile[source]);
}

#define ERROR_COLUMNS "| PSNR dB | max error | >2 | >8 | shading dB | shading >2 | panel dB | coverage |"
#define ERROR_RULE "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"

/* The yardstick's numbers, in ERROR_COLUMNS order. */
static void error_cells(FILE *f, const tarn_yardstick *y)
{
    fprintf(f, " %.2f | %d | %.3f%% | %.3f%% | %.2f | %.3f%% | %.2f | %.3f%% |", y->whole.psnr_db,
            y->whole.max_channel_error, 100.0 * y->whole.share_over2, 100.0 * y->whole.share_over8,
            y->shading.psnr_db, 100.0 * y->shading.share_over2, y->panel_psnr_db, 100.0 * y->coverage_share);
}

/* A table's header: its own columns, then one a source from `first` on. */
static void header_with_sources(FILE *f, const char *columns, const char *rule, const tarn_sweep_sources *sources,
                                size_t first, const char *label)
{
    fprintf(f, "%s", columns);
    for (size_t s = first; s < sources->count; s++) fprintf(f, " %s %s |", sources->names[s], label);
    fprintf(f, "\n%s", rule);
    for (size_t s = first; s < sources->count; s++) fprintf(f, " ---: |");
    fprintf(f, "\n");
}

static void preset_table(FILE *f, const tarn_sweep_scene *scene, const tarn_sweep_sources *sources)
{
    header_with_sources(f, "| preset " ERROR_COLUMNS, "| --- " ERROR_RULE, sources, 0, "insn/px");
    for (size_t i = 0; i < scene->count; i++) {
        const tarn_sweep_point *p = &scene->points[i];
        if (p->preset == NULL) continue;
        fprintf(f, "| `%s` |", p->preset);
        error_cells(f, &p->error);
        for (size_t s = 0; s < sources->count; s++) cost_cell(f, p, s);
        fprintf(f, "\n");
    }
}

/* What each board spends converting a frame to the panel's RGB565. */
static void panel_table(FILE *f, const tarn_sweep_scene *scene, const tarn_sweep_sources *sources)
{
    if (sources->count < 2) return;
    fprintf(f, "\nThe RGB565 conversion (`tarn_rgb565`, as the firmware sends it):\n\n");
    header_with_sources(f, "| preset | dither |", "| --- | --- |", sources, 1, "conversion insn/px");
    for (size_t i = 0; i < scene->count; i++) {
        const tarn_sweep_point *p = &scene->points[i];
        for (int dither = 0; dither < 2 && p->preset != NULL; dither++) {
            fprintf(f, "| `%s` | %s |", p->preset, dither ? "ordered 4x4" : "none");
            for (size_t s = 1; s < sources->count; s++) {
                if (p->convert[s][dither] < 0) fprintf(f, " does not fit |");
                else fprintf(f, " %.0f |", p->convert[s][dither]);
            }
            fprintf(f, "\n");
        }
    }
}

static void front_table(FILE *f, const tarn_sweep_scene *scene, size_t source, const char *name)
{
    size_t *front = malloc(scene->count * sizeof *front);
    if (front == NULL) return;
    size_t measured = 0;
    for (size_t i = 0; i < scene->count; i++) measured += scene->points[i].cost[source] >= 0;
    const size_t n = tarn_sweep_front(scene, source, front);
    fprintf(f, "\n### %s on %s: %zu of %zu points measured, %zu on the front\n\n", scene->name, name, measured,
            scene->count, n);
    fprintf(f, "| insn/px " ERROR_COLUMNS " knobs | preset |\n| ---: " ERROR_RULE " --- | --- |\n");
    for (size_t k = 0; k < n; k++) {
        const tarn_sweep_point *p = &scene->points[front[k]];
        char options[TARN_SWEEP_OPTIONS_MAX];
        tarn_quality_text(&p->quality, options, sizeof options);
        fprintf(f, "|");
        cost_cell(f, p, source);
        error_cells(f, &p->error);
        fprintf(f, " `%s` | %s |\n", options, p->preset ? p->preset : "");
    }
    free(front);
}

void tarn_sweep_write_fronts(FILE *f, const tarn_sweep_scene *scenes, size_t scene_count,
                             const tarn_sweep_sources *sources)
{
    for (size_t k = 0; k < scene_count; k++) {
        fprintf(f, "## %s (%ux%u, %zu points)\n\n", scenes[k].name, (unsigned)scenes[k].width,
                (unsigned)scenes[k].height, scenes[k].count);
        preset_table(f, &scenes[k], sources);
        panel_table(f, &scenes[k], sources);
        for (size_t s = 0; s < sources->count; s++) front_table(f, &scenes[k], s, sources->names[s]);
        fprintf(f, "\n");
    }
}

/* ---- the plot --------------------------------------------------------------------- */

/* Where a preset's name goes: fast below its point, balanced and exact above, a
 * step of the plot's PSNR range apart, so that neighbours do not overwrite. */
static double label_height(const tarn_sweep_scene *scene, size_t source, const tarn_sweep_point *p)
{
    double low = p->error.whole.psnr_db, high = p->error.whole.psnr_db;
    for (size_t i = 0; i < scene->count; i++) {
        if (scene->points[i].cost[source] < 0) continue;
        if (scene->points[i].error.whole.psnr_db < low) low = scene->points[i].error.whole.psnr_db;
        if (scene->points[i].error.whole.psnr_db > high) high = scene->points[i].error.whole.psnr_db;
    }
    const double step = (high - low) * 0.06 + 0.3;
    const int place = strcmp(p->preset, "fast") == 0 ? -1 : (strcmp(p->preset, "balanced") == 0 ? 1 : 2);
    return p->error.whole.psnr_db + place * step;
}

/* Three data files a source: every point, the front, the presets (with their
 * names and the height their names go at). */
static int write_plot_data(const char *work_dir, const tarn_sweep_scene *scene, size_t source,
                           const char *name, tarn_error *err)
{
    char path[PATH_MAX_BYTES];
    const char *kinds[] = {"all", "front", "presets"};
    size_t *front = malloc(scene->count * sizeof *front);
    if (front == NULL) return tarn_fail(err, "out of memory");
    const size_t n = tarn_sweep_front(scene, source, front);
    int failed = 0;
    for (int kind = 0; kind < 3 && !failed; kind++) {
        snprintf(path, sizeof path, "%s/%s-%s-%s.dat", work_dir, scene->name, name, kinds[kind]);
        FILE *f = open_for_writing(path, err);
        if (f == NULL) {
            failed = -1;
            break;
        }
        const size_t rows = kind == 1 ? n : scene->count;
        for (size_t r = 0; r < rows; r++) {
            const tarn_sweep_point *p = &scene->points[kind == 1 ? front[r] : r];
            if (p->cost[source] < 0 || (kind == 2 && p->preset == NULL)) continue;
            if (kind == 2)
                fprintf(f, "%.1f %.2f %s %.2f\n", p->cost[source], p->error.whole.psnr_db, p->preset,
                        label_height(scene, source, p));
            else
                fprintf(f, "%.1f %.2f\n", p->cost[source], p->error.whole.psnr_db);
        }
        failed = close_written(f, path, err);
    }
    free(front);
    return failed ? -1 : 0;
}

static void plot_panel(FILE *gp, const char *work_dir, const tarn_sweep_scene *scene, const char *name)
{
    fprintf(gp, "set title '%s on %s'\n", scene->name, name);
    fprintf(gp, "plot '%s/%s-%s-all.dat' using 1:2 with points pt 7 ps 0.5 lc rgb '#b0b0b0' title 'point', \\\n"
                "     '%s/%s-%s-front.dat' using 1:2 with linespoints pt 7 ps 0.8 lw 2 lc rgb '#1f5f9f' title 'front', \\\n"
                "     '%s/%s-%s-presets.dat' using 1:2 with points pt 9 ps 2 lc rgb '#d0452f' title 'preset', \\\n"
                "     '' using 1:4:3 with labels notitle\n",
            work_dir, scene->name, name, work_dir, scene->name, name, work_dir, scene->name, name);
}

static int run_gnuplot(const char *script, const char *log, tarn_error *err)
{
    char *argv[] = {"gnuplot", (char *)script, NULL};
    tarn_child gnuplot = {"gnuplot", log, TARN_SWEEP_INSTALL_GNUPLOT, 0};
    return tarn_child_run(&gnuplot, argv, err);
}

static int measured_by(const tarn_sweep_scene *scene, size_t source)
{
    for (size_t i = 0; i < scene->count; i++)
        if (scene->points[i].cost[source] >= 0) return 1;
    return 0;
}

int tarn_sweep_plot(const char *work_dir, const tarn_sweep_scene *scene, const tarn_sweep_sources *sources,
                    tarn_error *err)
{
    size_t panels = 0;
    for (size_t s = 0; s < sources->count; s++) {
        if (!measured_by(scene, s)) continue;
        if (write_plot_data(work_dir, scene, s, sources->names[s], err) != 0) return -1;
        panels++;
    }
    if (panels == 0) return tarn_fail(err, "%s: no cost measured, nothing to plot", scene->path);
    char script[PATH_MAX_BYTES], log[PATH_MAX_BYTES];
    snprintf(script, sizeof script, "%s/%s.gp", work_dir, scene->name);
    snprintf(log, sizeof log, "%s/%s.gnuplot.log", work_dir, scene->name);
    FILE *gp = open_for_writing(script, err);
    if (gp == NULL) return -1;
    fprintf(gp, "set terminal pngcairo size %u,480 noenhanced\nset output '%s/%s.png'\n",
            (unsigned)(480 * panels), work_dir, scene->name);
    fprintf(gp, "set multiplot layout 1,%zu\nset logscale x\nset grid\nset key bottom right\n"
                "set xlabel 'instructions per pixel'\nset ylabel 'PSNR against the float reference, dB'\n",
            panels);
    for (size_t s = 0; s < sources->count; s++)
        if (measured_by(scene, s)) plot_panel(gp, work_dir, scene, sources->names[s]);
    fprintf(gp, "unset multiplot\n");
    if (close_written(gp, script, err) != 0) return -1;
    return run_gnuplot(script, log, err);
}
