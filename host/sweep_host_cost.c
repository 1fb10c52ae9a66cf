#include "sweep_host_cost.h"

#include <errno.h>
#include <fcntl.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include <valgrind/callgrind.h>

#include "cli_options.h"
#include "scene_load.h"
#include "sweep_error.h"

extern char **environ;

#define WORKERS 2
#define PATH_MAX_BYTES 4096
#define LINE_MAX_BYTES 512

typedef struct {
    char points[PATH_MAX_BYTES], dumps[PATH_MAX_BYTES], log[PATH_MAX_BYTES];
    pid_t pid;
} worker;

/* Worker k renders points k, k + WORKERS, ...: "INDEX OPTIONS" per line. */
static int write_points(const tarn_sweep_scene *scene, unsigned k, const char *path, tarn_error *err)
{
    FILE *f = fopen(path, "w");
    if (f == NULL) return tarn_fail(err, "%s: cannot write: %s", path, strerror(errno));
    for (size_t i = k; i < scene->count; i += WORKERS) {
        char text[TARN_SWEEP_OPTIONS_MAX];
        tarn_sweep_quality_text(&scene->points[i].quality, text, sizeof text);
        fprintf(f, "%zu %s\n", i, text);
    }
    return fclose(f) == 0 ? 0 : tarn_fail(err, "%s: cannot write: %s", path, strerror(errno));
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
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, w->log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&files, 1, 2);
    const int status = posix_spawnp(&w->pid, "valgrind", &files, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&files);
    if (status != 0)
        return tarn_fail(err, "cannot run valgrind (%s); install it: sudo apt-get install valgrind, "
                         "or give --host-cost none", strerror(status));
    return 0;
}

static int finish_worker(const worker *w, tarn_error *err)
{
    int status;
    if (waitpid(w->pid, &status, 0) < 0) return tarn_fail(err, "waiting for valgrind: %s", strerror(errno));
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return 0;
    return tarn_fail(err, "the host-cost worker failed: see %s", w->log);
}

/* A dump holds "desc: Trigger: Client Request: point N" and "summary: INSTRUCTIONS". */
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
static void read_costs(tarn_sweep_scene *scene, const worker *w)
{
    const double pixels = (double)scene->width * scene->height;
    for (size_t n = 1; n <= (scene->count + WORKERS - 1) / WORKERS; n++) {
        char path[PATH_MAX_BYTES + 32];
        snprintf(path, sizeof path, "%s.%zu", w->dumps, n);
        size_t index;
        double instructions;
        if (read_dump(path, &index, &instructions) != 0) break;
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
        if (finish_worker(&workers[k], &worker_err) != 0 && !failed) {
            *err = worker_err;
            failed = 1;
        }
    }
    for (unsigned k = 0; k < started && !failed; k++) read_costs(scene, &workers[k]);
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

/* "INDEX OPTION VALUE ..." into the index and the quality. */
static int parse_point_line(char *line, size_t *index, tarn_quality *q, tarn_error *err)
{
    char *words[64];
    int count = 0;
    for (char *w = strtok(line, " \n"); w != NULL && count < 64; w = strtok(NULL, " \n")) words[count++] = w;
    if (count < 1 || sscanf(words[0], "%zu", index) != 1) return tarn_fail(err, "bad point line");
    *q = tarn_quality_default();
    for (int i = 1; i + 1 < count; i += 2)
        if (tarn_cli_parse_quality_option(words[i], words[i + 1], q, err) != 0) return -1;
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
    FILE *f = fopen(argv[3], "r");
    char line[LINE_MAX_BYTES], label[32];
    int failed = f == NULL;
    while (!failed && fgets(line, sizeof line, f) != NULL) {
        size_t index;
        tarn_quality q;
        failed = parse_point_line(line, &index, &q, &err) || render_point(&loaded, &q, &err);
        snprintf(label, sizeof label, "point %zu", index);
        CALLGRIND_DUMP_STATS_AT(label);
    }
    if (f != NULL) fclose(f);
    tarn_scene_free(&loaded);
    if (failed) fprintf(stderr, "tarn: %s: %s\n", argv[3], f == NULL ? strerror(errno) : err.message);
    return failed ? 2 : 0;
}
