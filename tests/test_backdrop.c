/* test_backdrop.c: a scene's water drawn over the backdrop of its opaque objects
 * (tarn_scene.h, host/bake/backdrop.h), without its triangles that draw no pixel
 * (host/bake/water_cull.h), gives the frame the whole scene gives, byte for byte, with
 * refracted samples read from the picture and no apron drawn: on every scene, at each preset and two times, and with the knobs that move what the
 * water reads (aprons, blocks, tiles, depth, perspective). The backdrop
 * keeps the depth only around the water, in as few colours' bits as it can; a frame
 * it does not apply to, a malformed backdrop and a picture of more colours than
 * 16-bit indices name are refused. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "backdrop.h"
#include "frame_render.h"
#include "scene_builder.h"
#include "scene_load.h"

/* In place: the scene points into its own struct (its underwater view). */
static void load(const char *path, tarn_loaded_scene *loaded)
{
    tarn_error err;
    if (tarn_scene_load(path, loaded, &err) != 0) fail_msg("%s", err.message);
}

static void backdrop_make(const tarn_loaded_scene *loaded, const tarn_frame_config *config, tarn_backdrop_scene *b)
{
    tarn_error err;
    if (tarn_backdrop_scene_make(&loaded->scene, config, tarn_backdrop_of(TARN_BACKDROP_OPAQUE), 0, b, &err) != 0) fail_msg("%s", err.message);
}

/* The frame at `config` of the scene as loaded, and of its water over the backdrop
 * made for that frame, at each time: equal. */
static void assert_same_frames(const char *path, tarn_frame_config config, const char *knobs)
{
    tarn_loaded_scene loaded;
    load(path, &loaded);
    tarn_backdrop_scene b;
    backdrop_make(&loaded, &config, &b);
    static const uint32_t times[] = {0, 1750};
    for (size_t t = 0; t < 2; t++) {
        config.time_ms = times[t];
        uint8_t *whole = test_render_rgb(&loaded.scene, &config, path);
        uint8_t *over = test_render_rgb(&b.water.scene, &config, "over the backdrop");
        if (memcmp(whole, over, 3u * config.width * config.height) != 0)
            fail_msg("%s (%s, %u ms): the backdrop changes the frame", path, knobs, (unsigned)config.time_ms);
        /* refracted samples read the picture in flash: no apron is drawn around a
         * tile, so the frame over its backdrop needs no more memory than one without
         * refraction drawn whole (the underwater view keeps its apron) */
        tarn_frame_config no_apron = config;
        no_apron.quality.refraction_apron = 0;
        if (loaded.scene.underwater == NULL &&
            tarn_frame_memory_bytes(&config, &b.water.scene) > tarn_frame_memory_bytes(&no_apron, &loaded.scene))
            fail_msg("%s (%s): %zu bytes over the backdrop, %zu drawn whole without an apron", path, knobs,
                     tarn_frame_memory_bytes(&config, &b.water.scene),
                     tarn_frame_memory_bytes(&no_apron, &loaded.scene));
        free(whole);
        free(over);
    }
    tarn_backdrop_scene_free(&b);
    tarn_scene_free(&loaded);
}

static tarn_frame_config scene_config(const char *path, tarn_preset preset)
{
    tarn_loaded_scene loaded;
    load(path, &loaded);
    const tarn_frame_config config = {loaded.width, loaded.height, tarn_quality_preset(preset), 0};
    tarn_scene_free(&loaded);
    return config;
}

static void test_every_scene_draws_the_same_frame(void **state)
{
    (void)state;
    for (size_t k = 0; k < TEST_FRAME_SCENE_COUNT; k++)
        for (int preset = 0; preset < TARN_PRESET_COUNT; preset++) {
            const char *path = test_frame_scenes[k];
            assert_same_frames(path, scene_config(path, (tarn_preset)preset), tarn_preset_name(preset));
        }
}

/* The knobs that change where the water reads the opaque pass, or how. */
static void test_every_knob_draws_the_same_frame(void **state)
{
    (void)state;
    static const char *const paths[] = {"scenes/pond.json", "scenes/beach.json", "scenes/effects/refraction.json"};
    for (size_t k = 0; k < sizeof paths / sizeof paths[0]; k++) {
        tarn_frame_config c = scene_config(paths[k], TARN_PRESET_BALANCED);
        c.quality.refraction_apron = 4;
        c.quality.tile_size = 16;
        assert_same_frames(paths[k], c, "apron 4, tile 16");
        c.quality.refraction_apron = 2;
        c.quality.tile_size = 8;
        assert_same_frames(paths[k], c, "apron 2, tile 8");
        c = scene_config(paths[k], TARN_PRESET_FAST);
        c.quality.depth_bits = 32;
        c.quality.water_block = 1;
        assert_same_frames(paths[k], c, "fast, depth 32, water block 1");
        c.quality.perspective = TARN_PERSPECTIVE_AFFINE;
        c.quality.cluster_bins = 0;
        c.quality.tile_size = 24;
        assert_same_frames(paths[k], c, "affine, no bins, tile 24");
        c.width = 160;
        c.height = 120;
        assert_same_frames(paths[k], c, "160x120");
    }
}

