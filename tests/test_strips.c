/* test_strips.c: a frame drawn in strips (TARN_FRAME_STRIPS) is the frame drawn in
 * tiles, byte for byte: on every scene that two ways of drawing are tested on and
 * the moving ones, at each preset, two times and three strip heights, one of which
 * leaves a short last strip. The sink takes full-width strips top to bottom (tiles
 * under the underwater view, which strips do not draw), and the memory is the
 * ring tarn_render.h states: 1 + 2 * ceil(apron / rows) strips of opaque pixels. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "frame_render.h"
#include "scene_load.h"

#define WIDTH 160
#define HEIGHT 120

static const char *const moving_scenes[] = {"scenes/pond-orbit.json", "scenes/lake-drift.json"};
static const tarn_preset presets[] = {TARN_PRESET_EXACT, TARN_PRESET_BALANCED, TARN_PRESET_FAST};
static const char *const preset_names[] = {"exact", "balanced", "fast"};

static tarn_loaded_scene *load(const char *path)
{
    tarn_loaded_scene *loaded = malloc(sizeof *loaded);
    assert_non_null(loaded);
    tarn_error err;
    if (tarn_scene_load(path, loaded, &err) != 0) fail_msg("%s", err.message);
    return loaded;
}

static void unload(tarn_loaded_scene *loaded)
{
    tarn_scene_free(loaded);
    free(loaded);
}

static tarn_frame_config config_of(tarn_preset preset, uint32_t time_ms)
{
    tarn_frame_config c;
    c.width = WIDTH;
    c.height = HEIGHT;
    c.quality = tarn_quality_preset(preset);
    c.time_ms = time_ms;
    return c;
}

/* The scene in strips of 8, 16 and 48 rows (48 leaves a last strip of 24) equals
 * its frame in the preset's tiles. */
static void assert_strips_draw_the_tiles_frame(const char *path)
{
    tarn_loaded_scene *loaded = load(path);
    static const uint8_t rows[] = {8, 16, 48};
    static const uint32_t times[] = {0, 1234};
    for (size_t p = 0; p < sizeof presets / sizeof presets[0]; p++)
        for (size_t t = 0; t < sizeof times / sizeof times[0]; t++) {
            tarn_frame_config config = config_of(presets[p], times[t]);
            uint8_t *tiles = test_render_rgb(&loaded->scene, &config, path);
            config.quality.frame_shape = TARN_FRAME_STRIPS;
            for (size_t r = 0; r < sizeof rows; r++) {
                config.quality.tile_size = rows[r];
                uint8_t *strips = test_render_rgb(&loaded->scene, &config, path);
                if (memcmp(tiles, strips, 3u * WIDTH * HEIGHT) != 0)
                    fail_msg("%s (%s, %u ms): strips of %u rows draw another frame than tiles", path,
                             preset_names[p], (unsigned)times[t], (unsigned)rows[r]);
                free(strips);
            }
            free(tiles);
        }
    unload(loaded);
}

static void test_strips_draw_the_frame_tiles_draw(void **state)
{
    (void)state;
    for (size_t i = 0; i < TEST_FRAME_SCENE_COUNT; i++) assert_strips_draw_the_tiles_frame(test_frame_scenes[i]);
    for (size_t i = 0; i < sizeof moving_scenes / sizeof moving_scenes[0]; i++)
        assert_strips_draw_the_tiles_frame(moving_scenes[i]);
}

typedef struct {
    int32_t next_y;       /* the row the next strip must start at */
    uint32_t pieces;
    uint32_t widest;
    int out_of_order;
} piece_log;

static int log_piece(void *user, const tarn_tile *tile)
{
    piece_log *log = user;
    if (tile->x == 0 && tile->width == WIDTH && tile->y == log->next_y) log->next_y += tile->height;
    else log->out_of_order = 1;
    if (tile->width > log->widest) log->widest = tile->width;
    log->pieces++;
    return 0;
}

static piece_log pieces_of(const tarn_scene *scene, const tarn_frame_config *config)
{
    const size_t bytes = tarn_frame_memory_bytes(config, scene);
    void *memory = malloc(bytes);
    assert_non_null(memory);
    piece_log log = {0, 0u, 0u, 0};
    assert_int_equal(tarn_render_frame(scene, config, memory, bytes, log_piece, &log), TARN_OK);
    free(memory);
    return log;
}

/* Strips reach the sink full width, top to bottom, each row once; the underwater
 * view is drawn in tiles of the strip's rows instead. */
static void test_strips_reach_the_sink_top_to_bottom(void **state)
{
    (void)state;
    tarn_loaded_scene *pond = load("scenes/pond.json");
    tarn_frame_config config = config_of(TARN_PRESET_BALANCED, 0);
    config.quality.frame_shape = TARN_FRAME_STRIPS;
    config.quality.tile_size = 48;
    const piece_log log = pieces_of(&pond->scene, &config);
    assert_false(log.out_of_order);
    assert_int_equal(log.next_y, HEIGHT);
    assert_int_equal(log.pieces, 3u); /* 48, 48 and 24 rows */
    unload(pond);

    tarn_loaded_scene *under = load("scenes/underwater.json");
    const piece_log tiles = pieces_of(&under->scene, &config);
    assert_int_equal(tiles.widest, 48u);
    assert_int_equal(tiles.pieces, 4u * 3u); /* 160x120 in 48-pixel tiles */
    unload(under);
}

/* What a ring of strips costs: without refraction one strip of opaque pixels and
 * the in-place water's two rows; with it, as many more strips above and below as
 * the apron reaches, and a strip for the water pass's copy. */
static void test_strips_keep_a_ring_as_deep_as_the_apron(void **state)
{
    (void)state;
    tarn_loaded_scene *pond = load("scenes/pond.json");
    tarn_frame_config config = config_of(TARN_PRESET_EXACT, 0);
    config.quality.frame_shape = TARN_FRAME_STRIPS;
    const size_t pixel_bytes = 4u + config.quality.depth_bits / 8u;
    const int32_t apron = tarn_frame_apron_pixels(&pond->scene, &config);
    assert_true(apron > 0);
    static const uint8_t rows[] = {8, 16, 48};
    for (size_t r = 0; r < sizeof rows; r++) {
        config.quality.tile_size = rows[r];
        tarn_frame_config flat = config;
        flat.quality.refraction_apron = 0;
        const size_t ring_strips = 1u + 2u * (((size_t)apron + rows[r] - 1u) / rows[r]);
        const size_t expected = (size_t)WIDTH * pixel_bytes * ((ring_strips - 1u) * rows[r] + (rows[r] - 2u));
        const size_t more = tarn_frame_memory_bytes(&config, &pond->scene) -
                            tarn_frame_memory_bytes(&flat, &pond->scene);
        if (more != expected)
            fail_msg("strips of %u rows, apron %d: refraction adds %zu bytes, expected %zu", (unsigned)rows[r],
                     (int)apron, more, expected);
        assert_int_equal(test_render_status(&pond->scene, &config), TARN_OK);
    }
    unload(pond);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_strips_draw_the_frame_tiles_draw),
        cmocka_unit_test(test_strips_reach_the_sink_top_to_bottom),
        cmocka_unit_test(test_strips_keep_a_ring_as_deep_as_the_apron),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
