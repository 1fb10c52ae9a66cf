/* test_cli_help.c: help on the tool and every command, the version, and usage
 * errors as one line that says where the help is; options given twice and stray
 * words are errors; messages keep their reason and escape what a terminal would
 * obey. Runs the real binary ($TARN_BIN). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_run.h"
#include "tarn/tarn_version.h"

#define TIMEOUT_S 20
#define WORDS_MAX 16

/* `tarn LINE`, words split at spaces. */
static void run_line(const char *line, cli_result *r)
{
    static char buffer[1024];
    char *argv[WORDS_MAX + 2] = {(char *)cli_tarn()};
    int argc = 1;
    snprintf(buffer, sizeof buffer, "%s", line);
    for (char *word = strtok(buffer, " "); word != NULL && argc <= WORDS_MAX; word = strtok(NULL, " "))
        argv[argc++] = word;
    argv[argc] = NULL;
    cli_run(argv, -1, -1, TIMEOUT_S, r);
}

static void test_help_on_the_tool_and_every_command(void **state)
{
    (void)state;
    static const struct {
        const char *line, *starts;
    } cases[] = {
        {"--help", "tarn: "}, {"-h", "tarn: "}, {"help", "tarn: "},
        {"render --help", "usage: tarn render "}, {"compare --help", "usage: tarn compare "},
        {"memory --help", "usage: tarn memory "}, {"bake --help", "usage: tarn bake "},
        {"accuracy --help", "usage: tarn accuracy "}, {"show --help", "usage: tarn show "},
        {"sweep --help", "usage: tarn sweep "}, {"view --help", "usage: tarn view "}, {"help bake", "usage: tarn bake "},
        {"render scenes/pond.json -h", "usage: tarn render "},
    };
    static cli_result r;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        run_line(cases[k].line, &r);
        if (r.status != 0 || r.err_length != 0 || strncmp(r.out, cases[k].starts, strlen(cases[k].starts)) != 0)
            fail_msg("tarn %s: exit %d, stdout '%.60s', stderr '%s'", cases[k].line, r.status, r.out, r.err);
    }
    /* the overview names every command, and where each one's options are */
    run_line("--help", &r);
    static const char *const commands[] = {"render", "compare", "memory", "bake", "show", "view", "sweep", "accuracy"};
    for (size_t k = 0; k < sizeof commands / sizeof commands[0]; k++)
        if (strstr(r.out, commands[k]) == NULL) fail_msg("tarn --help does not name %s", commands[k]);
    if (strstr(r.out, "tarn COMMAND --help") == NULL) fail_msg("tarn --help does not say where the options are");
    /* the commands that take QUALITY list its knobs */
    run_line("render --help", &r);
    if (strstr(r.out, "--water-block") == NULL || strstr(r.out, "-o OUT.png") == NULL)
        fail_msg("tarn render --help lacks its options: %s", r.out);
}

/* The choices a knob's error lists ("expected a (why), b (why) or c (why), got"),
 * as the help writes them: "a|b|c". */
static void choices_of(const char *error, char *out, size_t size)
{
    const char *at = strstr(error, "expected ");
    size_t length = 0;
    out[0] = '\0';
    if (at == NULL) return;
    at += strlen("expected ");
    while (*at != '\0' && strncmp(at, "got", 3) != 0 && length + 2 < size) {
        size_t word = strcspn(at, " (,");
        if (length > 0) out[length++] = '|';
        memcpy(out + length, at, word < size - length - 1 ? word : size - length - 1);
        length += word;
        out[length] = '\0';
        at += word;
        if (*at == ' ' && at[1] == '(') at = strchr(at, ')') != NULL ? strchr(at, ')') + 1 : at + strlen(at);
        at += strspn(at, ", ");
        if (strncmp(at, "or ", 3) == 0) at += 3;
    }
}

/* The help names every choice of every knob chosen by a word, as the option's own
 * table (which its error message prints) has them: the help is typed apart. */
static void test_help_names_every_choice(void **state)
{
    (void)state;
    static const char *const knobs[] = {"--vertices", "--frame", "--refraction-normal", "--depth-interpolation",
                                        "--bins", "--lit"};
    static cli_result help, bad;
    run_line("render --help", &help);
    for (size_t k = 0; k < sizeof knobs / sizeof knobs[0]; k++) {
        char line[128], want[160], choices[128];
        snprintf(line, sizeof line, "render scenes/pond.json %s bogus -o x.png", knobs[k]);
        run_line(line, &bad);
        choices_of(bad.err, choices, sizeof choices);
        snprintf(want, sizeof want, "%s %s ", knobs[k], choices);
        if (bad.status != 2 || choices[0] == '\0' || strstr(help.out, want) == NULL)
            fail_msg("tarn render --help does not give '%s' (its error: %s)", want, bad.err);
    }
}

static void test_version(void **state)
{
    (void)state;
    static cli_result r;
    run_line("--version", &r);
    char first[64];
    snprintf(first, sizeof first, "tarn %s\n", TARN_VERSION_STRING);
    if (r.status != 0 || strncmp(r.out, first, strlen(first)) != 0)
        fail_msg("tarn --version: exit %d, stdout '%s', expected it to start '%s'", r.status, r.out, first);
    if (strstr(r.out, "link switches: PERSPECTIVE_AFFINE=") == NULL || strstr(r.out, "display backends: gpio=") == NULL ||
        strstr(r.out, "view window: ") == NULL)
        fail_msg("tarn --version lacks the link switches or the backends: %s", r.out);
}

