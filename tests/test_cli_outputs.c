/* test_cli_outputs.c: where `tarn` writes, and what it leaves. A regular file is
 * replaced only when complete; a symlink's target is written and the link kept; a
 * device or FIFO is written through and stays what it was; "-" is stdout; a FIFO
 * nobody reads is an error, not a hang. A long command checks its arguments before
 * any work and a failure leaves nothing behind. Progress shows on a terminal only.
 * Every file here is one the test makes in its own folder: the machine's /dev is
 * never written. Runs the real binary ($TARN_BIN). */
/* mknod and the pseudo-terminal calls are XSI */
#define _XOPEN_SOURCE 700
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <time.h>
#include <unistd.h>

#include "cli_run.h"

#define TIMEOUT_S 20
#define SCENE "scenes/effects/fog.json"

/* tarn render SCENE at 32x32 -o `out`. */
static void render_to(const char *out, cli_result *r)
{
    char *argv[] = {(char *)cli_tarn(), "render", SCENE, "--size", "32x32", "-o", (char *)out, NULL};
    cli_run(argv, -1, -1, TIMEOUT_S, r);
}

static size_t file_bytes(const char *path, char *buffer, size_t size)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) return 0;
    size_t n = fread(buffer, 1, size, f);
    fclose(f);
    return n;
}

static char reference_png[65536];
static size_t reference_length;

/* The image as a plain render writes it into a new regular file. */
static void render_reference(void)
{
    static cli_result r;
    render_to(cli_in_folder("reference.png"), &r);
    if (r.status != 0) fail_msg("a plain render failed: %s", r.err);
    reference_length = file_bytes(cli_in_folder("reference.png"), reference_png, sizeof reference_png);
    assert_true(reference_length > 8);
}

static void expect_written(const char *what, const cli_result *r, const char *data, size_t length)
{
    if (r->status != 0) fail_msg("%s: exit %d, stderr '%s'", what, r->status, r->err);
    if (length != reference_length || memcmp(data, reference_png, length) != 0)
        fail_msg("%s: %zu bytes arrived, not the %zu of the image", what, length, reference_length);
}

static void test_a_link_keeps_pointing_at_its_written_target(void **state)
{
    (void)state;
    render_reference();
    static cli_result r;
    static char got[65536];
    assert_int_equal(symlink("target.png", cli_in_folder("link.png")), 0);
    render_to(cli_in_folder("link.png"), &r);
    expect_written("-o a symlink", &r, got, file_bytes(cli_in_folder("target.png"), got, sizeof got));
    struct stat info;
    assert_int_equal(lstat(cli_in_folder("link.png"), &info), 0);
    if (!S_ISLNK(info.st_mode)) fail_msg("-o a symlink: the link was replaced by a regular file");
    /* a dangling link: its target is made */
    assert_int_equal(symlink("made.png", cli_in_folder("dangling.png")), 0);
    render_to(cli_in_folder("dangling.png"), &r);
    expect_written("-o a dangling symlink", &r, got, file_bytes(cli_in_folder("made.png"), got, sizeof got));
}

static void test_stdout_takes_the_image(void **state)
{
    (void)state;
    render_reference();
    static cli_result r;
    render_to("-", &r);
    expect_written("-o -", &r, r.out, r.out_length);
    if (access("-", F_OK) == 0) fail_msg("-o - made a file named '-'");
    /* a link that names the pipe (as /dev/stdout does) reaches it */
    render_to("/proc/self/fd/1", &r);
    expect_written("-o /proc/self/fd/1 on a pipe", &r, r.out, r.out_length);
}

/* A FIFO with a reader gets the image and stays a FIFO; one without a reader is an
 * error at once. */
static void test_a_fifo_is_written_through(void **state)
{
    (void)state;
    render_reference();
    const char *fifo = cli_in_folder("pipe");
    assert_int_equal(mkfifo(fifo, 0600), 0);
    static cli_result r;
    const time_t start = time(NULL);
    render_to(fifo, &r);
    if (r.timed_out || r.status != 2 || !cli_one_line(&r) || strstr(r.err, "no process reads this FIFO") == NULL)
        fail_msg("-o a FIFO nobody reads: exit %d%s, stderr '%s'", r.status, r.timed_out ? " (hung)" : "", r.err);
    assert_true(time(NULL) - start < TIMEOUT_S);
    int reader = open(fifo, O_RDONLY | O_NONBLOCK);
    assert_true(reader >= 0);
    render_to(fifo, &r);
    static char got[65536];
    ssize_t length = read(reader, got, sizeof got);
    close(reader);
    expect_written("-o a FIFO", &r, got, length > 0 ? (size_t)length : 0);
    struct stat info;
    assert_int_equal(lstat(fifo, &info), 0);
    if (!S_ISFIFO(info.st_mode)) fail_msg("-o a FIFO: it is no longer a FIFO");
}

/* Device nodes of the kernel's null (1,3) and full (1,7) made in the test's own
 * folder: /dev/null takes the image and stays a device; /dev/full says it is full. */
