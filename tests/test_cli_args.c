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

#include "backdrop.h"
#include "cli_options.h"
#include "frame_path.h"

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

    assert_int_equal(parse("render s.json -o x.png --quality fast --refraction-normal exact", &o, &err), 0);
    assert_int_equal(o.quality.refraction_normal, TARN_REFRACTION_NORMAL_EXACT);
    assert_int_equal(parse("render s.json -o x.png --refraction-normal shared", &o, &err), 0);
    assert_int_equal(o.quality.refraction_normal, TARN_REFRACTION_NORMAL_SHARED);
    assert_int_equal(parse("render s.json -o x.png --lit planes", &o, &err), 0);
    assert_int_equal(o.quality.lit_colour, TARN_LIT_PLANES);
    assert_int_equal(parse("render s.json -o x.png --quality exact --lit line", &o, &err), 0);
    assert_int_equal(o.quality.lit_colour, TARN_LIT_LINE);
    assert_int_not_equal(parse("render s.json -o x.png --lit rgb", &o, &err), 0);
    assert_int_equal(parse("render s.json -o x.png --frame strips --vertices frame", &o, &err), 0);
    assert_int_equal(o.quality.frame_shape, TARN_FRAME_STRIPS);
    assert_int_equal(o.quality.vertex_pass, TARN_VERTICES_PER_FRAME);
    assert_int_equal(parse("render s.json -o x.png --vertices frame-view", &o, &err), 0);
    assert_int_equal(o.quality.vertex_pass, TARN_VERTICES_PER_FRAME_VIEW);
    assert_int_equal(parse("render s.json -o x.png", &o, &err), 0);
    assert_int_equal(o.quality.frame_shape, TARN_FRAME_TILES);
    assert_int_equal(o.quality.vertex_pass, TARN_VERTICES_PER_TILE);
    assert_int_not_equal(parse("render s.json -o x.png --frame bands", &o, &err), 0);
    assert_int_not_equal(parse("render s.json -o x.png --vertices 2", &o, &err), 0);
    assert_int_equal(parse("compare s.json --backdrop still --diff heat.png", &o, &err), 0);
    assert_int_equal(o.command, TARN_CMD_COMPARE);
    assert_int_equal(o.backdrop, TARN_BACKDROP_STILL);
    assert_string_equal(o.diff_path, "heat.png");
    assert_int_equal(parse("accuracy --math", &o, &err), 0);
    assert_true(o.math);
    assert_int_equal(parse("memory s.json --tile 16 --depth 16", &o, &err), 0);
    assert_int_equal(o.command, TARN_CMD_MEMORY);
    assert_int_equal(parse("render s.json -o x.png --apron off", &o, &err), 0);
    assert_int_equal(o.quality.refraction_apron, 0);
    assert_int_equal(parse("render s.json -o x.png --apron 12", &o, &err), 0);
    assert_int_equal(o.quality.refraction_apron, 12);
    assert_int_equal(parse("render s.json -o x.png --apron on", &o, &err), 0);
    assert_int_equal(o.quality.refraction_apron, TARN_APRON_FULL);
    assert_int_equal(o.frames, 0);
}

static int same_quality(const tarn_quality *a, const tarn_quality *b)
{
    return a->exp2.entries == b->exp2.entries && a->exp2.interpolate == b->exp2.interpolate &&
           a->recip_newton_steps == b->recip_newton_steps && a->subpixel_bits == b->subpixel_bits &&
           a->perspective == b->perspective && a->perspective_span == b->perspective_span &&
           a->depth_bits == b->depth_bits && a->tile_size == b->tile_size &&
           a->refraction_apron == b->refraction_apron && a->cluster_bins == b->cluster_bins &&
           a->fog_argument_bits == b->fog_argument_bits && a->water_block == b->water_block &&
           a->depth_interpolation == b->depth_interpolation && a->frame_shape == b->frame_shape &&
           a->vertex_pass == b->vertex_pass && a->lit_colour == b->lit_colour;
}

