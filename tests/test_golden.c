/* test_golden.c: the core's frames, byte for byte, against checksums recorded in
 * tests/golden/frames.txt: every scene at every preset and two times, the knobs one
 * at a time on the scenes that exercise them, and the backdrops. A change that is
 * meant to move pixels re-records the file (`make golden`) and says so in its
 * commit; any other change, a refactoring above all, must leave every line as it is.
 *
 * The checksum is core/include/tarn/tarn_checksum.h's, the number the boards report: a frame
 * differs from the recorded one when any pixel's RGB888 value does. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "backdrop.h"
#include "frame_render.h"
#include "image_checksum.h"
#include "scene_load.h"

#define GOLDEN_PATH "tests/golden/frames.txt"

static const char *const scenes[] = {
    "scenes/pond.json", "scenes/beach.json", "scenes/murky.json", "scenes/lake.json", "scenes/underwater.json",
    "scenes/effects/absorption.json", "scenes/effects/depth_colour.json", "scenes/effects/foam.json",
    "scenes/effects/fog.json", "scenes/effects/fresnel.json", "scenes/effects/none.json",
    "scenes/effects/normals.json", "scenes/effects/ramp.json", "scenes/effects/refraction.json",
    "scenes/effects/sparkles.json", "scenes/effects/underwater.json", "scenes/extremes/dense.json",
    "scenes/extremes/far.json", "scenes/extremes/grazing.json", "scenes/extremes/huge.json",
    "scenes/extremes/steep.json", "scenes/extremes/tiny.json", "scenes/extremes/deep-squared.json",
    "scenes/extremes/huge-near.json", "scenes/extremes/uv-scale.json", "scenes/extremes/skim-above.json",
    "scenes/extremes/skim-below.json", "scenes/pond-orbit.json", "scenes/lake-drift.json",
};

/* The scenes whose water reaches every knob: refraction, foam, sparkles, the
 * underwater view. */
static const char *const knob_scenes[] = {"scenes/pond.json", "scenes/beach.json", "scenes/murky.json",
                                          "scenes/underwater.json"};

typedef struct {
    const char *name; /* as the golden file names it */
    void (*apply)(tarn_quality *q);
} knob;

static void affine(tarn_quality *q) { q->perspective = TARN_PERSPECTIVE_AFFINE; }
static void span8(tarn_quality *q) { q->perspective = TARN_PERSPECTIVE_SPAN; q->perspective_span = 8; }
static void pixel(tarn_quality *q) { q->perspective = TARN_PERSPECTIVE_PIXEL; }
static void depth16(tarn_quality *q) { q->depth_bits = 16; }
static void depth32(tarn_quality *q) { q->depth_bits = 32; }
static void plane_depth(tarn_quality *q) { q->depth_interpolation = TARN_DEPTH_PLANE; }
static void block1(tarn_quality *q) { q->water_block = 1; }
static void block2(tarn_quality *q) { q->water_block = 2; }
static void block4(tarn_quality *q) { q->water_block = 4; }
static void apron_off(tarn_quality *q) { q->refraction_apron = 0; }
static void apron4(tarn_quality *q) { q->refraction_apron = 4; }
static void bins_off(tarn_quality *q) { q->cluster_bins = 0; }
static void recip0(tarn_quality *q) { q->recip_newton_steps = 0; }
static void exp2_nearest(tarn_quality *q) { q->exp2.entries = 16; q->exp2.interpolate = 0; }
static void fog_bits4(tarn_quality *q) { q->fog_argument_bits = 4; }
static void subpixel2(tarn_quality *q) { q->subpixel_bits = 2; }
static void tile8(tarn_quality *q) { q->tile_size = 8; }

static const knob knobs[] = {
    {"affine", affine},       {"span:8", span8},        {"pixel", pixel},
    {"depth16", depth16},     {"depth32", depth32},     {"depth-plane", plane_depth},
    {"block1", block1},       {"block2", block2},       {"block4", block4},
    {"apron-off", apron_off}, {"apron4", apron4},       {"bins-off", bins_off},
    {"recip0", recip0},       {"exp2:16:nearest", exp2_nearest}, {"fog-bits4", fog_bits4},
    {"subpixel2", subpixel2}, {"tile8", tile8},
};

