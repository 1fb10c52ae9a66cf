/* test_cli_inputs.c: `tarn render` and `tarn bake` on inputs that are not files to
 * read: FIFOs, devices, a pipe that never delivers, in place of a scene, a mesh, a
 * texture, a heightfield or a points file.
 *
 * Each runs the real binary ($TARN_BIN, set by `make check`) and must end with exit
 * status 2, exactly one stderr line "tarn: FILE: ..." naming the file and what was
 * expected, and nothing left beside the inputs. A run still going after
 * RUN_SECONDS_MAX is killed and reported as hung, so that a regression fails the
 * test instead of stopping it. FIFOs are made with mkfifo in a fresh directory;
 * nothing here writes to /dev. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "bad_scene_cases.h"

extern char **environ;

/* Far longer than any refusal takes; a run past it is hung. */
#define RUN_SECONDS_MAX 20

typedef struct {
    int status; /* exit status, or -1 if the process did not exit normally */
    int hung;   /* still running after RUN_SECONDS_MAX, and killed */
    double seconds;
    char stderr_text[4096];
    size_t stderr_length;
} run_result;

static double now_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + t.tv_nsec / 1e9;
}

/* Reads the child's stderr until it closes or the deadline passes: 0 at its end,
 * -1 when the deadline came first. */
static int read_until_closed(int fd, double deadline, run_result *out)
{
    for (;;) {
        int left_ms = (int)((deadline - now_seconds()) * 1000);
        if (left_ms <= 0) return -1;
        struct pollfd p = { fd, POLLIN, 0 };
        int ready = poll(&p, 1, left_ms);
        if (ready < 0 && errno == EINTR) continue;
        if (ready == 0) return -1;
        size_t room = sizeof out->stderr_text - 1 - out->stderr_length;
        char discard[256];
        ssize_t got = room ? read(fd, out->stderr_text + out->stderr_length, room)
                           : read(fd, discard, sizeof discard);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return 0;
        if (room) out->stderr_length += (size_t)got;
    }
}

/* Runs `argv` with stdout discarded, stderr captured and stdin from `stdin_fd` (or
 * /dev/null when it is -1); kills it after RUN_SECONDS_MAX. */
static void run(char *const argv[], int stdin_fd, run_result *out)
{
    memset(out, 0, sizeof *out);
    int err_pipe[2];
    assert_int_equal(pipe(err_pipe), 0);
    assert_int_equal(fcntl(err_pipe[0], F_SETFD, FD_CLOEXEC), 0);
    assert_int_equal(fcntl(err_pipe[1], F_SETFD, FD_CLOEXEC), 0); /* dup2 clears it on fd 2 */
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (stdin_fd >= 0)
        posix_spawn_file_actions_adddup2(&actions, stdin_fd, STDIN_FILENO);
    else
        posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, err_pipe[1], STDERR_FILENO);
    pid_t pid;
    double start = now_seconds();
    int spawned = posix_spawn(&pid, argv[0], &actions, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    close(err_pipe[1]);
    if (spawned != 0) fail_msg("cannot run %s: %s", argv[0], strerror(spawned));

    if (read_until_closed(err_pipe[0], start + RUN_SECONDS_MAX, out) != 0) {
        out->hung = 1;
        kill(pid, SIGKILL);
    }
    out->stderr_text[out->stderr_length] = '\0';
    close(err_pipe[0]);
    int wait_status;
    while (waitpid(pid, &wait_status, 0) < 0) assert_int_equal(errno, EINTR);
    out->seconds = now_seconds() - start;
    out->status = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1;
}

/* The binary under test ($TARN_BIN, which make check sets); without it the test is
 * skipped. */
static const char *tarn_binary(void)
{
    const char *tarn = getenv("TARN_BIN");
    if (!tarn || access(tarn, X_OK) != 0) {
        print_message("TARN_BIN is not set to an executable tarn binary; skipping\n");
        skip();
    }
    return tarn;
}

/* A name in `dir` other than `inputs` (NULL-terminated): an output or a temporary
 * file left behind. 1 with it in `name`, else 0. */
static int stray_file(const char *dir, const char *const inputs[], char *name, size_t size)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int found = 0;
    for (struct dirent *e; !found && (e = readdir(d)) != NULL;) {
        int expected = strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0;
        for (size_t k = 0; inputs[k]; k++) expected |= strcmp(e->d_name, inputs[k]) == 0;
        if (!expected) {
            snprintf(name, size, "%s", e->d_name);
            found = 1;
        }
    }
    closedir(d);
    return found;
}

/* What is wrong with a refused run, or "" when it is right: exit status 2, stderr
 * exactly `expected` (one line), nothing in `dir` but `inputs`. */
static void check_refusal(const run_result *r, const char *expected, const char *dir,
                          const char *const inputs[], char *problem, size_t size)
{
    char stray[256];
    problem[0] = '\0';
    if (r->hung)
        snprintf(problem, size, "hung: still running after %d s", RUN_SECONDS_MAX);
    else if (r->status != TARN_EXIT_BAD_INPUT)
        snprintf(problem, size, "exit status %d, expected 2", r->status);
    else if (strcmp(r->stderr_text, expected) != 0)
        snprintf(problem, size, "stderr is not the expected line");
    else if (stray_file(dir, inputs, stray, sizeof stray))
        snprintf(problem, size, "%s was left behind", stray);
}

/* ---- inputs that are not regular files --------------------------------------- */

#define TEXTURE_SCENE(path) \
    "{" BAD_CAMERA ", \"materials\": {\"m\": {\"texture\": \"" path "\"}}, \"objects\": []}"

