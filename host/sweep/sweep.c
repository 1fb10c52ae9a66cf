/* nftw, to remove a failed run's work folder */
#define _XOPEN_SOURCE 700
#include "sweep.h"

#include <errno.h>
#include <ftw.h>
#include <glob.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "atomic_file.h"
#include "child_process.h"
#include "option_values.h"
#include "progress.h"
#include "quality_text.h"
#include "scene_load.h"
#include "sweep_error.h"
#include "sweep_grid.h"
#include "sweep_host_cost.h"
#include "sweep_report.h"
#include "sweep_stability.h"
#include "sweep_target.h"

#define SCENES_MAX 16
#define POINTS_MAX 512
#define PATH_MAX_BYTES 4096

typedef struct {
    const char *scenes[SCENES_MAX];
    size_t scene_count;
    const char *out_dir, *extremes_dir;
    glob_t extremes;     /* the extreme scenes, when extremes_dir is given */
    tarn_sweep_grid grid;
    int host_cost;
    int quiet;           /* no progress lines */
    char boards[128];
    tarn_sweep_sources sources;
} sweep_options;

const char tarn_sweep_usage[] =
    "usage: tarn sweep [SCENE...] [--out DIR] [--grid full|quick|presets] [--boards B,B|none]\n"
    "                  [--host-cost callgrind|none] [--extremes DIR] [--quiet]\n"
    "  SCENE        scenes to sweep (scenes/pond.json when none is given)\n"
    "  --out        where sweep.csv, front.md, SCENE.png and stability.md go (build/sweep)\n"
    "  --grid       full: the crossed knobs and every other value alone; quick: a few points;\n"
    "               presets: the three presets alone\n"
    "  --boards     emulated boards that measure target cost (qemu-m0,qemu-rv32; also qemu-m3)\n"
    "  --host-cost  callgrind (host instructions per pixel) or none\n"
    "  --extremes   a folder of extreme scenes: each knob value's worst case, in stability.md\n"
    "  --quiet      no progress lines on stderr\n";

static int parse_sources(sweep_options *o, const char *list, tarn_error *err)
{
    snprintf(o->boards, sizeof o->boards, "%s", list);
    o->sources.count = 1;
    if (strcmp(list, "none") == 0) return 0;
    for (char *b = strtok(o->boards, ","); b != NULL; b = strtok(NULL, ",")) {
        if (tarn_sweep_board_memory(b) == 0)
            return tarn_fail(err, "--boards: expected qemu-m0, qemu-rv32, qemu-m3 or none, got '%s'", b);
        if (o->sources.count == TARN_SWEEP_SOURCES_MAX) return tarn_fail(err, "--boards: at most %d boards",
                                                                        TARN_SWEEP_SOURCES_MAX - 1);
        o->sources.names[o->sources.count++] = b;
    }
    return 0;
}

static int parse_option(sweep_options *o, const char *name, const char *value, tarn_error *err)
{
    if (value == NULL || *value == '\0') return tarn_fail(err, "%s: expected a value", name);
    if (strcmp(name, "--out") == 0) o->out_dir = value;
    else if (strcmp(name, "--extremes") == 0) o->extremes_dir = value;
    else if (strcmp(name, "--boards") == 0) return parse_sources(o, value, err);
    else if (strcmp(name, "--grid") == 0) {
        static const tarn_option_choice grids[] = {
            {"full", TARN_SWEEP_GRID_FULL, NULL}, {"quick", TARN_SWEEP_GRID_QUICK, NULL},
            {"presets", TARN_SWEEP_GRID_PRESETS, NULL}};
        int grid;
        if (tarn_parse_choice(name, value, TARN_CHOICES(grids), &grid, err) != 0) return -1;
        o->grid = (tarn_sweep_grid)grid;
    } else if (strcmp(name, "--host-cost") == 0) {
        static const tarn_option_choice host_costs[] = {{"callgrind", 1, NULL}, {"none", 0, NULL}};
        return tarn_parse_choice(name, value, TARN_CHOICES(host_costs), &o->host_cost, err);
    } else return tarn_fail(err, "unknown option '%s'", name);
    return 0;
}