static const uint32_t times_ms[] = {0, 1500};
/* scenes/extremes/late.json also at 2^31 ms and at the last millisecond before the
 * clock wraps (its maps and foam pan at the loader's fastest speeds) */
static const char late_scene[] = "scenes/extremes/late.json";
static const uint32_t late_times_ms[] = {0, 1500, 2147483648u, UINT32_MAX};

/* The frames this suite checks, as lines of the golden file, and their checksums. */
typedef struct {
    char **lines;
    size_t count, capacity;
} frame_list;

static void add_line(frame_list *l, const char *scene, const char *quality, uint32_t time_ms, uint32_t sum)
{
    if (l->count == l->capacity) {
        l->capacity = l->capacity ? 2 * l->capacity : 256;
        l->lines = realloc(l->lines, l->capacity * sizeof *l->lines);
        assert_non_null(l->lines);
    }
    char line[256];
    snprintf(line, sizeof line, "%s %s %u %08x", scene, quality, (unsigned)time_ms, (unsigned)sum);
    l->lines[l->count] = strdup(line);
    assert_non_null(l->lines[l->count]);
    l->count++;
}

static uint32_t frame_checksum(const tarn_scene *scene, const tarn_frame_config *config, const char *path)
{
    uint8_t *rgb = test_render_rgb(scene, config, path);
    const uint32_t sum = tarn_image_checksum(rgb, config->width, config->height);
    free(rgb);
    return sum;
}

static void load(const char *path, tarn_loaded_scene *s)
{
    tarn_error err;
    if (tarn_scene_load(path, s, &err) != 0) fail_msg("%s", err.message);
}

static void add_presets(frame_list *l, const char *path, const uint32_t *times, size_t time_count)
{
    tarn_loaded_scene s;
    load(path, &s);
    for (int p = 0; p < TARN_PRESET_COUNT; p++)
        for (size_t t = 0; t < time_count; t++) {
            const tarn_frame_config config = {s.width, s.height, tarn_quality_preset((tarn_preset)p), times[t]};
            add_line(l, path, tarn_preset_name((tarn_preset)p), times[t], frame_checksum(&s.scene, &config, path));
        }
    tarn_scene_free(&s);
}

static void add_knobs(frame_list *l, const char *path)
{
    tarn_loaded_scene s;
    load(path, &s);
    for (size_t k = 0; k < sizeof knobs / sizeof knobs[0]; k++) {
        tarn_frame_config config = {s.width, s.height, tarn_quality_default(), 1500};
        knobs[k].apply(&config.quality);
        char name[64];
        snprintf(name, sizeof name, "balanced+%s", knobs[k].name);
        add_line(l, path, name, config.time_ms, frame_checksum(&s.scene, &config, path));
    }
    tarn_scene_free(&s);
}

/* The scene drawn at one quality, named as the golden file names it. */
static void add_quality(frame_list *l, const char *path, const char *quality_name, tarn_quality quality)
{
    tarn_loaded_scene s;
    load(path, &s);
    const tarn_frame_config config = {s.width, s.height, quality, 1500};
    add_line(l, path, quality_name, config.time_ms, frame_checksum(&s.scene, &config, path));
    tarn_scene_free(&s);
}

/* The scene drawn over a backdrop of `kind`, as tarn render --backdrop draws it. */
static void add_backdrop(frame_list *l, const char *path, tarn_backdrop_kind kind, const char *quality_name,
                         tarn_quality quality)
{
    tarn_loaded_scene s;
    load(path, &s);
    const tarn_frame_config config = {s.width, s.height, quality, 1500};
    tarn_backdrop_scene backdrop;
    tarn_error err;
    if (tarn_backdrop_scene_make(&s.scene, &config, tarn_backdrop_of(kind), 0, &backdrop, &err) != 0)
        fail_msg("%s: %s", path, err.message);
    add_line(l, path, quality_name, config.time_ms, frame_checksum(&backdrop.water.scene, &config, path));
    tarn_backdrop_scene_free(&backdrop);
    tarn_scene_free(&s);
}