static void test_a_device_is_written_through(void **state)
{
    (void)state;
    const char *null = cli_in_folder("null"), *full = cli_in_folder("full");
    if (mknod(null, S_IFCHR | 0666, makedev(1, 3)) != 0 || mknod(full, S_IFCHR | 0666, makedev(1, 7)) != 0) {
        if (errno == EPERM) skip(); /* device nodes need root (CI runs as root) */
        fail_msg("mknod: %s", strerror(errno));
    }
    static cli_result r;
    render_to(null, &r);
    struct stat info;
    assert_int_equal(lstat(null, &info), 0);
    if (r.status != 0 || !S_ISCHR(info.st_mode))
        fail_msg("-o a null device: exit %d, %s", r.status, S_ISCHR(info.st_mode) ? "still a device" : "replaced by a file");
    render_to(full, &r);
    assert_int_equal(lstat(full, &info), 0);
    if (r.status != 2 || !cli_one_line(&r) || strstr(r.err, "No space left on device") == NULL || !S_ISCHR(info.st_mode))
        fail_msg("-o a full device: exit %d, stderr '%s', %s", r.status, r.err,
                 S_ISCHR(info.st_mode) ? "still a device" : "replaced by a file");
}

static void test_a_folder_is_refused(void **state)
{
    (void)state;
    static cli_result r;
    render_to(cli_in_folder(""), &r);
    if (r.status != 2 || !cli_one_line(&r) || strstr(r.err, "is a directory") == NULL)
        fail_msg("-o a folder: exit %d, stderr '%s'", r.status, r.err);
}

/* A sweep with a bad --extremes fails before its work, and leaves no folder. */
static void test_a_sweep_checks_before_its_work(void **state)
{
    (void)state;
    const char *out = cli_in_folder("sweep");
    char *argv[] = {(char *)cli_tarn(), "sweep", SCENE, "--grid", "quick", "--boards", "none", "--out",
                    (char *)out, "--extremes", (char *)cli_in_folder("none"), NULL};
    static cli_result r;
    const time_t start = time(NULL);
    cli_run(argv, -1, -1, TIMEOUT_S, &r);
    if (r.status != 2 || !cli_one_line(&r) || strstr(r.err, "--extremes: no scene") == NULL)
        fail_msg("sweep --extremes (none): exit %d, stderr '%s'", r.status, r.err);
    if (time(NULL) - start > 2) fail_msg("sweep --extremes (none): the error took %ld s", (long)(time(NULL) - start));
    if (access(out, F_OK) == 0) fail_msg("a failed sweep left %s behind", out);
}

/* On a terminal, --frames and bake draw their progress on stderr and erase it;
 * --quiet, or stderr not a terminal, draws none. */
static void test_progress_on_a_terminal_only(void **state)
{
    (void)state;
    int terminal = posix_openpt(O_RDWR | O_NOCTTY);
    assert_true(terminal >= 0);
    assert_int_equal(grantpt(terminal), 0);
    assert_int_equal(unlockpt(terminal), 0);
    int screen = open(ptsname(terminal), O_RDWR | O_NOCTTY);
    assert_true(screen >= 0);
    fcntl(terminal, F_SETFL, O_NONBLOCK); /* what the child drew is there once it has ended */
    char *argv[] = {(char *)cli_tarn(), "render", SCENE, "--size", "32x32", "-o", (char *)cli_in_folder("seq.png"),
                    "--frames", "12", NULL, NULL};
    static cli_result r;
    static char shown[8192];
    for (int quiet = 0; quiet <= 1; quiet++) {
        argv[9] = quiet ? "--quiet" : NULL;
        cli_run(argv, -1, screen, TIMEOUT_S, &r);
        assert_int_equal(r.status, 0);
        ssize_t length = read(terminal, shown, sizeof shown - 1);
        shown[length > 0 ? length : 0] = '\0';
        const int drawn = strstr(shown, "tarn render: frames: 0/12") != NULL && strstr(shown, "\r\033[K") != NULL;
        if (drawn == quiet) fail_msg("--frames %s: the terminal shows '%s'", quiet ? "--quiet" : "", shown);
    }
    /* bake shows its tables being written the same way */
    char *bake[] = {(char *)cli_tarn(), "bake", SCENE, "-o", (char *)cli_in_folder("x.c"), NULL};
    cli_run(bake, -1, screen, TIMEOUT_S, &r);
    ssize_t length = read(terminal, shown, sizeof shown - 1);
    shown[length > 0 ? length : 0] = '\0';
    if (r.status != 0 || strstr(shown, "tarn bake: tables written: 0/") == NULL)
        fail_msg("bake on a terminal: exit %d, the terminal shows '%s'", r.status, shown);
    close(screen);
    close(terminal);
    argv[9] = NULL;
    cli_run(argv, -1, -1, TIMEOUT_S, &r);
    if (r.status != 0 || r.err_length != 0) fail_msg("--frames into a pipe: stderr '%s'", r.err);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_a_link_keeps_pointing_at_its_written_target, cli_make_folder, cli_remove_folder),
        cmocka_unit_test_setup_teardown(test_stdout_takes_the_image, cli_make_folder, cli_remove_folder),
        cmocka_unit_test_setup_teardown(test_a_fifo_is_written_through, cli_make_folder, cli_remove_folder),
        cmocka_unit_test_setup_teardown(test_a_device_is_written_through, cli_make_folder, cli_remove_folder),
        cmocka_unit_test_setup_teardown(test_a_folder_is_refused, cli_make_folder, cli_remove_folder),
        cmocka_unit_test_setup_teardown(test_a_sweep_checks_before_its_work, cli_make_folder, cli_remove_folder),
        cmocka_unit_test_setup_teardown(test_progress_on_a_terminal_only, cli_make_folder, cli_remove_folder),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