typedef struct {
    const char *what;
    const char *scene;   /* bad.json's text; NULL: bad.json is the FIFO */
    const char *fifo;    /* the case's FIFO in the directory, or NULL */
    int bake_points;     /* `tarn bake ... --points DIR/points.txt` instead of render */
    int stdin_pipe;      /* stdin is a pipe that stays open and never delivers */
    const char *file;    /* the file the message names: in the directory, or absolute */
    const char *expect;  /* what follows its path */
} input_case;

static const input_case INPUT_CASES[] = {
    { "scene a FIFO", NULL, "bad.json", 0, 0, "bad.json", ": is a FIFO; a scene file must be a regular file" },
    { "mesh a FIFO", BAD_MESH_SCENE, "leaf.obj", 0, 0, "leaf.obj", ": is a FIFO; an OBJ file must be a regular file" },
    { "texture a FIFO", BAD_TEXTURE_SCENE, "tex.png", 0, 0, "tex.png", ": is a FIFO; a PNG file must be a regular file" },
    { "heightfield a FIFO", BAD_HEIGHTFIELD_SCENE, "pit.png", 0, 0, "pit.png",
      ": is a FIFO; a PNG file must be a regular file" },
    { "points file a FIFO", "", "points.txt", 1, 0, "points.txt", ": is a FIFO; a points file must be a regular file" },
    { "texture /dev/null", TEXTURE_SCENE("/dev/null"), NULL, 0, 0, "/dev/null",
      ": is a character device; a PNG file must be a regular file" },
    { "texture /dev/zero", TEXTURE_SCENE("/dev/zero"), NULL, 0, 0, "/dev/zero",
      ": is a character device; a PNG file must be a regular file" },
    { "texture /dev/stdin, a pipe that never delivers", TEXTURE_SCENE("/dev/stdin"), NULL, 0, 1, "/dev/stdin",
      ": is a FIFO; a PNG file must be a regular file" },
};

/* Runs one case in a fresh directory: 0 when it is refused as it must be. */
static int check_input_case(const char *tarn, const input_case *c)
{
    char dir[] = "/tmp/tarn_cli_inputs_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char scene[1100], fifo[1100], out[1100], points[1100], expected[1400], problem[300];
    snprintf(scene, sizeof scene, "%s/bad.json", dir);
    snprintf(points, sizeof points, "%s/points.txt", dir);
    snprintf(out, sizeof out, "%s/out.%s", dir, c->bake_points ? "c" : "png");
    if (c->bake_points) snprintf(scene, sizeof scene, "scenes/effects/none.json");
    else if (c->scene) assert_int_equal(bad_write_text(scene, c->scene), 0);
    if (c->fifo) {
        snprintf(fifo, sizeof fifo, "%s/%s", dir, c->fifo);
        assert_int_equal(mkfifo(fifo, 0600), 0);
    }
    snprintf(expected, sizeof expected, "tarn: %s%s%s%s\n", c->file[0] == '/' ? "" : dir,
             c->file[0] == '/' ? "" : "/", c->file, c->expect);

    int never_written[2] = { -1, -1 }; /* held open, so a reader waits for ever */
    if (c->stdin_pipe) assert_int_equal(pipe(never_written), 0);
    char *const render[] = { (char *)tarn, "render", scene, "-o", out, NULL };
    char *const bake[] = { (char *)tarn, "bake", scene, "-o", out, "--points", points, NULL };
    run_result r;
    run(c->bake_points ? bake : render, never_written[0], &r);
    if (c->stdin_pipe) {
        close(never_written[0]);
        close(never_written[1]);
    }
    const char *const inputs[] = { "bad.json", c->fifo ? c->fifo : "bad.json", NULL };
    check_refusal(&r, expected, dir, inputs, problem, sizeof problem);
    if (problem[0])
        print_error("case \"%s\": %s\n  stderr   %s  expected %s", c->what, problem,
                    r.stderr_length ? r.stderr_text : "(empty)\n", expected);
    bad_case_remove_dir(dir);
    return problem[0] != '\0';
}

static void test_inputs_that_are_not_files(void **state)
{
    (void)state;
    const char *tarn = tarn_binary();
    int failures = 0; /* every case runs, so one run shows every wrong message */
    for (size_t k = 0; k < sizeof INPUT_CASES / sizeof INPUT_CASES[0]; k++)
        failures += check_input_case(tarn, &INPUT_CASES[k]);
    assert_int_equal(failures, 0);
}

/* A symbolic link to a regular file is that file: a scene and a texture through
 * links render. */
static void test_links_to_files_are_read(void **state)
{
    (void)state;
    const char *tarn = tarn_binary();
    char dir[] = "/tmp/tarn_cli_links_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char cwd[1024], ground[1100], scene[1100], link[1100], texture[1100], out[1100];
    assert_non_null(getcwd(cwd, sizeof cwd));
    snprintf(ground, sizeof ground, "%s/scenes/assets/ground.png", cwd);
    snprintf(scene, sizeof scene, "%s/scene.json", dir);
    snprintf(link, sizeof link, "%s/link.json", dir);
    snprintf(texture, sizeof texture, "%s/tex.png", dir);
    snprintf(out, sizeof out, "%s/out.png", dir);
    assert_int_equal(bad_write_text(scene, BAD_TEXTURE_SCENE), 0);
    assert_int_equal(symlink("scene.json", link), 0);
    assert_int_equal(symlink(ground, texture), 0);
    char *const argv[] = { (char *)tarn, "render", link, "-o", out, "--size", "32x32", NULL };
    run_result r;
    run(argv, -1, &r);
    if (r.status != 0) fail_msg("status %d, stderr %s", r.status, r.stderr_text);
    assert_int_equal(access(out, F_OK), 0);
    bad_case_remove_dir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_inputs_that_are_not_files),
        cmocka_unit_test(test_links_to_files_are_read),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
