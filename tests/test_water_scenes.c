/* test_water_scenes.c: every water scene, and every one-effect scene, against the
 * float reference at default quality: at least 42 dB and 99% of pixels within 2
 * levels, with the reference's own transform (what `tarn compare` prints) and fed
 * the core's snapped triangles (so a failure there is the water arithmetic alone);
 * the one-effect scenes name the effect. And the pond's refraction through the
 * narrow aprons that fit a 16 KB board. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>

#include "compare.h"
#include "core_render.h"
#include "reference.h"
#include "scene_load.h"

static const char *const scenes[] = {
    "scenes/pond.json", "scenes/beach.json", "scenes/murky.json", "scenes/lake.json",
    "scenes/underwater.json", "scenes/effects/fog.json", "scenes/effects/absorption.json",
    "scenes/effects/depth_colour.json", "scenes/effects/ramp.json", "scenes/effects/refraction.json",
    "scenes/effects/normals.json", "scenes/effects/fresnel.json", "scenes/effects/foam.json",
    "scenes/effects/sparkles.json", "scenes/effects/underwater.json",
};

static tarn_compare_metrics compare_at(const char *path, const tarn_quality *quality, uint32_t time_ms, int snapped)
{
    tarn_loaded_scene s;
    tarn_error err;
    if (tarn_scene_load(path, &s, &err) != 0) fail_msg("%s", err.message);
    tarn_frame_config config = {s.width, s.height, *quality, time_ms};
    const size_t pixels = (size_t)s.width * s.height;
    uint8_t *core = malloc(3 * pixels), *ref = malloc(3 * pixels);
    if (tarn_core_render(&s.scene, &config, core, NULL, &err) != 0) fail_msg("%s: %s", path, err.message);
    tarn_reference_options options = {.snapped = snapped, .subpixel_bits = config.quality.subpixel_bits,
                                      .time_ms = time_ms};
    assert_int_equal(tarn_reference_render(&s.scene, s.width, s.height, &options, ref, NULL), 0);
    tarn_compare_metrics m;
    tarn_compare_images(core, ref, NULL, NULL, s.width, s.height, &m);
    free(core);
    free(ref);
    tarn_scene_free(&s);
    return m;
}

static tarn_compare_metrics compare_scene(const char *path, uint32_t time_ms, int snapped)
{
    const tarn_quality quality = tarn_quality_default();
    return compare_at(path, &quality, time_ms, snapped);
}

static void test_every_scene_within_the_bounds(void **state)
{
    (void)state;
    static const uint32_t times[] = {0, 1234};
    for (int snapped = 0; snapped < 2; snapped++)
        for (size_t t = 0; t < 2; t++)
            for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; k++) {
                tarn_compare_metrics m = compare_scene(scenes[k], times[t], snapped);
                print_message("%-34s %-9s t=%-5u psnr=%6.2f over2=%.3f%%\n", scenes[k],
                              snapped ? "snapped" : "unsnapped", times[t], m.psnr_db, 100 * m.share_over2);
                if (m.psnr_db < 42.0 || m.share_over2 > 0.01)
                    fail_msg("%s at %u ms (%s): %.2f dB, %.3f%% of pixels off by more than 2", scenes[k],
                             times[t], snapped ? "snapped" : "unsnapped", m.psnr_db, 100 * m.share_over2);
            }
}

/* The aprons that fit a 16 KB board (docs/firmware.md, "Refraction in 16 KB"),
 * each with the widest tile its RAM leaves, at the fast preset without water
 * blocks: each draws the pond's refraction nearer the reference than the one
 * before, the 12 pixels qemu-m0 bakes over 7 dB nearer than none. */
static void test_narrow_aprons_draw_refraction(void **state)
{
    (void)state;
    static const struct {
        int16_t apron;
        uint16_t tile;
    } aprons[] = {{0, 40}, {4, 24}, {8, 20}, {12, 16}};
    double previous = 0.0, none = 0.0;
    for (size_t k = 0; k < sizeof aprons / sizeof aprons[0]; k++) {
        tarn_quality quality = tarn_quality_preset(TARN_PRESET_FAST);
        quality.water_block = 1;
        quality.refraction_apron = aprons[k].apron;
        quality.tile_size = aprons[k].tile;
        const double db = compare_at("scenes/pond.json", &quality, 0, 0).psnr_db;
        print_message("pond, fast, apron %d, tile %u: %.2f dB\n", aprons[k].apron, aprons[k].tile, db);
        if (k == 0) none = db;
        assert_true(k == 0 || db > previous + 1.0);
        previous = db;
    }
    assert_true(previous > none + 7.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_scene_within_the_bounds),
        cmocka_unit_test(test_narrow_aprons_draw_refraction),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