/* The pond at the fast preset, and its water over the backdrop made for that
 * frame; made in place, since both point into themselves. */
typedef struct {
    tarn_frame_config config;
    tarn_loaded_scene loaded;
    tarn_backdrop_scene b;
} pond_backdrop;

static void pond_backdrop_make(pond_backdrop *p)
{
    p->config = scene_config("scenes/pond.json", TARN_PRESET_FAST);
    load("scenes/pond.json", &p->loaded);
    backdrop_make(&p->loaded, &p->config, &p->b);
}

static void pond_backdrop_free(pond_backdrop *p)
{
    tarn_backdrop_scene_free(&p->b);
    tarn_scene_free(&p->loaded);
}

/* Only water objects are left to draw, and only their triangles that draw a pixel;
 * the pond's 5,719 colours take 13 bits; the depth is kept in the rows the water
 * covers, not beyond. */
static void test_backdrop_keeps_what_the_water_reads(void **state)
{
    (void)state;
    static pond_backdrop pond;
    pond_backdrop_make(&pond);
    tarn_backdrop_scene *b = &pond.b;
    assert_int_equal(b->water.scene.object_count, 1);
    assert_non_null(b->water.scene.objects[0].material->water);
    const tarn_backdrop *backdrop = b->water.scene.static_view->backdrop;
    assert_ptr_equal(backdrop, &b->image.backdrop);
    assert_int_equal(backdrop->index_bits, 13);
    assert_int_equal(backdrop->palette_count, 5719); /* not padded to 8,192 */
    assert_int_equal(b->image.colour_words, 240u * 240u * 13u / 16u);
    assert_int_equal(backdrop->row_spans[1] - backdrop->row_spans[0], 0); /* the sky */
    assert_int_equal(backdrop->row_spans[240] - backdrop->row_spans[239], 0); /* the near shore */
    /* one span a row around the water */
    for (uint32_t j = 0; j < 240; j++) assert_true(backdrop->row_spans[j + 1] <= backdrop->row_spans[j] + 1u);
    assert_true(backdrop->depth_count > 20000u && backdrop->depth_count < 240u * 240u / 2u);
    /* the water plane's triangles under the rim and near the camera draw nothing */
    assert_int_equal(b->cull.triangles_before, 288);
    assert_int_equal(b->cull.triangles_after, 127);
    assert_int_equal(b->water.scene.objects[0].mesh->triangle_count, 127);
    pond_backdrop_free(&pond);
}

/* A frame the backdrop was not drawn for has no opaque objects to draw: refused. */
static void test_another_frame_is_refused(void **state)
{
    (void)state;
    static pond_backdrop pond;
    pond_backdrop_make(&pond);
    const tarn_frame_config config = pond.config;
    tarn_backdrop_scene *b = &pond.b;
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_OK);
    tarn_frame_config other = config;
    other.width = 200;
    assert_int_equal(test_render_status(&b->water.scene, &other), TARN_ERR_SCENE);
    other = config;
    other.quality.depth_bits = 32;
    assert_int_equal(test_render_status(&b->water.scene, &other), TARN_ERR_SCENE);
    other = config;
    other.quality.perspective = TARN_PERSPECTIVE_PIXEL;
    assert_int_equal(test_render_status(&b->water.scene, &other), TARN_ERR_SCENE);
    other = config; /* knobs that leave the opaque pixels alone */
    other.quality.tile_size = 16;
    other.quality.water_block = 1;
    other.quality.exp2.entries = 64;
    assert_int_equal(test_render_status(&b->water.scene, &other), TARN_OK);
    tarn_scene moved = b->water.scene;
    moved.camera.position.y += 65536;
    assert_int_equal(test_render_status(&moved, &config), TARN_ERR_SCENE);
    pond_backdrop_free(&pond);
}

/* Each malformed field is refused before a tile is drawn: a palette longer than
 * its indices can spell, or empty, too. */