/* A preset is the base; a knob changes it wherever it stands on the line. */
static void test_presets_are_the_base_of_the_knobs(void **state)
{
    (void)state;
    tarn_cli_options o;
    tarn_error err;
    const tarn_quality fast = tarn_quality_preset(TARN_PRESET_FAST);
    assert_int_equal(parse("render s.json -o x.png --quality fast", &o, &err), 0);
    assert_true(same_quality(&o.quality, &fast));
    assert_int_equal(parse("render s.json -o x.png", &o, &err), 0);
    const tarn_quality balanced = tarn_quality_preset(TARN_PRESET_BALANCED);
    assert_true(same_quality(&o.quality, &balanced));
    tarn_quality expected = tarn_quality_preset(TARN_PRESET_EXACT);
    expected.depth_bits = 16;
    expected.fog_argument_bits = 10;
    assert_int_equal(parse("bake s.json -o x.c --depth 16 --quality exact --fog-bits 10", &o, &err), 0);
    assert_true(same_quality(&o.quality, &expected));
    assert_false(same_quality(&fast, &balanced));
    for (int p = 0; p < TARN_PRESET_COUNT; p++) {
        const tarn_frame_config config = {240, 240, tarn_quality_preset((tarn_preset)p), 0};
        assert_true(tarn_frame_memory_bytes(&config, NULL) > 0); /* every preset is a valid config */
    }
    assert_rejected("render s.json -o x.png --quality turbo", "--quality: expected fast, balanced or exact, got 'turbo'");
    assert_rejected("render s.json -o x.png --quality fast --quality exact", "--quality: given twice");
    assert_rejected("compare s.json --quality", "--quality: expected fast, balanced or exact, got ''");
    assert_rejected("render s.json -o x.png --points p.txt", "--points applies to bake");
    assert_rejected("compare s.json --fog-bits 3", "--fog-bits: expected a whole number 4..16, got '3'");
}

/* --depth-interpolation exact|plane; the fast preset steps depth on a plane. */
static void test_depth_interpolation_option(void **state)
{
    (void)state;
    tarn_cli_options o;
    tarn_error err;
    assert_int_equal(tarn_quality_preset(TARN_PRESET_FAST).depth_interpolation, TARN_DEPTH_PLANE);
    assert_int_equal(tarn_quality_default().depth_interpolation, TARN_DEPTH_EXACT);
    assert_int_equal(parse("render s.json -o x.png --depth-interpolation plane", &o, &err), 0);
    assert_int_equal(o.quality.depth_interpolation, TARN_DEPTH_PLANE);
    assert_int_equal(parse("bake s.json -o x.c --depth-interpolation exact --quality fast", &o, &err), 0);
    assert_int_equal(o.quality.depth_interpolation, TARN_DEPTH_EXACT);
    assert_rejected("render s.json -o x.png --depth-interpolation linear",
                    "--depth-interpolation: expected exact (near/d rounded exactly at each pixel) or plane "
                    "(stepped on a plane, a division less a triangle), got 'linear'");
    assert_rejected("compare s.json --depth-interpolation", "--depth-interpolation: expected exact");
}

/* --water-block 1|2|4, a block only with a tile it divides, wherever the tile comes
 * from. */
static void test_water_block_option(void **state)
{
    (void)state;
    tarn_cli_options o;
    tarn_error err;
    assert_int_equal(parse("render s.json -o x.png --water-block 2", &o, &err), 0);
    assert_int_equal(o.quality.water_block, 2);
    assert_int_equal(parse("bake s.json -o x.c --quality exact --water-block 2 --tile 32", &o, &err), 0);
    assert_int_equal(o.quality.water_block, 2);
    assert_int_equal(o.quality.tile_size, 32);
    assert_int_equal(parse("bake s.json -o x.c --water-block 4 --tile 36", &o, &err), 0);
    assert_int_equal(o.quality.water_block, 4);
    assert_rejected("render s.json -o x.png --water-block 3", "--water-block: expected 1, 2 or 4, got '3'");
    assert_rejected("render s.json -o x.png --water-block 2 --tile 43",
                    "--water-block 2: expected a --tile that is a multiple of 2 (a tile must hold whole blocks), got 43");
    assert_rejected("compare s.json --tile 9 --water-block 2", "--water-block 2: expected a --tile that is a multiple of 2");
    assert_rejected("bake s.json -o x.c --water-block 4 --tile 42", "--water-block 4: expected a --tile that is a multiple of 4");
}

