#include "sweep_target.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "child_process.h"
#include "quality_text.h"
#include "static_view.h"
#include "sweep_grid.h"

#define PATH_MAX_BYTES 4096
#define LINE_MAX_BYTES 512

typedef struct {
    const char *name;
    size_t memory; /* RAM - BOARD_STACK_BYTES (boards/NAME/board.mk) - 512 for .data,
                      .bss and the report */
} board_budget;

static const board_budget boards[] = {
    {"qemu-m0", 16384u - 4352u - 512u},
    {"qemu-rv32", 16384u - 4096u - 512u},
    {"qemu-m3", 4u * 1024u * 1024u - 8192u - 512u},
};

size_t tarn_sweep_board_memory(const char *board)
{
    for (size_t i = 0; i < sizeof boards / sizeof boards[0]; i++)
        if (strcmp(boards[i].name, board) == 0) return boards[i].memory;
    return 0;
}

/* The point at the largest tile the board holds (which walks the geometry the
 * fewest times), or 0 when none does. Points that vary the tile themselves are the
 * host's: a board picks its own. The memory is the baked scene's, whose static view
 * is made for the first point the board holds (`made_for`, or NULL while this is
 * that point): a point in its frame reads the bins from flash. */
static int fitted_quality(const tarn_sweep_scene *scene, const tarn_sweep_point *p, size_t budget,
                          const tarn_scene *core_scene, const tarn_frame_config *made_for, tarn_quality *out)
{
    if (p->host_tile_only) return 0;
    for (unsigned tile = TARN_TILE_SIZE_MAX; tile >= TARN_TILE_SIZE_MIN; tile--) {
        tarn_frame_config config = {scene->width, scene->height, p->quality, 0};
        config.quality.tile_size = (uint8_t)tile;
        const size_t bytes = tarn_static_memory_bytes(&config, core_scene, made_for ? made_for : &config);
        if (bytes > 0 && bytes <= budget) {
            *out = config.quality;
            return 1;
        }
    }
    return 0;
}

/* The points the board holds, each at its tile (noted in the point); map[j] is the
 * sweep index of fitted[j]. Returns how many. */
static size_t fit_points(tarn_sweep_scene *scene, const tarn_scene *core_scene, size_t budget, size_t source,
                         tarn_quality *fitted, size_t *map)
{
    size_t count = 0;
    tarn_frame_config made_for = {scene->width, scene->height, tarn_quality_default(), 0}; /* its quality: below */
    for (size_t i = 0; i < scene->count; i++) {
        tarn_sweep_point *p = &scene->points[i];
        p->tile[source] = 0;
        if (!fitted_quality(scene, p, budget, core_scene, count > 0 ? &made_for : NULL, &fitted[count])) continue;
        if (count == 0) made_for.quality = fitted[0];
        p->tile[source] = fitted[count].tile_size;
        map[count++] = i;
    }
    return count;
}

static int run_make(const char *board, const char *scene_path, const char *points, const char *first,
                    const char *build_dir, const char *log, tarn_error *err)
{
    char board_arg[64], scene_arg[PATH_MAX_BYTES + 8], points_arg[PATH_MAX_BYTES + 8], dir_arg[PATH_MAX_BYTES + 16],
        bake_arg[TARN_SWEEP_OPTIONS_MAX + 16];
    snprintf(board_arg, sizeof board_arg, "BOARD=%s", board);
    snprintf(scene_arg, sizeof scene_arg, "SCENE=%s", scene_path);
    snprintf(points_arg, sizeof points_arg, "POINTS=%s", points);
    snprintf(dir_arg, sizeof dir_arg, "FW_BUILD_DIR=%s", build_dir);
    snprintf(bake_arg, sizeof bake_arg, "BAKE_FLAGS=%s", first);
    char *argv[] = {"make", "-s", "--no-print-directory", "firmware-sweep", board_arg, scene_arg,
                    points_arg, dir_arg, bake_arg, NULL};
    tarn_child make = {"make", log, TARN_SWEEP_INSTALL_MAKE, 0};
    return tarn_child_run(&make, argv, err);
}

typedef struct {
    size_t index;
    double insn_per_pixel, convert, dither;
    unsigned checksum;
    char status[32];
} point_line;

static int parse_point_line(const char *line, point_line *p)
{
    const char *insn = strstr(line, " insn_per_pixel="), *sum = strstr(line, " checksum="),
               *status = strstr(line, " status="), *convert = strstr(line, " convert_insn_per_pixel="),
               *dither = strstr(line, " dither_insn_per_pixel=");
    return sscanf(line, "point index=%zu", &p->index) == 1 && insn && sum && status && convert && dither &&
                   sscanf(insn, " insn_per_pixel=%lf", &p->insn_per_pixel) == 1 &&
                   sscanf(convert, " convert_insn_per_pixel=%lf", &p->convert) == 1 &&
                   sscanf(dither, " dither_insn_per_pixel=%lf", &p->dither) == 1 &&
                   sscanf(sum, " checksum=%x", &p->checksum) == 1 && sscanf(status, " status=%31s", p->status) == 1
               ? 0
               : -1;
}

