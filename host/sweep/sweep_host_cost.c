#include "sweep_host_cost.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <valgrind/callgrind.h>

#include "bake_points.h"
#include "child_process.h"
#include "scene_load.h"
#include "sweep_error.h"
#include "sweep_grid.h"

#define WORKERS 2
#define PATH_MAX_BYTES 4096
#define LINE_MAX_BYTES 512

typedef struct {
    char points[PATH_MAX_BYTES], dumps[PATH_MAX_BYTES], log[PATH_MAX_BYTES];
    tarn_child child;
} worker;

/* Worker k renders points k, k + WORKERS, ...: its dump for line j of its points
 * file is that of point k + j * WORKERS. */
static int write_points(const tarn_sweep_scene *scene, unsigned k, const char *path, tarn_error *err)
{
    tarn_quality *shard = malloc((scene->count / WORKERS + 1) * sizeof *shard);
    if (shard == NULL) return tarn_fail(err, "out of memory");
    size_t count = 0;
    for (size_t i = k; i < scene->count; i += WORKERS) shard[count++] = scene->points[i].quality;
    const int failed = tarn_sweep_write_points(path, shard, count, err);
    free(shard);
    return failed;
}

/* This program's own file: valgrind must be given it, since /proc/self/exe would
 * name valgrind once it runs. */
static int own_path(char *out, size_t size, tarn_error *err)
{
    const ssize_t n = readlink("/proc/self/exe", out, size - 1);
    if (n <= 0) return tarn_fail(err, "cannot find the tarn program itself: %s", strerror(errno));
    out[n] = '\0';
    return 0;
}

static int start_worker(const tarn_sweep_scene *scene, worker *w, tarn_error *err)
{
    char self[PATH_MAX_BYTES], out_file[PATH_MAX_BYTES + 32];
    if (own_path(self, sizeof self, err) != 0) return -1;
    snprintf(out_file, sizeof out_file, "--callgrind-out-file=%s", w->dumps);
    char *argv[] = {"valgrind", "--tool=callgrind", out_file, "--collect-atstart=no",
                    "--toggle-collect=tarn_render_frame", "--dump-instr=no", self,
                    "sweep-cost-worker", (char *)scene->path, w->points, NULL};
    w->child.program = "valgrind";
    w->child.log = w->log;
    w->child.install = TARN_SWEEP_INSTALL_VALGRIND;
    return tarn_child_start(&w->child, argv, err);
}

/* A dump holds "desc: Trigger: Client Request: point J" (J the worker's line, from
 * 0) and "summary: INSTRUCTIONS". */
static int read_dump(const char *path, size_t *index, double *instructions)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) return -1;
    char line[LINE_MAX_BYTES];
    int found = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        if (sscanf(line, "desc: Trigger: Client Request: point %zu", index) == 1) found |= 1;
        if (sscanf(line, "summary: %lf", instructions) == 1) found |= 2;
    }
    fclose(f);
    return found == 3 ? 0 : -1;
}

/* Dumps are numbered from 1 after the file name; the last, at exit, has none. */
static void read_costs(tarn_sweep_scene *scene, const worker *w, unsigned k)
{
    const double pixels = (double)scene->width * scene->height;
    for (size_t n = 1; n <= (scene->count + WORKERS - 1) / WORKERS; n++) {
        char path[PATH_MAX_BYTES + 32];
        snprintf(path, sizeof path, "%s.%zu", w->dumps, n);
        size_t line;
        double instructions;
        if (read_dump(path, &line, &instructions) != 0) break;
        const size_t index = k + line * WORKERS;
        if (index < scene->count) scene->points[index].cost[0] = instructions / pixels;
        remove(path);
    }
    remove(w->dumps);
}

int tarn_sweep_host_costs(tarn_sweep_scene *scene, const char *work_dir, tarn_error *err)
{
    worker workers[WORKERS];
    unsigned started = 0;
    int failed = 0;
    for (unsigned k = 0; k < WORKERS && !failed; k++) {
        worker *w = &workers[k];
        snprintf(w->points, sizeof w->points, "%s/%s-host-%u.txt", work_dir, scene->name, k);
        snprintf(w->dumps, sizeof w->dumps, "%s/%s-host-%u.callgrind", work_dir, scene->name, k);
        snprintf(w->log, sizeof w->log, "%s/%s-host-%u.log", work_dir, scene->name, k);
        failed = write_points(scene, k, w->points, err) || start_worker(scene, w, err);
        if (!failed) started++;
    }
    for (unsigned k = 0; k < started; k++) {
        tarn_error worker_err;
        if (tarn_child_finish(&workers[k].child, &worker_err) != 0 && !failed) {
            *err = worker_err;
            failed = 1;
        }
    }
    for (unsigned k = 0; k < started && !failed; k++) read_costs(scene, &workers[k], k);
    for (size_t i = 0; i < scene->count && !failed; i++)
        if (scene->points[i].cost[0] < 0)
            failed = tarn_fail(err, "%s: callgrind gave no count for point %zu (see %s-host-*.log)",
                               scene->path, i, scene->name);
    return failed ? -1 : 0;
}

/* ---- the worker, under callgrind ---------------------------------------------- */

static int keep_nothing(void *user, const tarn_tile *tile)
{
    (void)user;
    (void)tile;
    return 0;
}

static int render_point(const tarn_loaded_scene *loaded, const tarn_quality *q, tarn_error *err)
{
    const tarn_frame_config config = {loaded->width, loaded->height, *q, TARN_SWEEP_TIME_MS};
    const size_t bytes = tarn_frame_memory_bytes(&config, &loaded->scene);
    void *memory = bytes ? malloc(bytes) : NULL;
    if (memory == NULL) return tarn_fail(err, "no memory for the frame (%zu bytes)", bytes);
    const tarn_status status = tarn_render_frame(&loaded->scene, &config, memory, bytes, keep_nothing, NULL);
    free(memory);
    return status == TARN_OK ? 0 : tarn_fail(err, "render failed: %s", tarn_status_text(status));
}

int tarn_command_sweep_cost_worker(int argc, char **argv)
{
    tarn_error err;
    tarn_loaded_scene loaded;
    if (argc != 4) {
        fprintf(stderr, "tarn: sweep-cost-worker SCENE POINTS_FILE (run by tarn sweep)\n");
        return 2;
    }
    if (!RUNNING_ON_VALGRIND) {
        fprintf(stderr, "tarn: sweep-cost-worker runs under callgrind (tarn sweep starts it)\n");
        return 2;
    }
    if (tarn_scene_load(argv[2], &loaded, &err) != 0) {
        fprintf(stderr, "tarn: %s\n", err.message);
        return 2;
    }
    const tarn_quality base = tarn_quality_default();
    tarn_bake_points points;
    int failed = tarn_bake_points_load(argv[3], &base, &points, &err);
    for (size_t j = 0; j < points.count && !failed; j++) {
        char label[32];
        failed = render_point(&loaded, &points.qualities[j], &err);
        snprintf(label, sizeof label, "point %zu", j);
        CALLGRIND_DUMP_STATS_AT(label);
    }
    tarn_bake_points_free(&points);
    tarn_scene_free(&loaded);
    if (failed) fprintf(stderr, "tarn: %s\n", err.message);
    return failed ? 2 : 0;
}