/* bake --static-view: on by default, off when asked, and nothing else. */
static void test_static_view_option(void **state)
{
    (void)state;
    tarn_cli_options o;
    tarn_error err;
    assert_int_equal(parse("bake s.json -o x.c", &o, &err), 0);
    assert_int_equal(o.no_static_view, 0);
    assert_int_equal(parse("bake s.json -o x.c --static-view off", &o, &err), 0);
    assert_int_equal(o.no_static_view, 1);
    assert_rejected("bake s.json -o x.c --static-view off --static-view on", "--static-view: given twice");
    assert_rejected("bake s.json -o x.c --static-view maybe", "--static-view: expected on or off, got 'maybe'");
    assert_rejected("bake s.json -o x.c --static-view", "--static-view: expected on or off, got ''");
    assert_rejected("render s.json -o x.png --static-view off", "--static-view applies to bake");
}

/* render, bake --backdrop: off by default, on or still when asked; one core quality
 * with static vertices, so not with the reference, points or --static-view off. */
static void test_backdrop_option(void **state)
{
    (void)state;
    tarn_cli_options o;
    tarn_error err;
    assert_int_equal(parse("bake s.json -o x.c", &o, &err), 0);
    assert_int_equal(o.backdrop, TARN_BACKDROP_NONE);
    assert_int_equal(parse("bake s.json -o x.c --backdrop on", &o, &err), 0);
    assert_int_equal(o.backdrop, TARN_BACKDROP_OPAQUE);
    assert_rejected("render s.json -o x.png --backdrop on --backdrop off", "--backdrop: given twice");
    assert_int_equal(parse("bake s.json -o x.c --backdrop still", &o, &err), 0);
    assert_int_equal(o.backdrop, TARN_BACKDROP_STILL);
    assert_rejected("bake s.json -o x.c --backdrop yes", "--backdrop: expected on, off or still, got 'yes'");
    assert_rejected("render s.json -o x.png --backdrop", "--backdrop: expected on, off or still, got ''");
    assert_rejected("render s.json -o x.png --reference --backdrop still", "it excludes --reference");
    assert_rejected("memory s.json --backdrop on", "--backdrop applies to render, compare and bake");
    assert_rejected("render s.json -o x.png --reference --backdrop on", "it excludes --reference");
    assert_rejected("bake s.json -o x.c --backdrop on --points p.txt", "it excludes --points");
    assert_rejected("bake s.json -o x.c --backdrop on --static-view off", "it excludes --static-view off");
    /* --landing-depth: world units 1..4 with still water, the deepest unless given */
    assert_int_equal(parse("bake s.json -o x.c --backdrop still", &o, &err), 0);
    assert_int_equal(tarn_cli_backdrop(&o).landing_depth_q16, TARN_LANDING_DEPTH_MAX_Q16);
    assert_int_equal(parse("bake s.json -o x.c --backdrop still --landing-depth 1.25", &o, &err), 0);
    assert_int_equal(tarn_cli_backdrop(&o).kind, TARN_BACKDROP_STILL);
    assert_int_equal(tarn_cli_backdrop(&o).landing_depth_q16, 81920u);
    assert_rejected("bake s.json -o x.c --backdrop still --landing-depth 0.5",
                    "--landing-depth: expected world units 1..4, got '0.5'");
    assert_rejected("bake s.json -o x.c --backdrop still --landing-depth nan",
                    "--landing-depth: expected world units 1..4, got 'nan'");
    assert_rejected("bake s.json -o x.c --backdrop still --landing-depth 2x",
                    "--landing-depth: expected world units 1..4, got '2x'");
    assert_rejected("bake s.json -o x.c --backdrop on --landing-depth 2", "--landing-depth applies to --backdrop still");
}