static int check_point(tarn_sweep_scene *scene, const char *board, const point_line *line,
                       const tarn_sweep_point *p, tarn_error *err)
{
    char text[TARN_SWEEP_OPTIONS_MAX];
    tarn_quality_text(&p->quality, text, sizeof text);
    if (strcmp(line->status, "ok") != 0)
        return tarn_fail(err, "%s: %s could not render [%s]: %s", scene->path, board, text, line->status);
    if (line->checksum != p->checksum)
        return tarn_fail(err, "%s: %s drew [%s] with checksum %08x, the host %08x: the bytes differ",
                         scene->path, board, text, line->checksum, (unsigned)p->checksum);
    return 0;
}

static int read_report(tarn_sweep_scene *scene, const char *board, size_t source, const char *path,
                       const size_t *map, size_t count, tarn_error *err)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) return tarn_fail(err, "%s: cannot read: %s", path, strerror(errno));
    char text[LINE_MAX_BYTES];
    size_t seen = 0;
    int failed = 0;
    while (!failed && fgets(text, sizeof text, f) != NULL) {
        point_line line;
        if (parse_point_line(text, &line) != 0) continue;
        if (line.index >= count) {
            failed = tarn_fail(err, "%s: point index %zu past the %zu written", path, line.index, count);
            break;
        }
        tarn_sweep_point *p = &scene->points[map[line.index]];
        failed = check_point(scene, board, &line, p, err);
        p->cost[source] = line.insn_per_pixel;
        p->convert[source][0] = line.convert;
        p->convert[source][1] = line.dither;
        seen++;
    }
    fclose(f);
    if (!failed && seen != count)
        failed = tarn_fail(err, "%s: %zu point lines for the %zu points written", path, seen, count);
    return failed ? -1 : 0;
}

/* One boot of the board over points fitted[0..count), their sweep indices in map;
 * `label` names the build's files in work_dir ("" for the whole set). */
static int measure_points(tarn_sweep_scene *scene, const char *board, size_t source, const char *work_dir,
                          const char *label, const tarn_quality *fitted, const size_t *map, size_t count,
                          tarn_error *err)
{
    char points[PATH_MAX_BYTES], build_dir[PATH_MAX_BYTES], log[PATH_MAX_BYTES], report[PATH_MAX_BYTES + 16];
    snprintf(points, sizeof points, "%s/%s-%s%s.txt", work_dir, scene->name, board, label);
    snprintf(build_dir, sizeof build_dir, "%s/%s-%s%s", work_dir, scene->name, board, label);
    snprintf(log, sizeof log, "%s/%s-%s%s.log", work_dir, scene->name, board, label);
    snprintf(report, sizeof report, "%s/report.txt", build_dir);
    /* the bake's own quality must fit the board too: the first point's */
    char first[TARN_SWEEP_OPTIONS_MAX];
    tarn_quality_text(&fitted[0], first, sizeof first);
    return tarn_sweep_write_points(points, fitted, count, err) ||
                   run_make(board, scene->path, points, first, build_dir, log, err) ||
                   read_report(scene, board, source, report, map, count, err)
               ? -1
               : 0;
}

/* Keeps the presets among the fitted points, in place; returns how many. */
static size_t keep_presets(const tarn_sweep_scene *scene, tarn_quality *fitted, size_t *map, size_t count)
{
    size_t kept = 0;
    for (size_t j = 0; j < count; j++) {
        if (scene->points[map[j]].preset == NULL) continue;
        fitted[kept] = fitted[j];
        map[kept++] = map[j];
    }
    return kept;
}

int tarn_sweep_target_costs(tarn_sweep_scene *scene, const tarn_scene *core_scene, const char *board,
                            size_t source, const char *work_dir, tarn_error *err)
{
    const size_t budget = tarn_sweep_board_memory(board);
    if (budget == 0) return tarn_fail(err, "--boards: no emulated board '%s' (qemu-m0, qemu-rv32, qemu-m3)", board);
    size_t *map = malloc(scene->count * sizeof *map);
    tarn_quality *fitted = malloc(scene->count * sizeof *fitted);
    int failed = map == NULL || fitted == NULL ? tarn_fail(err, "out of memory") : 0;
    const size_t count = failed ? 0 : fit_points(scene, core_scene, budget, source, fitted, map);
    if (count > 0) failed = measure_points(scene, board, source, work_dir, "", fitted, map, count, err);
    /* One image for every point links what any of them needs, which moves a point by
     * what the others link (exact depth beside the fast preset's plane: 2%). The
     * presets are measured again in an image of their own, as a board baking one
     * builds it, and those are their figures. */
    const size_t presets = failed ? 0 : keep_presets(scene, fitted, map, count);
    if (presets > 0 && presets < count)
        failed = measure_points(scene, board, source, work_dir, "-presets", fitted, map, presets, err);
    free(map);
    free(fitted);
    return failed ? -1 : 0;
}