static void test_malformed_backdrop_is_refused(void **state)
{
    (void)state;
    static pond_backdrop pond;
    pond_backdrop_make(&pond);
    const tarn_frame_config config = pond.config;
    tarn_backdrop_scene *b = &pond.b;
    tarn_backdrop *backdrop = &b->image.backdrop;
    const tarn_backdrop saved = *backdrop;
    backdrop->index_bits = 12; /* 4,096 indices for 5,719 colours */
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    *backdrop = saved;
    backdrop->index_bits = 17;
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    *backdrop = saved;
    backdrop->palette_count = 0;
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    *backdrop = saved;
    backdrop->palette = NULL;
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    *backdrop = saved;
    const uint32_t last = b->image.palette[5718];
    b->image.palette[5718] = 0x01000000u; /* a bit the water pass marks pixels with */
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    b->image.palette[5718] = last;
    backdrop->depth_count -= 1u; /* the last span now reads past it */
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    *backdrop = saved;
    backdrop->span_count -= 1u; /* the last row's spans end past it */
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    *backdrop = saved;
    tarn_backdrop_span *span = &b->image.spans[b->image.row_spans[120]];
    const tarn_backdrop_span kept = *span;
    span->x1 = 241; /* past the frame */
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    *span = kept;
    span->x0 = span->x1; /* empty */
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    *span = kept;
    b->image.row_spans[121]++; /* row 121's span counted in row 120, after one it overlaps */
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    b->image.row_spans[121]--;
    const uint16_t first = b->image.row_spans[120];
    b->image.row_spans[120] = (uint16_t)(first + 2u); /* past the next row's first */
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    b->image.row_spans[120] = first;
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_OK);
    pond_backdrop_free(&pond);
}

/* A pixel's index past the palette's end reads its last colour: a palette cut to
 * one colour draws that colour wherever no water does, and reads nothing past it
 * (the ASan build would stop). */
static void test_index_past_the_palette_reads_its_last_colour(void **state)
{
    (void)state;
    static pond_backdrop pond;
    pond_backdrop_make(&pond);
    tarn_backdrop *backdrop = &pond.b.image.backdrop;
    const uint32_t only = 0x123456u;
    static uint32_t one[1];
    one[0] = only;
    backdrop->palette = one;
    backdrop->palette_count = 1u;
    uint8_t *rgb = test_render_rgb(&pond.b.water.scene, &pond.config, "over a one-colour palette");
    const uint8_t *sky = rgb; /* pixel (0, 0): no water above the horizon */
    assert_int_equal(sky[0], 0x12);
    assert_int_equal(sky[1], 0x34);
    assert_int_equal(sky[2], 0x56);
    size_t other = 0;
    for (size_t k = 0; k < 240u * 240u; k++)
        if (rgb[3 * k] != 0x12 || rgb[3 * k + 1] != 0x34 || rgb[3 * k + 2] != 0x56) other++;
    /* only the water's pixels differ */
    assert_true(other > 0u && other < 240u * 240u / 2u);
    free(rgb);
    pond_backdrop_free(&pond);
}

/* More colours than 16-bit indices name: a 16x16 grid of quads whose vertices take
 * scattered colours, shaded across 512x512 pixels, is refused with the count. */
static void test_too_many_colours_are_refused(void **state)
{
    (void)state;
    static scene_builder b;
    builder_init(&b, 0, 0, 2, 0, 0, 0);
    builder_begin_object(&b, 0xFFFFFFu, TARN_CULL_NONE);
    builder_grid(&b, 0, 0, 0, 4, 4, 16, 16);
    static uint32_t colours[BUILDER_VERTICES_MAX];
    uint32_t seed = 1;
    for (uint32_t k = 0; k < b.vertex_count; k++) {
        seed = seed * 1664525u + 1013904223u;
        colours[k] = seed >> 8;
    }
    b.meshes[0].colours = colours;
    const tarn_frame_config config = {512, 512, tarn_quality_default(), 0};
    tarn_backdrop_scene backdrop;
    tarn_error err;
    assert_int_equal(tarn_backdrop_scene_make(&b.scene, &config, tarn_backdrop_of(TARN_BACKDROP_OPAQUE), 0, &backdrop, &err), -1);
    if (strstr(err.message, "colours, at most 65536 fit its 16-bit indices") == NULL)
        fail_msg("expected the colour count in the error, got: %s", err.message);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_scene_draws_the_same_frame),
        cmocka_unit_test(test_every_knob_draws_the_same_frame),
        cmocka_unit_test(test_backdrop_keeps_what_the_water_reads),
        cmocka_unit_test(test_another_frame_is_refused),
        cmocka_unit_test(test_malformed_backdrop_is_refused),
        cmocka_unit_test(test_index_past_the_palette_reads_its_last_colour),
        cmocka_unit_test(test_too_many_colours_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