static int parse(int argc, char **argv, sweep_options *o, tarn_error *err)
{
    memset(o, 0, sizeof *o);
    o->out_dir = "build/sweep";
    o->grid = TARN_SWEEP_GRID_FULL;
    o->host_cost = 1;
    o->sources.names[0] = "host";
    if (parse_sources(o, "qemu-m0,qemu-rv32", err) != 0) return -1;
    tarn_options_seen seen = {.count = 0};
    for (int i = 2; i < argc; i++) {
        if (argv[i][0] != '-') {
            if (o->scene_count == SCENES_MAX) return tarn_fail(err, "at most %d scenes", SCENES_MAX);
            o->scenes[o->scene_count++] = argv[i];
        } else if (tarn_option_once(&seen, argv[i], err) != 0) {
            return -1;
        } else if (strcmp(argv[i], "--quiet") == 0) {
            o->quiet = 1;
        } else if (parse_option(o, argv[i], i + 1 < argc ? argv[i + 1] : NULL, err) != 0) {
            return -1;
        } else {
            i++;
        }
    }
    if (o->scene_count == 0) o->scenes[o->scene_count++] = "scenes/pond.json";
    return 0;
}

/* 1 when this run made the folder, 0 when it was there, -1 with `err` set. */
static int make_dir(const char *path, tarn_error *err)
{
    if (mkdir(path, 0755) == 0) return 1;
    if (errno == EEXIST) return 0;
    return tarn_fail(err, "%s: cannot create: %s", path, strerror(errno));
}

static int scene_loads(const char *path, tarn_error *err)
{
    tarn_loaded_scene loaded;
    if (tarn_scene_load(path, &loaded, err) != 0) return -1;
    tarn_scene_free(&loaded);
    return 0;
}

static int plotted(const sweep_options *o)
{
    return o->host_cost || o->sources.count > 1;
}

/* What the work will need, before any of it: every scene and extreme scene loads,
 * and every program the sweep runs is installed. A mistake then costs no minutes. */
static int check_before_work(sweep_options *o, tarn_error *err)
{
    for (size_t k = 0; k < o->scene_count; k++)
        if (scene_loads(o->scenes[k], err) != 0) return -1;
    if (o->extremes_dir != NULL) {
        char pattern[PATH_MAX_BYTES];
        snprintf(pattern, sizeof pattern, "%s/*.json", o->extremes_dir);
        if (glob(pattern, 0, NULL, &o->extremes) != 0)
            return tarn_fail(err, "--extremes: no scene (*.json) in '%s'", o->extremes_dir);
        for (size_t k = 0; k < o->extremes.gl_pathc; k++)
            if (scene_loads(o->extremes.gl_pathv[k], err) != 0) return -1;
    }
    const tarn_child valgrind = {"valgrind", NULL, TARN_SWEEP_INSTALL_VALGRIND, 0};
    const tarn_child make = {"make", NULL, TARN_SWEEP_INSTALL_MAKE, 0};
    const tarn_child gnuplot = {"gnuplot", NULL, TARN_SWEEP_INSTALL_GNUPLOT, 0};
    if (o->host_cost && tarn_child_installed(&valgrind, err) != 0) return -1;
    if (o->sources.count > 1 && tarn_child_installed(&make, err) != 0) return -1;
    return plotted(o) ? tarn_child_installed(&gnuplot, err) : 0;
}

static int remove_entry(const char *path, const struct stat *info, int kind, struct FTW *at)
{
    (void)info;
    (void)kind;
    (void)at;
    remove(path);
    return 0;
}

/* A failed run leaves nothing of its own: the work folder it made goes, unless
 * the error names a log there, and so does the output folder it made (empty: the
 * outputs are written all or none). */
