/* test_cli_bad_input.c: `tarn render BAD -o OUT.png` on every bad scene input.
 *
 * For each case of bad_scene_cases.h, run the real binary ($TARN_BIN, set by
 * `make check`) and require: exit status 2, stderr exactly one line starting
 * "tarn: " naming the file and its line or field, and no output file (nor any
 * leftover temporary file) in the case's directory. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "bad_scene_cases.h"
#include "cli_run.h"

/* Far longer than any refusal takes. */
#define RUN_SECONDS_MAX 20

/* Files in `dir` besides those the case wrote: an output or a temporary file. */
static int stray_files(const char *dir, const bad_scene_case *c, char *name, size_t size)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int found = 0;
    for (struct dirent *e; !found && (e = readdir(d)) != NULL;) {
        int expected = strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0 ||
                       (c->scene && strcmp(e->d_name, "bad.json") == 0);
        for (size_t k = 0; k < sizeof c->assets / sizeof c->assets[0]; k++) {
            if (c->assets[k].name && strcmp(e->d_name, c->assets[k].name) == 0) expected = 1;
        }
        if (!expected) {
            snprintf(name, size, "%s", e->d_name);
            found = 1;
        }
    }
    closedir(d);
    return found;
}

static int check_case(const char *tarn, const bad_scene_case *c)
{
    char dir[] = "/tmp/tarn_cli_test_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char scene_path[1100], out_path[1100], expected[1600], stray[256];
    assert_int_equal(bad_case_write(c, dir, scene_path, sizeof scene_path), 0);
    snprintf(out_path, sizeof out_path, "%s/out.png", dir);
    snprintf(expected, sizeof expected, "tarn: %s/%s%s\n", dir, c->file, c->expect);

    char *const argv[] = { (char *)tarn, "render", scene_path, "-o", out_path, NULL };
    cli_result r;
    cli_run(argv, -1, -1, RUN_SECONDS_MAX, &r);

    char problem[300] = "";
    char *first_newline = strchr(r.err, '\n');
    if (r.status != TARN_EXIT_BAD_INPUT) {
        snprintf(problem, sizeof problem, "exit status %d, expected 2", r.status);
    } else if (strncmp(r.err, "tarn: ", 6) != 0) {
        snprintf(problem, sizeof problem, "stderr does not start with \"tarn: \"");
    } else if (!first_newline || first_newline[1] != '\0') {
        snprintf(problem, sizeof problem, "stderr is not exactly one line");
    } else if (strcmp(r.err, expected) != 0) {
        snprintf(problem, sizeof problem, "stderr is not the expected message");
    } else if (stray_files(dir, c, stray, sizeof stray)) {
        snprintf(problem, sizeof problem, "%s was left behind", stray);
    }
    if (problem[0]) {
        print_error("case \"%s\": %s\n  stderr   %s  expected %s", c->what, problem,
                    r.err_length ? r.err : "(empty)\n", expected);
    }
    bad_case_remove_dir(dir);
    return problem[0] != '\0';
}

static void test_cli_bad_inputs(void **state)
{
    (void)state;
    const char *tarn = cli_tarn();
    int failures = 0; /* every case runs, so one run shows every wrong message */
    for (size_t k = 0; k < BAD_SCENE_CASE_COUNT; k++) {
        failures += check_case(tarn, &BAD_SCENE_CASES[k]);
    }
    assert_int_equal(failures, 0);
}

/* Outputs that cannot be written: into a directory that does not exist, onto a
 * directory, for `render` and `bake`. Exit status 2, one line that starts with the
 * output path, and nothing left behind: no temporary file beside the target. */
static void test_cli_unwritable_outputs(void **state)
{
    (void)state;
    const char *tarn = cli_tarn();
    char dir[] = "/tmp/tarn_cli_out_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char missing_png[1100], missing_c[1100], a_directory[1100];
    snprintf(missing_png, sizeof missing_png, "%s/no-such-dir/out.png", dir);
    snprintf(missing_c, sizeof missing_c, "%s/no-such-dir/out.c", dir);
    snprintf(a_directory, sizeof a_directory, "%s/taken.png", dir);
    assert_int_equal(mkdir(a_directory, 0700), 0);
    const char *const cases[][3] = {{"render", missing_png, "cannot create "},
                                    {"bake", missing_c, "cannot create "},
                                    {"render", a_directory, "is a directory, expected a file name"}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char *const argv[] = {(char *)tarn, (char *)cases[k][0], "scenes/effects/none.json", "-o",
                              (char *)cases[k][1], NULL};
        cli_result r;
        cli_run(argv, -1, -1, RUN_SECONDS_MAX, &r);
        char start[1200];
        snprintf(start, sizeof start, "tarn: %s: %s", cases[k][1], cases[k][2]);
        const char *newline = strchr(r.err, '\n');
        if (r.status != TARN_EXIT_BAD_INPUT || strncmp(r.err, start, strlen(start)) != 0 ||
            newline == NULL || newline[1] != '\0')
            fail_msg("%s -o %s: status %d, stderr %s", cases[k][0], cases[k][1], r.status, r.err);
    }
    DIR *d = opendir(dir);
    assert_non_null(d);
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        if (e->d_name[0] != '.' && strcmp(e->d_name, "taken.png") != 0) fail_msg("%s was left behind", e->d_name);
    closedir(d);
    rmdir(a_directory);
    rmdir(dir);
}

/* A texture its reader may not read. Root reads everything, so as root the binary
 * runs as nobody (setpriv, from util-linux), from a directory anyone may enter.
 * Exit status 2, the one line, no output. */
static void test_cli_unreadable_texture(void **state)
{
    (void)state;
    const char *tarn = cli_tarn();
    char dir[] = "/tmp/tarn_cli_perm_XXXXXX";
    assert_non_null(mkdtemp(dir));
    assert_int_equal(chmod(dir, 0777), 0);
    char scene[1100], texture[1100], out[1100], binary[1100], expected[1400];
    snprintf(scene, sizeof scene, "%s/bad.json", dir);
    snprintf(texture, sizeof texture, "%s/tex.png", dir);
    snprintf(out, sizeof out, "%s/out.png", dir);
    /* a copy nobody may run, whatever the permissions of the checkout's folders */
    snprintf(binary, sizeof binary, "%s/tarn", dir);
    char copy[2400];
    snprintf(copy, sizeof copy, "cp '%s' '%s' && chmod 755 '%s'", tarn, binary, binary);
    assert_int_equal(system(copy), 0);
    assert_int_equal(bad_write_text(scene, BAD_TEXTURE_SCENE), 0);
    const bad_file png = {"tex.png", BAD_PNG, NULL, 4, 4};
    assert_int_equal(bad_write_file(dir, &png), 0);
    assert_int_equal(chmod(scene, 0644), 0);
    assert_int_equal(chmod(texture, 0), 0);
    snprintf(expected, sizeof expected, "tarn: %s: cannot open: Permission denied\n", texture);
    char *const argv[] = {"/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", binary,
                          "render", scene, "-o", out, NULL};
    cli_result r;
    cli_run(geteuid() == 0 ? argv : argv + 4, -1, -1, RUN_SECONDS_MAX, &r); /* without setpriv when not root */
    assert_int_equal(r.status, TARN_EXIT_BAD_INPUT);
    assert_string_equal(r.err, expected);
    assert_int_not_equal(access(out, F_OK), 0);
    unlink(texture);
    unlink(scene);
    unlink(binary);
    rmdir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cli_bad_inputs),
        cmocka_unit_test(test_cli_unwritable_outputs),
        cmocka_unit_test(test_cli_unreadable_texture),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
