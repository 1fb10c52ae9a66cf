/* test_refraction_aprons.c: the pond's refraction through the narrow aprons that
 * fit a 16 KB board (docs/firmware.md, "Refraction in 16 KB"), each with the widest
 * tile its RAM leaves, at the fast preset without water blocks: each draws nearer
 * the reference than the one before (tarn compare's shading PSNR), the 12 pixels
 * qemu-m0 bakes over 7 dB nearer than none. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>

#include "core_render.h"
#include "scene_load.h"
#include "yardstick.h"

static double shading_psnr(const tarn_loaded_scene *s, const tarn_continuous_reference *reference,
                         const tarn_quality *quality)
{
    tarn_error err;
    const tarn_frame_config config = {s->width, s->height, *quality, 0};
    uint8_t *rgb = malloc(3u * s->width * s->height);
    assert_non_null(rgb);
    tarn_yardstick y;
    if (tarn_core_render(&s->scene, &config, rgb, NULL, &err) != 0 ||
        tarn_yardstick_measure(&s->scene, s->name, &config, rgb, reference, &y, NULL, &err) != 0)
        fail_msg("%s", err.message);
    free(rgb);
    return y.shading.psnr_db;
}

static void test_narrow_aprons_draw_refraction(void **state)
{
    (void)state;
    static const struct {
        int16_t apron;
        uint16_t tile;
    } aprons[] = {{0, 40}, {4, 24}, {8, 20}, {12, 16}};
    tarn_loaded_scene s;
    tarn_error err;
    if (tarn_scene_load("scenes/pond.json", &s, &err) != 0) fail_msg("%s", err.message);
    tarn_continuous_reference reference;
    if (tarn_continuous_reference_render(&s.scene, s.name, s.width, s.height, 0, &reference, &err) != 0)
        fail_msg("%s", err.message);
    double previous = 0.0, none = 0.0;
    for (size_t k = 0; k < sizeof aprons / sizeof aprons[0]; k++) {
        tarn_quality quality = tarn_quality_preset(TARN_PRESET_FAST);
        quality.water_block = 1;
        quality.refraction_apron = aprons[k].apron;
        quality.tile_size = aprons[k].tile;
        const double db = shading_psnr(&s, &reference, &quality);
        print_message("pond, fast, apron %d, tile %u: %.2f dB\n", aprons[k].apron, aprons[k].tile, db);
        if (k == 0) none = db;
        if (k > 0 && db <= previous + 1.0)
            fail_msg("apron %d draws %.2f dB, not 1 dB above the narrower one's %.2f", aprons[k].apron, db, previous);
        previous = db;
    }
    if (previous <= none + 7.0) fail_msg("the 12-pixel apron draws %.2f dB, not 7 dB above none's %.2f", previous, none);
    tarn_continuous_reference_free(&reference);
    tarn_scene_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_narrow_aprons_draw_refraction),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