static void test_frame_sequences_parse(void **state)
{
    (void)state;
    tarn_cli_options o;
    tarn_error err;
    assert_int_equal(parse("render s.json -o o.png --frames 10000 --fps 120 --time 5", &o, &err),
                     0);
    assert_int_equal(o.frames, 10000);
    assert_int_equal(o.fps, 120);
    /* frame k at time + floor(k * 1000 / fps) */
    assert_int_equal(tarn_cli_frame_time(&o, 0), 5);
    assert_int_equal(tarn_cli_frame_time(&o, 1), 5 + 8);  /* 8.33 */
    assert_int_equal(tarn_cli_frame_time(&o, 3), 5 + 25);
    assert_int_equal(tarn_cli_frame_time(&o, 9999), 5 + 83325);
    assert_int_equal(parse("render s.json -o out.png --frames 2", &o, &err), 0);
    assert_int_equal(o.fps, 30); /* the default */
    assert_int_equal(tarn_cli_frame_time(&o, 1), 33);
    /* the last frame's clock may reach UINT32_MAX but not pass it */
    assert_int_equal(parse("render s.json -o o.png --frames 2 --fps 1 --time 4294966295", &o,
                           &err), 0);
    assert_true(tarn_cli_frame_time(&o, 1) == UINT32_MAX);

    char path[32];
    assert_int_equal(tarn_frame_path("out.png", 0, path, sizeof path), 0);
    assert_string_equal(path, "out-0000.png");
    assert_int_equal(tarn_frame_path("dir.v2/frames", 9999, path, sizeof path), 0);
    assert_string_equal(path, "dir.v2/frames-9999.png");
    assert_int_equal(tarn_frame_path("a.png.png", 12, path, sizeof path), 0);
    assert_string_equal(path, "a.png-0012.png");
    assert_int_equal(tarn_frame_path("a-long-name.png", 1, path, 16), -1); /* no room */
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
    assert_rejected("render s.json -o x.png --apron maybe", "--apron: expected on");
    assert_rejected("render s.json -o x.png --apron 33", "--apron: expected on");
    assert_rejected("render s.json -o x.png --apron -1", "--apron: expected on");
    assert_rejected("render s.json -o x.png --recip-steps 3", "--recip-steps");
    assert_rejected("render s.json -o x.png --exp2 300", "--exp2");
    assert_rejected("render s.json -o x.png --exp2 48", "--exp2");
    assert_rejected("render s.json -o x.png --exp2 64:cubic", "--exp2");
    assert_rejected("render s.json -o x.png --snapped", "--snapped applies to render --reference");
    assert_rejected("compare s.json --snapped", "--snapped applies to render --reference");
    assert_rejected("render s.json -o x.png --bogus 1", "unknown option '--bogus'");
    assert_rejected("accuracy", "accuracy: expected --math");
    assert_rejected("render s.json -o x.png --frames 0",
                    "--frames: expected a whole number 1..10000");
    assert_rejected("render s.json -o x.png --frames 10001", "--frames: expected");
    assert_rejected("render s.json -o x.png --frames 2.5", "--frames: expected");
    assert_rejected("render s.json -o x.png --frames", "--frames: expected");
    assert_rejected("render s.json -o x.png --frames 3 --fps 0",
                    "--fps: expected a whole number 1..120");
    assert_rejected("render s.json -o x.png --frames 3 --fps 121", "--fps: expected");
    assert_rejected("render s.json -o x.png --fps 30",
                    "--fps applies to a sequence: add --frames N");
    assert_rejected("compare s.json --frames 3", "--frames applies to render");
    assert_rejected("render s.json -o x.png --frames 3 --fps 1 --time 4294966296",
                    "--frames: the last frame would be at 4294968296 ms, past 4294967295");
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
    /* a --size that widens refraction past the apron: a clear error, no file */
    snprintf(command, sizeof command, "%s render scenes/pond.json --size 1024x1024 -o %s 2>/dev/null", tarn, out);
    status = system(command);
    assert_int_equal(WEXITSTATUS(status), 2);
    assert_int_not_equal(stat(out, &st), 0);
    assert_int_equal(rmdir(dir), 0); /* empty: nothing was left behind */
}