static void measure_all(frame_list *l)
{
    for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; k++)
        add_presets(l, scenes[k], times_ms, sizeof times_ms / sizeof times_ms[0]);
    add_presets(l, late_scene, late_times_ms, sizeof late_times_ms / sizeof late_times_ms[0]);
    for (size_t k = 0; k < sizeof knob_scenes / sizeof knob_scenes[0]; k++) add_knobs(l, knob_scenes[k]);
    tarn_quality fast_still = tarn_quality_preset(TARN_PRESET_FAST);
    fast_still.water_block = 4;
    fast_still.water_coordinates = TARN_WATER_UV_PLANE; /* still water's, always */
    add_backdrop(l, "scenes/pond.json", TARN_BACKDROP_OPAQUE, "fast+backdrop-on", tarn_quality_preset(TARN_PRESET_FAST));
    add_backdrop(l, "scenes/pond.json", TARN_BACKDROP_STILL, "fast+block4+backdrop-still", fast_still);
    add_backdrop(l, "scenes/beach.json", TARN_BACKDROP_OPAQUE, "balanced+backdrop-on", tarn_quality_default());
    /* refraction on the 16 KB boards: read from the still picture, and from a
     * narrow apron around small tiles (the qemu-m0 boards' board.mk) */
    tarn_quality refracting = fast_still;
    refracting.refraction_apron = TARN_APRON_FULL;
    add_backdrop(l, "scenes/pond.json", TARN_BACKDROP_STILL, "fast+block4+apron-on+backdrop-still", refracting);
    refracting = tarn_quality_preset(TARN_PRESET_FAST);
    refracting.refraction_apron = 12;
    refracting.tile_size = 16;
    refracting.water_block = 1;
    add_quality(l, "scenes/pond.json", "fast+apron12+tile16+block1", refracting);
}

static void free_list(frame_list *l)
{
    for (size_t k = 0; k < l->count; k++) free(l->lines[k]);
    free(l->lines);
}

/* TARN_GOLDEN_RECORD=1 (make golden) writes the file instead of checking it. */
static void record(const frame_list *l)
{
    FILE *f = fopen(GOLDEN_PATH, "w");
    if (f == NULL) fail_msg("cannot write %s", GOLDEN_PATH);
    fprintf(f, "# scene quality time_ms checksum: written by make golden (tests/test_golden.c)\n");
    for (size_t k = 0; k < l->count; k++) fprintf(f, "%s\n", l->lines[k]);
    if (fclose(f) != 0) fail_msg("cannot write %s", GOLDEN_PATH);
    print_message("recorded %zu frames in %s\n", l->count, GOLDEN_PATH);
}

/* Every frame's line equals the recorded one, and the file holds no other. */
static void test_frames_are_the_recorded_bytes(void **state)
{
    (void)state;
    frame_list measured = {NULL, 0, 0};
    measure_all(&measured);
    const char *mode = getenv("TARN_GOLDEN_RECORD");
    if (mode != NULL && strcmp(mode, "1") == 0) {
        record(&measured);
        free_list(&measured);
        return;
    }
    FILE *f = fopen(GOLDEN_PATH, "r");
    if (f == NULL) fail_msg("cannot read %s (make golden writes it)", GOLDEN_PATH);
    char line[256];
    size_t k = 0, differing = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        if (line[0] == '#') continue;
        line[strcspn(line, "\n")] = '\0';
        if (k >= measured.count) {
            print_error("%s holds a frame this suite no longer draws: %s\n", GOLDEN_PATH, line);
            differing++;
        } else if (strcmp(line, measured.lines[k]) != 0) {
            print_error("recorded: %s\n   drawn: %s\n", line, measured.lines[k]);
            differing++;
        }
        k++;
    }
    fclose(f);
    for (; k < measured.count; k++, differing++)
        print_error("%s lacks a frame this suite draws: %s\n", GOLDEN_PATH, measured.lines[k]);
    const size_t total = measured.count;
    free_list(&measured);
    if (differing != 0)
        fail_msg("%zu of %zu frames differ from %s: the core draws other bytes", differing, total, GOLDEN_PATH);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_frames_are_the_recorded_bytes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
