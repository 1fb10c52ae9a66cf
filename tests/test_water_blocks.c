/* test_water_blocks.c: the quality's water_block 2 and 4, which find the water's
 * effects once per 2x2 or 4x4 block of pixels (tarn_render.h): the image does not
 * depend on the tile size or the cluster bins, it stays close to the image of
 * water_block 1 and to the float reference where the water has no refraction and
 * within 10 dB of it where it refracts (refracted effects are never shared), it
 * changes nothing where there is no water or under the underwater view, and tiles
 * a block does not divide are refused. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "compare.h"
#include "frame_render.h"
#include "reference.h"
#include "scene_load.h"
#include "tarn_internal.h"

/* In place: a loaded scene points into itself. */
static void load(const char *path, tarn_loaded_scene *s)
{
    tarn_error err;
    if (tarn_scene_load(path, s, &err) != 0) fail_msg("%s", err.message);
}

static uint8_t *render(const tarn_loaded_scene *s, const char *path, tarn_quality quality, uint32_t time_ms)
{
    const tarn_frame_config config = {s->width, s->height, quality, time_ms};
    return test_render_rgb(&s->scene, &config, path);
}

static tarn_quality with_block(tarn_preset preset, uint8_t block)
{
    tarn_quality q = tarn_quality_preset(preset);
    q.water_block = block;
    return q;
}

/* Which pixels share a block's effects depends on the triangles alone, so every
 * tile the block divides and the bins on or off draw the same image, with and
 * without refraction, foam and sparkles (found at every pixel), at two times. */
static void test_blocks_do_not_depend_on_the_tile(void **state)
{
    (void)state;
    static const char *const paths[] = {"scenes/pond.json", "scenes/beach.json", "scenes/murky.json",
                                        "scenes/effects/foam.json", "scenes/effects/sparkles.json",
                                        "scenes/effects/refraction.json"};
    static const uint8_t tiles[] = {8, 20, 40, 64};
    for (size_t k = 0; k < sizeof paths / sizeof paths[0]; k++) {
        tarn_loaded_scene s;
        load(paths[k], &s);
        const size_t bytes = 3u * s.width * s.height;
        for (int preset = TARN_PRESET_FAST; preset <= TARN_PRESET_BALANCED; preset++)
            for (uint32_t time_ms = 0; time_ms <= 1500; time_ms += 1500) {
                tarn_quality q = with_block((tarn_preset)preset, time_ms == 0 ? 2 : 4);
                uint8_t *first = render(&s, paths[k], q, time_ms);
                for (size_t t = 0; t < sizeof tiles; t++)
                    for (uint8_t bins = 0; bins <= 1; bins++) {
                        q.tile_size = tiles[t];
                        q.cluster_bins = bins;
                        uint8_t *other = render(&s, paths[k], q, time_ms);
                        if (memcmp(first, other, bytes) != 0)
                            fail_msg("%s, %s: tile %u, bins %u draw another image", paths[k],
                                     tarn_preset_name((tarn_preset)preset), tiles[t], bins);
                        free(other);
                    }
                free(first);
            }
        tarn_scene_free(&s);
    }
}

/* The pond at a preset with water_block 1 and `block`, each against the float
 * reference, and the two against each other. Fails if the blocks share nothing
 * (the images are the same), or a test on them would measure nothing. */
typedef struct {
    double one_db, two_db, between_db; /* PSNR: 1 and the block against the reference, against 1 */
} block_psnr;

static block_psnr pond_with_and_without_blocks(tarn_preset preset, uint32_t time_ms, uint8_t block)
{
    tarn_loaded_scene s;
    load("scenes/pond.json", &s);
    const size_t pixels = (size_t)s.width * s.height;
    const tarn_quality one = with_block(preset, 1), two = with_block(preset, block);
    uint8_t *a = render(&s, "pond", one, time_ms), *b = render(&s, "pond", two, time_ms);
    uint8_t *ref = malloc(3u * pixels);
    tarn_reference_options options = {.subpixel_bits = one.subpixel_bits, .time_ms = time_ms};
    assert_int_equal(tarn_reference_render(&s.scene, s.width, s.height, &options, ref, NULL), 0);
    tarn_compare_metrics to_ref_a, to_ref_b, between;
    tarn_compare_images(a, ref, NULL, NULL, s.width, s.height, &to_ref_a);
    tarn_compare_images(b, ref, NULL, NULL, s.width, s.height, &to_ref_b);
    tarn_compare_images(a, b, NULL, NULL, s.width, s.height, &between);
    assert_true(memcmp(a, b, 3u * pixels) != 0);
    free(a);
    free(b);
    free(ref);
    tarn_scene_free(&s);
    const block_psnr p = {to_ref_a.psnr_db, to_ref_b.psnr_db, between.psnr_db};
    return p;
}

