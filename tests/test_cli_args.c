/* test_cli_args.c: the command line is checked before anything is read or written:
 * each bad argument gets one line naming the option and what was expected. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmocka.h>

#include "cli_options.h"

#define ARGS_MAX 32

/* Parses a space-separated command line (after "tarn"). */
static int parse(const char *line, tarn_cli_options *o, tarn_error *err)
{
    static char buffer[512];
    char *argv[ARGS_MAX] = {"tarn"};
    int argc = 1;
    snprintf(buffer, sizeof buffer, "%s", line);
    for (char *word = strtok(buffer, " "); word && argc < ARGS_MAX; word = strtok(NULL, " "))
        argv[argc++] = word;
    return tarn_cli_parse(argc, argv, o, err);
}

static void assert_rejected(const char *line, const char *expected_text)
{
    tarn_cli_options o;
    tarn_error err;
    err.message[0] = '\0';
    if (parse(line, &o, &err) == 0) fail_msg("accepted: tarn %s", line);
    if (strstr(err.message, expected_text) == NULL)
        fail_msg("tarn %s: message '%s' lacks '%s'", line, err.message, expected_text);
    assert_null(strchr(err.message, '\n'));
}

static void test_good_lines_parse(void **state)
{
    (void)state;
    tarn_cli_options o;
    tarn_error err;
    assert_int_equal(parse("render s.json -o out.png --size 320x200 --tile 16 --time 4294967295 "
                           "--perspective span:8 --depth 16 --subpixel 3 --recip-steps 0 --exp2 32:nearest",
                           &o, &err), 0);
    assert_int_equal(o.command, TARN_CMD_RENDER);
    assert_string_equal(o.scene_path, "s.json");
    assert_string_equal(o.output_path, "out.png");
    assert_int_equal(o.width, 320);
    assert_int_equal(o.height, 200);
    assert_int_equal(o.quality.tile_size, 16);
    assert_true(o.time_ms == 4294967295u);
    assert_int_equal(o.quality.perspective, TARN_PERSPECTIVE_SPAN);
    assert_int_equal(o.quality.perspective_span, 8);
    assert_int_equal(o.quality.depth_bits, 16);
    assert_int_equal(o.quality.subpixel_bits, 3);
    assert_int_equal(o.quality.recip_newton_steps, 0);
    assert_int_equal(o.quality.exp2.entries, 32);
    assert_int_equal(o.quality.exp2.interpolate, 0);

    assert_int_equal(parse("compare s.json --snapped --diff heat.png", &o, &err), 0);
    assert_int_equal(o.command, TARN_CMD_COMPARE);
    assert_true(o.snapped);
    assert_string_equal(o.diff_path, "heat.png");
    assert_int_equal(parse("accuracy --math", &o, &err), 0);
    assert_true(o.math);
}

static void test_bad_lines_name_what_was_expected(void **state)
{
    (void)state;
    assert_rejected("", "expected a command");
    assert_rejected("draw s.json", "unknown command 'draw'");
    assert_rejected("render s.json", "expected -o");
    assert_rejected("render -o out.png", "expected a scene file");
    assert_rejected("render a.json b.json -o out.png", "unexpected argument 'b.json'");
    assert_rejected("render s.json -o", "-o: expected a file name");
    assert_rejected("render s.json -o x.png --size 0x10", "--size: expected WxH");
    assert_rejected("render s.json -o x.png --size 1025x10", "--size: expected WxH");
    assert_rejected("render s.json -o x.png --size 99999999999999999999x1", "--size");
    assert_rejected("render s.json -o x.png --size 10x", "--size");
    assert_rejected("render s.json -o x.png --size -5x5", "--size");
    assert_rejected("render s.json -o x.png --tile 7", "--tile: expected a whole number 8..64");
    assert_rejected("render s.json -o x.png --tile 65", "--tile");
    assert_rejected("render s.json -o x.png --tile 1e1", "--tile");
    assert_rejected("render s.json -o x.png --subpixel 0", "--subpixel");
    assert_rejected("render s.json -o x.png --time -1", "--time: expected milliseconds");
    assert_rejected("render s.json -o x.png --time 4294967296", "--time");
    assert_rejected("render s.json -o x.png --perspective span:12", "--perspective");
    assert_rejected("render s.json -o x.png --perspective span:128", "--perspective");
    assert_rejected("render s.json -o x.png --perspective exact", "--perspective");
    assert_rejected("render s.json -o x.png --depth 24", "--depth: expected 16 or 32");
    assert_rejected("render s.json -o x.png --recip-steps 3", "--recip-steps");
    assert_rejected("render s.json -o x.png --exp2 300", "--exp2");
    assert_rejected("render s.json -o x.png --exp2 48", "--exp2");
    assert_rejected("render s.json -o x.png --exp2 64:cubic", "--exp2");
    assert_rejected("render s.json -o x.png --snapped", "--snapped applies to the reference");
    assert_rejected("render s.json -o x.png --bogus 1", "unknown option '--bogus'");
    assert_rejected("accuracy", "accuracy: expected --math");
}

/* Through the real binary: exit status 2, usage on stderr, nothing written. */
static void test_binary_exits_2_and_writes_nothing(void **state)
{
    (void)state;
    const char *tarn = getenv("TARN_BIN");
    if (tarn == NULL) skip();
    char dir[] = "/tmp/tarn-cli-XXXXXX", out[64], command[512];
    assert_non_null(mkdtemp(dir));
    snprintf(out, sizeof out, "%s/out.png", dir);
    snprintf(command, sizeof command, "%s render scenes/pond.json -o %s --tile 3 2>/dev/null", tarn, out);
    int status = system(command);
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 2);
    struct stat st;
    assert_int_not_equal(stat(out, &st), 0);
    /* an output directory that does not exist: a one-line error, no file anywhere */
    snprintf(command, sizeof command, "%s render scenes/pond.json -o %s/missing/out.png 2>/dev/null", tarn, dir);
    status = system(command);
    assert_int_equal(WEXITSTATUS(status), 2);
    assert_int_equal(rmdir(dir), 0); /* empty: nothing was left behind */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_good_lines_parse),
        cmocka_unit_test(test_bad_lines_name_what_was_expected),
        cmocka_unit_test(test_binary_exits_2_and_writes_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