static int run_quiet(const char *command)
{
    int status = system(command);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static size_t file_size(const char *path)
{
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    return (size_t)st.st_size;
}

static int same_file(const char *a, const char *b)
{
    size_t size = file_size(a);
    if (size != file_size(b)) return 0;
    FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
    assert_non_null(fa);
    assert_non_null(fb);
    int same = 1;
    for (size_t k = 0; k < size && same; k++) same = fgetc(fa) == fgetc(fb);
    fclose(fa);
    fclose(fb);
    return same;
}

/* --frames 3 on a scene whose normal maps pan: three numbered files, each different;
 * then a sequence that fails at its second frame leaves none of its frames. */
static void test_binary_writes_a_sequence(void **state)
{
    (void)state;
    const char *tarn = getenv("TARN_BIN");
    if (tarn == NULL) skip();
    char dir[] = "/tmp/tarn-frames-XXXXXX", command[512], frame[3][64];
    assert_non_null(mkdtemp(dir));
    snprintf(command, sizeof command,
             "%s render scenes/effects/normals.json -o %s/out.png --frames 3 --fps 4", tarn, dir);
    assert_int_equal(run_quiet(command), 0);
    for (int k = 0; k < 3; k++) snprintf(frame[k], sizeof frame[k], "%s/out-%04d.png", dir, k);
    assert_false(same_file(frame[0], frame[1]));
    assert_false(same_file(frame[1], frame[2]));
    assert_false(same_file(frame[0], frame[2]));
    char stray[64];
    snprintf(stray, sizeof stray, "%s/out.png", dir);
    assert_int_not_equal(access(stray, F_OK), 0); /* only the numbered frames */
    for (int k = 0; k < 3; k++) assert_int_equal(unlink(frame[k]), 0);

    /* frame 1's name is taken by a directory that cannot be replaced */
    char blocker[80], inside[96];
    snprintf(blocker, sizeof blocker, "%s/out-0001.png", dir);
    snprintf(inside, sizeof inside, "%s/keep", blocker);
    assert_int_equal(mkdir(blocker, 0755), 0);
    FILE *f = fopen(inside, "w");
    assert_non_null(f);
    fclose(f);
    snprintf(command, sizeof command,
             "%s render scenes/effects/normals.json -o %s/out.png --frames 3 2>/dev/null", tarn,
             dir);
    assert_int_equal(run_quiet(command), 2);
    assert_int_not_equal(access(frame[0], F_OK), 0); /* frame 0 was written, then removed */
    assert_int_not_equal(access(frame[2], F_OK), 0);
    assert_int_equal(unlink(inside), 0);
    assert_int_equal(rmdir(blocker), 0);
    assert_int_equal(rmdir(dir), 0); /* empty: nothing else was left behind */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_good_lines_parse),
        cmocka_unit_test(test_bad_lines_name_what_was_expected),
        cmocka_unit_test(test_binary_exits_2_and_writes_nothing),
        cmocka_unit_test(test_static_view_option),
        cmocka_unit_test(test_water_block_option),
        cmocka_unit_test(test_depth_interpolation_option),
        cmocka_unit_test(test_backdrop_option),
        cmocka_unit_test(test_frame_sequences_parse),
        cmocka_unit_test(test_presets_are_the_base_of_the_knobs),
        cmocka_unit_test(test_binary_writes_a_sequence),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