/* Without refraction the blocks move only what varies within two or four pixels:
 * the pond's fast preset stays within 0.3 dB of water_block 1 against the
 * reference with 2x2 blocks and 0.5 dB with 4x4, and both images within 30 dB of
 * water_block 1's. */
static void test_blocks_stay_close_without_refraction(void **state)
{
    (void)state;
    const block_psnr two = pond_with_and_without_blocks(TARN_PRESET_FAST, 1000, 2);
    assert_true(two.two_db > two.one_db - 0.3);
    assert_true(two.between_db > 30.0);
    const block_psnr four = pond_with_and_without_blocks(TARN_PRESET_FAST, 1000, 4);
    print_message("pond, fast: water block 1 %.2f dB, 2 %.2f dB, 4 %.2f dB; 2 and 4 from 1: %.2f and %.2f dB\n",
                  two.one_db, two.two_db, four.two_db, two.between_db, four.between_db);
    assert_true(four.two_db > four.one_db - 0.5);
    assert_true(four.between_db > 30.0);
}

/* Refracted effects are never shared (each pixel's sample moves with its own
 * normal), so with refraction the blocks keep the pond above 30 dB against the
 * reference at the balanced preset (34.8; 49.9 without blocks); shared, the
 * refracted samples took it to about 25. */
static void test_blocks_share_no_refraction(void **state)
{
    (void)state;
    const block_psnr p = pond_with_and_without_blocks(TARN_PRESET_BALANCED, 0, 2);
    assert_true(p.two_db > 30.0);
}

/* A scene without water, and the underwater view (whose displaced pass ignores
 * blocks), draw exactly as with water_block 1. */
static void test_blocks_change_nothing_without_water_pixels(void **state)
{
    (void)state;
    static const char *const paths[] = {"scenes/effects/none.json", "scenes/underwater.json"};
    for (size_t k = 0; k < sizeof paths / sizeof paths[0]; k++) {
        tarn_loaded_scene s;
        load(paths[k], &s);
        tarn_quality one = with_block(TARN_PRESET_FAST, 1), two = with_block(TARN_PRESET_FAST, 2);
        one.tile_size = two.tile_size = 16; /* the underwater view's second buffer */
        uint8_t *a = render(&s, paths[k], one, 700), *b = render(&s, paths[k], two, 700);
        if (memcmp(a, b, 3u * s.width * s.height) != 0) fail_msg("%s: blocks changed the image", paths[k]);
        tarn_frame_config c1 = {s.width, s.height, one, 0}, c2 = {s.width, s.height, two, 0};
        assert_int_equal(tarn_frame_memory_bytes(&c1, &s.scene), tarn_frame_memory_bytes(&c2, &s.scene));
        free(a);
        free(b);
        tarn_scene_free(&s);
    }
}

/* Blocks take a slot per block column of a tile, with water only; a tile the
 * block does not divide (or a block of another size) is refused, by the size
 * function and the frame. */
static void test_block_memory_and_odd_tiles(void **state)
{
    (void)state;
    tarn_loaded_scene s;
    load("scenes/pond.json", &s);
    tarn_frame_config config = {s.width, s.height, with_block(TARN_PRESET_FAST, 1), 0};
    const size_t one = tarn_frame_memory_bytes(&config, &s.scene);
    config.quality.water_block = 2;
    assert_int_equal(tarn_frame_memory_bytes(&config, &s.scene) - one,
                     config.quality.tile_size / 2u * sizeof(tarn_water_block));
    assert_int_equal(sizeof(tarn_water_block), 48u); /* the size tarn_render.h gives */
    config.quality.water_block = 4;
    assert_int_equal(tarn_frame_memory_bytes(&config, &s.scene) - one,
                     config.quality.tile_size / 4u * sizeof(tarn_water_block));
    static const uint8_t bad[][2] = {{2, 41}, {2, 9}, {4, 42}, {0, 40}, {3, 40}, {8, 40}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        config.quality.water_block = bad[k][0];
        config.quality.tile_size = bad[k][1];
        assert_int_equal(tarn_frame_memory_bytes(&config, &s.scene), 0u);
        uint32_t memory[64];
        assert_int_equal(tarn_render_frame(&s.scene, &config, memory, sizeof memory, NULL, NULL), TARN_ERR_CONFIG);
    }
    tarn_scene_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_blocks_do_not_depend_on_the_tile),
        cmocka_unit_test(test_blocks_stay_close_without_refraction),
        cmocka_unit_test(test_blocks_share_no_refraction),
        cmocka_unit_test(test_blocks_change_nothing_without_water_pixels),
        cmocka_unit_test(test_block_memory_and_odd_tiles),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