/* Each: exit 2, one line on stderr holding `says` and ending with the help. */
static void test_usage_errors_are_one_line(void **state)
{
    (void)state;
    static const struct {
        const char *line, *says, *help;
    } cases[] = {
        {"", "expected a command: render, compare, memory, bake, show, view, sweep or accuracy", "tarn --help"},
        {"frob", "unknown command 'frob'", "tarn --help"},
        {"help frob", "no command 'frob'", "tarn --help"},
        {"help render extra", "help: unexpected argument 'extra'", "tarn --help"},
        {"render scenes/pond.json --tile 3 -o x.png", "--tile: expected a whole number 8..64", "tarn render --help"},
        {"render scenes/pond.json -o a.png -o b.png", "-o: given twice", "tarn render --help"},
        {"render scenes/pond.json -o a.png --tile 8 --tile 16", "--tile: given twice", "tarn render --help"},
        {"render scenes/pond.json scenes/lake.json -o a.png", "unexpected argument 'scenes/lake.json'",
         "tarn render --help"},
        {"accuracy --math extra", "accuracy: unexpected argument 'extra'", "tarn accuracy --help"},
        {"bake scenes/pond.json -o -", "-o -: standard output takes one image", "tarn bake --help"},
        {"render scenes/pond.json -o - --frames 3", "-o -: standard output takes one image", "tarn render --help"},
        {"compare scenes/pond.json --diff -", "--diff -:", "tarn compare --help"},
        {"compare scenes/pond.json --quiet", "--quiet applies to render and bake", "tarn compare --help"},
        {"compare scenes/pond.json --rgb565", "--rgb565 applies to render", "tarn compare --help"},
        {"view scenes/pond.json --scale 9", "--scale: expected a whole number 1..8", "tarn view --help"},
        {"view", "expected a scene file", "tarn view --help"},
        {"render scenes/pond.json --camera 0,0,0:0,0,0 -o x.png", "--camera: the position and the target",
         "tarn render --help"},
        {"memory scenes/pond.json --camera 0,0,1:0,0,0", "--camera applies to render and compare",
         "tarn memory --help"},
        {"render scenes/pond.json -o a.gif --frames 2 --fps 60", "--fps: a GIF shows at most 50 frames a second",
         "tarn render --help"},
        {"show scenes/pond.json --panel st7789-240x240 --panel st7789-240x240", "--panel: given twice",
         "tarn show --help"},
        {"sweep --out a --out b", "--out: given twice", "tarn sweep --help"},
        {"sweep --grid coarse", "--grid: expected full, quick or presets", "tarn sweep --help"},
    };
    static cli_result r;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        run_line(cases[k].line, &r);
        char ending[64];
        snprintf(ending, sizeof ending, "; try '%s'\n", cases[k].help);
        const size_t n = strlen(ending);
        if (r.status != 2 || r.out_length != 0 || !cli_one_line(&r) || strncmp(r.err, "tarn: ", 6) != 0 ||
            strstr(r.err, cases[k].says) == NULL || r.err_length < n || strcmp(r.err + r.err_length - n, ending) != 0)
            fail_msg("tarn %s: exit %d, stderr '%s': expected exit 2 and one line with '%s' ending '%s'",
                     cases[k].line, r.status, r.err, cases[k].says, cases[k].help);
    }
}

/* A path longer than the old 512-byte message: the reason still ends the line. */
static void test_long_names_keep_their_reason(void **state)
{
    (void)state;
    static char path[3000];
    memset(path, 'a', sizeof path - 1);
    for (size_t k = 200; k < sizeof path - 1; k += 200) path[k] = '/';
    path[sizeof path - 1] = '\0';
    char *argv[] = {(char *)cli_tarn(), "render", path, "-o", "/tmp/x.png", NULL};
    static cli_result r;
    cli_run(argv, -1, -1, TIMEOUT_S, &r);
    if (r.status != 2 || !cli_one_line(&r) || strstr(r.err, path) == NULL ||
        strstr(r.err, ": cannot open: No such file or directory\n") == NULL)
        fail_msg("a %zu-byte path: exit %d, stderr of %zu bytes ending '%s'", strlen(path), r.status, r.err_length,
                 r.err_length > 80 ? r.err + r.err_length - 80 : r.err);
}

/* Escape, bell and the right-to-left override in a file name never reach the
 * terminal as themselves. */
static void test_names_are_escaped(void **state)
{
    (void)state;
    char *argv[] = {(char *)cli_tarn(), "render", "x\033[2J\a\xe2\x80\xaeyz.json", "-o", "/tmp/x.png", NULL};
    static cli_result r;
    cli_run(argv, -1, -1, TIMEOUT_S, &r);
    if (r.status != 2 || !cli_one_line(&r) || strstr(r.err, "x\\x1b[2J\\x07\\u202Eyz.json: cannot open") == NULL)
        fail_msg("stderr '%s': expected the name as x\\x1b[2J\\x07\\u202Eyz.json", r.err);
    for (size_t k = 0; k + 1 < r.err_length; k++)
        if ((unsigned char)r.err[k] < 0x20 || (unsigned char)r.err[k] == 0xe2)
            fail_msg("stderr holds byte 0x%02x at %zu", (unsigned char)r.err[k], k);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_help_on_the_tool_and_every_command),
        cmocka_unit_test(test_help_names_every_choice),
        cmocka_unit_test(test_version),
        cmocka_unit_test(test_usage_errors_are_one_line),
        cmocka_unit_test(test_long_names_keep_their_reason),
        cmocka_unit_test(test_names_are_escaped),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