static void clean_up_failure(const char *out_dir, int made_out, const char *work_dir, int made_work,
                             const tarn_error *err)
{
    if (made_work && strstr(err->message, work_dir) == NULL) nftw(work_dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
    if (made_out) rmdir(out_dir);
}

/* Drops the points the frame refuses (a frame too large for the subpixel bits),
 * saying which. */
static size_t keep_valid_points(const tarn_loaded_scene *loaded, tarn_sweep_point *points, size_t count)
{
    size_t kept = 0;
    for (size_t i = 0; i < count; i++) {
        const tarn_frame_config config = {loaded->width, loaded->height, points[i].quality, TARN_SWEEP_TIME_MS};
        if (tarn_frame_memory_bytes(&config, &loaded->scene) > 0) {
            points[kept++] = points[i];
            continue;
        }
        char text[TARN_SWEEP_OPTIONS_MAX];
        tarn_quality_text(&points[i].quality, text, sizeof text);
        fprintf(stderr, "tarn sweep: %s refuses [%s] at %ux%u: left out\n", loaded->name, text,
                (unsigned)loaded->width, (unsigned)loaded->height);
    }
    return kept;
}

/* Errors, host cost and each board's cost of one scene's points. */
static int sweep_scene(const sweep_options *o, const char *work_dir, tarn_sweep_scene *scene, tarn_error *err)
{
    tarn_loaded_scene loaded;
    if (tarn_scene_load(scene->path, &loaded, err) != 0) return -1;
    scene->name = strdup(loaded.name);
    scene->width = loaded.width;
    scene->height = loaded.height;
    scene->points = calloc(POINTS_MAX, sizeof *scene->points);
    int failed = scene->name == NULL || scene->points == NULL ? tarn_fail(err, "out of memory") : 0;
    if (!failed) {
        scene->count = keep_valid_points(&loaded, scene->points,
                                         tarn_sweep_grid_points(o->grid, scene->points, POINTS_MAX));
        fprintf(stderr, "tarn sweep: %s, %zu points: error against the reference\n", scene->name, scene->count);
        tarn_progress progress;
        tarn_progress_start(&progress, "tarn sweep: points measured", scene->count, o->quiet);
        failed = tarn_sweep_measure_errors(&loaded, scene, &progress, err);
        tarn_progress_end(&progress);
    }
    if (!failed && o->host_cost) {
        fprintf(stderr, "tarn sweep: %s: host instructions (callgrind, two workers)\n", scene->name);
        failed = tarn_sweep_host_costs(scene, work_dir, err);
    }
    for (size_t s = 1; s < o->sources.count && !failed; s++) {
        fprintf(stderr, "tarn sweep: %s: %s instructions (one boot)\n", scene->name, o->sources.names[s]);
        failed = tarn_sweep_target_costs(scene, &loaded.scene, o->sources.names[s], s, work_dir, err);
    }
    tarn_scene_free(&loaded);
    return failed ? -1 : 0;
}

/* One machine-readable line a preset, for scripts and tests. */
static void print_presets(const tarn_sweep_scene *scene, const tarn_sweep_sources *sources)
{
    for (size_t i = 0; i < scene->count; i++) {
        const tarn_sweep_point *p = &scene->points[i];
        if (p->preset == NULL) continue;
        printf("preset scene=%s name=%s psnr=%.2f maxerr=%d over2=%.3f%% over8=%.3f%% shading_psnr=%.2f "
               "shading_over2=%.3f%% panel_psnr=%.2f coverage=%.3f%%", scene->name, p->preset,
               p->error.whole.psnr_db, p->error.whole.max_channel_error, 100.0 * p->error.whole.share_over2,
               100.0 * p->error.whole.share_over8, p->error.shading.psnr_db, 100.0 * p->error.shading.share_over2,
               p->error.panel_psnr_db, 100.0 * p->error.coverage_share);
        for (size_t s = 0; s < sources->count; s++)
            if (p->cost[s] >= 0) printf(" %s=%.0f", sources->names[s], p->cost[s]);
        printf("\n");
    }
}

static int write_stability(const sweep_options *o, FILE *out, tarn_error *err)
{
    const glob_t *found = &o->extremes;
    fprintf(stderr, "tarn sweep: every knob value over the %zu extreme scenes\n", found->gl_pathc);
    tarn_progress progress;
    tarn_progress_start(&progress, "tarn sweep: extreme scenes measured", found->gl_pathc, o->quiet);
    const int failed = tarn_sweep_stability((const char *const *)found->gl_pathv, found->gl_pathc, out, &progress, err);
    tarn_progress_end(&progress);
    return failed;
}

static int copy_file(FILE *to, const char *from, tarn_error *err)
{
    FILE *f = fopen(from, "rb");
    if (f == NULL) return tarn_fail(err, "%s: cannot read: %s", from, strerror(errno));
    char buffer[8192];
    for (size_t n; (n = fread(buffer, 1, sizeof buffer, f)) > 0;) fwrite(buffer, 1, n, to);
    const int failed = ferror(f);
    fclose(f);
    return failed ? tarn_fail(err, "%s: cannot read", from) : 0;
}

#define OUTPUTS_MAX (3 + SCENES_MAX)

typedef struct {
    char names[OUTPUTS_MAX][PATH_MAX_BYTES];
    const char *paths[OUTPUTS_MAX];
    size_t count;
} output_paths;

static size_t add_output(output_paths *out, const char *dir, const char *name, const char *suffix)
{
    snprintf(out->names[out->count], PATH_MAX_BYTES, "%s/%s%s", dir, name, suffix);
    out->paths[out->count] = out->names[out->count];
    return out->count++;
}

/* The plots first (into the work folder), then every output to a temporary file,
 * renamed into place only when all are complete: a failure leaves none, and the
 * last run's outputs intact. */
static int write_outputs(const sweep_options *o, const char *work_dir, const tarn_sweep_scene *scenes,
                         size_t count, tarn_error *err)
{
    for (size_t k = 0; k < count && plotted(o); k++)
        if (tarn_sweep_plot(work_dir, &scenes[k], &o->sources, err) != 0) return -1;
    output_paths out = {.count = 0};
    const size_t csv = add_output(&out, o->out_dir, "sweep", ".csv");
    const size_t fronts = add_output(&out, o->out_dir, "front", ".md");
    const size_t stability = o->extremes_dir ? add_output(&out, o->out_dir, "stability", ".md") : 0;
    const size_t first_plot = out.count;
    for (size_t k = 0; k < count && plotted(o); k++) add_output(&out, o->out_dir, scenes[k].name, ".png");
    tarn_atomic_file files[OUTPUTS_MAX];
    if (tarn_atomic_open_all(files, out.paths, out.count, err) != 0) return -1;
    tarn_sweep_write_csv(files[csv].file, scenes, count, &o->sources);
    tarn_sweep_write_fronts(files[fronts].file, scenes, count, &o->sources);
    int failed = o->extremes_dir != NULL && write_stability(o, files[stability].file, err);
    for (size_t k = first_plot; k < out.count && !failed; k++) {
        char plot[PATH_MAX_BYTES];
        int length = snprintf(plot, sizeof plot, "%s/%s.png", work_dir, scenes[k - first_plot].name);
        failed = length < 0 || (size_t)length >= sizeof plot ? tarn_fail(err, "%s: path too long", work_dir)
                                                             : copy_file(files[k].file, plot, err);
    }
    if (!failed) return tarn_atomic_commit_all(files, out.count, err);
    tarn_atomic_abandon_all(files, out.count);
    return -1;
}

/* The sweep itself, once every check has passed. */
static int run_sweep(const sweep_options *o, const char *work_dir, tarn_sweep_scene *scenes, tarn_error *err)
{
    int failed = 0;
    for (size_t k = 0; k < o->scene_count && !failed; k++) {
        scenes[k].path = o->scenes[k];
        failed = sweep_scene(o, work_dir, &scenes[k], err);
    }
    if (!failed) failed = write_outputs(o, work_dir, scenes, o->scene_count, err);
    for (size_t k = 0; k < o->scene_count && !failed; k++) print_presets(&scenes[k], &o->sources);
    return failed;
}

int tarn_command_sweep(int argc, char **argv)
{
    sweep_options o;
    tarn_error err;
    tarn_sweep_scene scenes[SCENES_MAX];
    memset(scenes, 0, sizeof scenes);
    char work_dir[PATH_MAX_BYTES];
    if (parse(argc, argv, &o, &err) != 0) return tarn_usage_error("sweep", &err);
    int failed = check_before_work(&o, &err);
    snprintf(work_dir, sizeof work_dir, "%s/work", o.out_dir);
    const int made_out = failed ? 0 : make_dir(o.out_dir, &err);
    const int made_work = failed || made_out < 0 ? 0 : make_dir(work_dir, &err);
    failed = failed || made_out < 0 || made_work < 0 || run_sweep(&o, work_dir, scenes, &err);
    if (failed) {
        clean_up_failure(o.out_dir, made_out > 0, work_dir, made_work > 0, &err);
        fprintf(stderr, "tarn: %s\n", err.message);
    }
    for (size_t k = 0; k < o.scene_count; k++) {
        free((char *)scenes[k].name);
        free(scenes[k].points);
    }
    if (o.extremes_dir != NULL) globfree(&o.extremes);
    return failed ? 2 : 0;
}
