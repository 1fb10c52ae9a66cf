/* test_checksum.c: the frame checksum of core/include/tarn/tarn_checksum.h does not depend on the
 * tile size, equals the host's sum over a whole image, and notices one flipped bit. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "core_render.h"
#include "image_checksum.h"
#include "scene_load.h"
#include "tarn/tarn_checksum.h"

#define WIDTH 120
#define HEIGHT 90

/* The definition in tarn_checksum.h, written out again. */
static uint32_t pixel_term(uint32_t x, uint32_t y, uint32_t rgb)
{
    uint32_t h = (x * 0x9E3779B1u) ^ (y * 0x85EBCA77u) ^ (rgb & 0xFFFFFFu);
    h ^= h >> 16;
    h *= 0x85EBCA6Bu;
    h ^= h >> 13;
    h *= 0xC2B2AE35u;
    return h ^ (h >> 16);
}

static void test_pixel_term_is_the_stated_hash(void **state)
{
    (void)state;
    static const uint32_t values[][3] = {{0, 0, 0},         {1, 0, 0},        {0, 1, 0},
                                         {0, 0, 1},         {239, 239, 0xFFFFFF}, {17, 200, 0x123456},
                                         {1023, 1023, 0x808080}, {5, 7, 0xFF000000u}};
    for (size_t i = 0; i < sizeof values / sizeof values[0]; i++)
        assert_int_equal(tarn_checksum_pixel(values[i][0], values[i][1], values[i][2]),
                         pixel_term(values[i][0], values[i][1], values[i][2]));
    assert_int_equal(tarn_checksum_pixel(0, 0, 0), 0); /* fmix32(0) */
    assert_int_equal(tarn_checksum_pixel(5, 7, 0xAB123456u), tarn_checksum_pixel(5, 7, 0x123456u));
}

static int sum_tiles(void *user, const tarn_tile *tile)
{
    uint32_t *sum = user;
    *sum = tarn_checksum_tile(*sum, tile);
    return 0;
}

static uint32_t render_checksum(const tarn_scene *scene, tarn_frame_config config, uint8_t tile_size)
{
    config.quality.tile_size = tile_size;
    size_t bytes = tarn_frame_memory_bytes(&config, scene);
    assert_true(bytes > 0);
    void *memory = malloc(bytes);
    assert_non_null(memory);
    uint32_t sum = 0;
    assert_int_equal(tarn_render_frame(scene, &config, memory, bytes, sum_tiles, &sum), TARN_OK);
    free(memory);
    return sum;
}

/* The pond at tiles of 16 and 32 (and an odd 13), as tiles arrive, and the host's
 * sum over the whole image: one number. */
static void test_same_frame_same_sum_at_any_tile_size(void **state)
{
    (void)state;
    tarn_loaded_scene scene;
    tarn_error err;
    if (tarn_scene_load("scenes/pond.json", &scene, &err) != 0) fail_msg("%s", err.message);
    tarn_frame_config config = {WIDTH, HEIGHT, tarn_quality_default(), 1000};
    config.quality.refraction_apron = 0;
    uint32_t at16 = render_checksum(&scene.scene, config, 16);
    uint32_t at32 = render_checksum(&scene.scene, config, 32);
    uint32_t at13 = render_checksum(&scene.scene, config, 13);
    uint8_t *rgb = malloc(3u * WIDTH * HEIGHT);
    assert_non_null(rgb);
    config.quality.tile_size = 28;
    if (tarn_core_render(&scene.scene, &config, rgb, NULL, &err) != 0) fail_msg("%s", err.message);
    uint32_t whole = tarn_image_checksum(rgb, WIDTH, HEIGHT);
    print_message("pond %dx%d at 1000 ms: tiles 16 %08x, 32 %08x, 13 %08x, whole image %08x\n", WIDTH,
                  HEIGHT, at16, at32, at13, whole);
    assert_int_equal(at16, at32);
    assert_int_equal(at16, at13);
    assert_int_equal(at16, whole);
    /* another time is another picture, and another sum */
    config.time_ms = 0;
    assert_int_not_equal(render_checksum(&scene.scene, config, 16), at16);
    free(rgb);
    tarn_scene_free(&scene);
}

/* Every bit of a pixel's colour, at a few positions of a frame of noise: flipping
 * it changes the sum. */
static void test_one_bit_changes_the_sum(void **state)
{
    (void)state;
    enum { W = 40, H = 30 };
    static uint32_t rgb[W * H];
    uint32_t seed = 7;
    for (size_t i = 0; i < W * H; i++) {
        seed = seed * 1664525u + 1013904223u;
        rgb[i] = seed >> 8;
    }
    tarn_tile tile = {0, 0, W, H, rgb, NULL, W, 16};
    const uint32_t sum = tarn_checksum_tile(0, &tile);
    static const uint32_t positions[][2] = {{0, 0}, {W - 1, 0}, {0, H - 1}, {W - 1, H - 1}, {17, 11}};
    for (size_t p = 0; p < sizeof positions / sizeof positions[0]; p++)
        for (uint32_t bit = 0; bit < 24; bit++) {
            uint32_t *pixel = &rgb[positions[p][1] * W + positions[p][0]];
            *pixel ^= 1u << bit;
            assert_int_not_equal(tarn_checksum_tile(0, &tile), sum);
            *pixel ^= 1u << bit;
        }
    assert_int_equal(tarn_checksum_tile(0, &tile), sum);
    /* two pixels swapped: the position is in the hash */
    uint32_t t = rgb[3];
    rgb[3] = rgb[4];
    rgb[4] = t;
    assert_int_not_equal(tarn_checksum_tile(0, &tile), sum);
    /* a tile placed elsewhere in the frame sums its pixels at their frame positions */
    tarn_tile part = {8, 4, 16, 8, rgb + 4 * W + 8, NULL, W, 16};
    uint32_t expected = 0;
    for (uint32_t y = 4; y < 12; y++)
        for (uint32_t x = 8; x < 24; x++) expected += pixel_term(x, y, rgb[y * W + x]);
    assert_int_equal(tarn_checksum_tile(5, &part), expected + 5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pixel_term_is_the_stated_hash),
        cmocka_unit_test(test_same_frame_same_sum_at_any_tile_size),
        cmocka_unit_test(test_one_bit_changes_the_sum),
    };
    return cmocka_run_group_tests_name("checksum", tests, NULL, NULL);
}
