/* test_still_water.c: the water drawn over a still-water backdrop (tarn_scene.h,
 * host/bake/backdrop.h), which holds the water's still terms drawn and each flat water
 * object's plane: where the water has no moving terms, the frame is the whole
 * scene's, byte for byte; where it has some, it is as close to the float reference
 * as the whole scene drawn, one water object or two that overlap. The backdrop
 * marks each water pixel with its object and where foam can show, keeping the
 * depth there only, or with refraction wherever the water is shallow and where a
 * refracted sample may land within a foam band; refracted samples are read from
 * the picture, their fog moved to the refracting surface; no mark reaches a tile;
 * what it does not apply to (the underwater view, water that is not flat, another
 * quality, a lit colour past 255) is refused. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "backdrop.h"
#include "compare.h"
#include "frame_render.h"
#include "reference.h"
#include "scene_load.h"
#include "tarn_internal.h"

static void load(const char *path, tarn_loaded_scene *loaded)
{
    tarn_error err;
    if (tarn_scene_load(path, loaded, &err) != 0) fail_msg("%s", err.message);
}

static void still_make(const tarn_scene *scene, const tarn_frame_config *config, tarn_backdrop_scene *b)
{
    tarn_error err;
    if (tarn_backdrop_scene_make(scene, config, tarn_backdrop_of(TARN_BACKDROP_STILL), 0, b, &err) != 0) fail_msg("%s", err.message);
}

static tarn_frame_config fast_config(const tarn_loaded_scene *loaded, uint8_t water_block)
{
    tarn_frame_config config = {loaded->width, loaded->height, tarn_quality_preset(TARN_PRESET_FAST), 0};
    config.quality.water_coordinates = TARN_WATER_UV_PLANE; /* still water's, always */
    config.quality.water_block = water_block;
    return config;
}

typedef struct {
    int largest;      /* the largest difference in a channel */
    size_t over_one;  /* pixels differing by more than 1 in some channel */
    size_t differing; /* pixels differing at all */
} frame_difference;

static frame_difference difference(const uint8_t *a, const uint8_t *b, size_t pixels)
{
    frame_difference d = {0, 0, 0};
    for (size_t k = 0; k < pixels; k++) {
        int pixel = 0;
        for (int c = 0; c < 3; c++) {
            const int apart = abs((int)a[3 * k + c] - (int)b[3 * k + c]);
            if (apart > pixel) pixel = apart;
        }
        if (pixel > d.largest) d.largest = pixel;
        d.over_one += pixel > 1;
        d.differing += pixel > 0;
    }
    return d;
}

/* The whole scene's frame and the one over its still water, at each of two times. */
static frame_difference still_against_whole(const tarn_scene *scene, tarn_frame_config config, const char *what)
{
    tarn_backdrop_scene b;
    still_make(scene, &config, &b);
    frame_difference worst = {0, 0, 0};
    static const uint32_t times[] = {0, 1750};
    for (size_t t = 0; t < 2; t++) {
        config.time_ms = times[t];
        uint8_t *whole = test_render_rgb(scene, &config, what);
        uint8_t *over = test_render_rgb(&b.water.scene, &config, "over still water");
        const frame_difference d = difference(whole, over, (size_t)config.width * config.height);
        if (d.largest > worst.largest) worst.largest = d.largest;
        worst.over_one += d.over_one;
        worst.differing += d.differing;
        free(whole);
        free(over);
    }
    tarn_backdrop_scene_free(&b);
    return worst;
}

/* The scenes still water applies to: no underwater view. */
static int applies(const tarn_loaded_scene *loaded)
{
    return loaded->scene.underwater == NULL;
}

static uint32_t water_features(const tarn_scene *scene)
{
    uint32_t features = 0;
    for (uint32_t k = 0; k < scene->object_count; k++)
        if (scene->objects[k].material->water != NULL) features |= scene->objects[k].material->water->features;
    return features;
}

/* PSNR of the frame at `config` against the float reference's. */
static double psnr_against_reference(const tarn_scene *scene, const tarn_frame_config *config, const uint8_t *rgb)
{
    const size_t bytes = 3u * config->width * config->height;
    uint8_t *reference = malloc(bytes);
    assert_non_null(reference);
    const tarn_reference_options options = {.geometry = TARN_REF_CONTINUOUS, .subpixel_bits = TARN_SUBPIXEL_BITS_MAX,
                                            .time_ms = config->time_ms};
    assert_int_equal(tarn_reference_render(scene, config->width, config->height, &options, reference, NULL), 0);
    tarn_compare_metrics m;
    tarn_compare_images(rgb, reference, NULL, NULL, config->width, config->height, &m);
    free(reference);
    return m.psnr_db;
}

/* The frame of `scene` and the one over its still water at `config`, and their
 * PSNR against the float reference. */
static frame_difference still_and_reference(const tarn_scene *scene, const tarn_frame_config *config,
                                            double *whole_db, double *still_db)
{
    tarn_backdrop_scene b;
    still_make(scene, config, &b);
    uint8_t *whole = test_render_rgb(scene, config, "the whole scene");
    uint8_t *over = test_render_rgb(&b.water.scene, config, "over still water");
    const frame_difference d = difference(whole, over, (size_t)config->width * config->height);
    *whole_db = psnr_against_reference(scene, config, whole);
    *still_db = psnr_against_reference(scene, config, over);
    free(whole);
    free(over);
    tarn_backdrop_scene_free(&b);
    return d;
}

/* Where the water has no moving terms, its still colour is its colour: the frame
 * is the same, byte for byte, on every scene whose water has none. Where it has
 * some, the texture coordinates are the plane's, exact where triangles interpolate
 * them, and each pixel finds its own highlight: as close to the float reference. */
static void test_every_scene_keeps_its_still_colours(void **state)
{
    (void)state;
    size_t still_scenes = 0, moving_scenes = 0;
    for (size_t k = 0; k < TEST_FRAME_SCENE_COUNT; k++) {
        tarn_loaded_scene loaded;
        load(test_frame_scenes[k], &loaded);
        if (applies(&loaded)) {
            tarn_frame_config config = fast_config(&loaded, 1);
            config.time_ms = 1750;
            double whole_db, still_db;
            const frame_difference d = still_and_reference(&loaded.scene, &config, &whole_db, &still_db);
            const int moving = (water_features(&loaded.scene) & TARN_WATER_MOVING) != 0u;
            print_message("%s: %.2f dB whole, %.2f dB over still water\n", test_frame_scenes[k], whole_db, still_db);
            if (!moving && d.differing != 0u)
                fail_msg("%s: %zu pixels differ over still water", test_frame_scenes[k], d.differing);
            /* the backdrop's plane and the frame's own round otherwise, and on a
             * foam edge or a highlight's one pixel can tip (one of scenes/effects/
             * foam.json's costs 0.5 dB; the beach's four at 1750 ms, 0.36 dB):
             * a few such beside the still colours' rounding by one level, or
             * 0.2 dB, and no more */
            if (moving && still_db < whole_db - 0.2 && d.over_one > 8u)
                fail_msg("%s: %.2f dB over still water, %.2f dB whole", test_frame_scenes[k], still_db, whole_db);
            still_scenes += !moving;
            moving_scenes += moving;
        }
        tarn_scene_free(&loaded);
    }
    assert_true(still_scenes >= 1u && moving_scenes >= 10u);
}

/* Against the float reference, the pond over still water is no further than the
 * whole scene drawn: each pixel finds its own highlight from exact coordinates,
 * or a block shares one, as the whole scene's blocks do. */
static void test_pond_is_as_close_to_the_reference(void **state)
{
    (void)state;
    tarn_loaded_scene loaded;
    load("scenes/pond.json", &loaded);
    for (uint8_t block = 1; block <= 4; block *= 2) {
        tarn_frame_config config = fast_config(&loaded, block);
        config.time_ms = 1750;
        tarn_backdrop_scene b;
        still_make(&loaded.scene, &config, &b);
        uint8_t *whole = test_render_rgb(&loaded.scene, &config, "pond");
        uint8_t *over = test_render_rgb(&b.water.scene, &config, "over still water");
        const double whole_db = psnr_against_reference(&loaded.scene, &config, whole);
        const double still_db = psnr_against_reference(&loaded.scene, &config, over);
        print_message("pond, water block %u: %.2f dB whole, %.2f dB over still water\n", block, whole_db, still_db);
        assert_true(still_db >= whole_db - 0.02);
        free(whole);
        free(over);
        tarn_backdrop_scene_free(&b);
    }
    tarn_scene_free(&loaded);
}

/* Two water objects, the second a copy of the pond's raised and moved aside so that
 * it covers part of the first: each pixel is its front water's. */
static void test_overlapping_water_objects_are_told_apart(void **state)
{
    (void)state;
    tarn_loaded_scene loaded;
    load("scenes/pond.json", &loaded);
    const uint32_t count = loaded.scene.object_count;
    tarn_object *objects = malloc((count + 1u) * sizeof *objects);
    assert_non_null(objects);
    memcpy(objects, loaded.scene.objects, count * sizeof *objects);
    objects[count] = objects[count - 1u]; /* the water plane */
    objects[count].position.x += 12 * 65536;
    objects[count].position.y += 65536 / 2;
    tarn_scene two = loaded.scene;
    two.objects = objects;
    two.object_count = count + 1u;
    tarn_frame_config config = fast_config(&loaded, 1);
    tarn_backdrop_scene b;
    still_make(&two, &config, &b);
    size_t marked[3] = {0, 0, 0};
    const tarn_backdrop *backdrop = &b.image.backdrop;
    for (uint32_t k = 0; k < backdrop->palette_count; k++) {
        const uint32_t object = (backdrop->palette[k] & TARN_BACKDROP_STILL_OBJECT) >> TARN_BACKDROP_STILL_SHIFT;
        assert_true(object <= 2u);
        marked[object]++;
    }
    assert_true(marked[1] > 100u && marked[2] > 100u);
    tarn_backdrop_scene_free(&b);
    const frame_difference d = still_against_whole(&two, config, "two water objects");
    assert_true(d.over_one * 100u < (size_t)config.width * config.height);
    free(objects);
    tarn_scene_free(&loaded);
}

/* The pond's water pixels are all marked with its one water object; the depth is
 * kept only in the foam band, a few pixels a row; every pixel a tile hands on is
 * 0xRRGGBB. */
static int no_marks(void *user, const tarn_tile *tile)
{
    size_t *marked = user;
    for (int y = 0; y < tile->height; y++)
        for (int x = 0; x < tile->width; x++) *marked += tile->rgb[(size_t)y * tile->stride + (size_t)x] > 0xFFFFFFu;
    return 0;
}

/* The pond at the fast preset over its still water; made in place, since both
 * point into themselves. */
typedef struct {
    tarn_frame_config config;
    tarn_loaded_scene loaded;
    tarn_backdrop_scene b;
} pond_still;

static void pond_still_make(pond_still *p)
{
    load("scenes/pond.json", &p->loaded);
    p->config = fast_config(&p->loaded, 2);
    still_make(&p->loaded.scene, &p->config, &p->b);
}

static void pond_still_free(pond_still *p)
{
    tarn_backdrop_scene_free(&p->b);
    tarn_scene_free(&p->loaded);
}

static void test_backdrop_keeps_the_still_water(void **state)
{
    (void)state;
    static pond_still pond;
    pond_still_make(&pond);
    const tarn_frame_config config = pond.config;
    const tarn_backdrop_scene *b = &pond.b;
    const tarn_backdrop *backdrop = &b->image.backdrop;
    assert_int_equal(backdrop->still_water, 1);
    assert_int_equal(backdrop->water_block, 2);
    size_t water_colours = 0;
    size_t foam_colours = 0;
    for (uint32_t k = 0; k < backdrop->palette_count; k++) {
        water_colours += (backdrop->palette[k] & TARN_BACKDROP_STILL_OBJECT) == 1u << TARN_BACKDROP_STILL_SHIFT;
        foam_colours += (backdrop->palette[k] & TARN_BACKDROP_STILL_FOAM) != 0u;
    }
    assert_true(foam_colours > 100u && foam_colours < 3000u);
    assert_true(water_colours > 5000u && water_colours < backdrop->palette_count);
    assert_true(backdrop->depth_count > 1000u && backdrop->depth_count < 4000u);
    assert_true(backdrop->span_count > 100u && backdrop->span_count < 600u);
    const size_t bytes = tarn_frame_memory_bytes(&config, &b->water.scene);
    void *memory = malloc(bytes);
    size_t marked = 0;
    assert_int_equal(tarn_render_frame(&b->water.scene, &config, memory, bytes, no_marks, &marked), TARN_OK);
    assert_int_equal(marked, 0);
    free(memory);
    pond_still_free(&pond);
}

static void assert_refused(const tarn_scene *scene, const tarn_frame_config *config, const char *expected)
{
    tarn_backdrop_scene b;
    tarn_error err;
    assert_int_equal(tarn_backdrop_scene_make(scene, config, tarn_backdrop_of(TARN_BACKDROP_STILL), 0, &b, &err), -1);
    if (strstr(err.message, expected) == NULL) fail_msg("expected \"%s\" in: %s", expected, err.message);
}

/* The underwater view moves every pixel with the clock. */
static void test_underwater_is_refused_at_bake(void **state)
{
    (void)state;
    tarn_loaded_scene loaded;
    load("scenes/effects/underwater.json", &loaded);
    const tarn_frame_config config = fast_config(&loaded, 2);
    assert_refused(&loaded.scene, &config, "--backdrop still: the scene's underwater view moves every pixel");
    tarn_scene_free(&loaded);
}

/* With an apron, the pond's refracted samples are read from the still picture:
 * against the float reference the frame gains as much as the scene drawn whole
 * gains from its apron, within 3 dB, whatever the water block (a sample that lands
 * on water takes that pixel's still terms, not its own: 32.82 against 35.26 dB at
 * water block 1, where both take their coordinates from the plane); it is the same at
 * any tile size; and the backdrop keeps the depth of water wherever it is under
 * one unit, for refraction's reach, more pixels than the foam band alone. */
static void test_refraction_reads_the_picture(void **state)
{
    (void)state;
    tarn_loaded_scene loaded;
    load("scenes/pond.json", &loaded);
    for (uint8_t block = 1; block <= 4; block *= 2) {
        tarn_frame_config config = fast_config(&loaded, block);
        config.time_ms = 1750;
        double whole_db, flat_db, refracted_db;
        (void)still_and_reference(&loaded.scene, &config, &whole_db, &flat_db);
        config.quality.refraction_apron = TARN_APRON_FULL;
        (void)still_and_reference(&loaded.scene, &config, &whole_db, &refracted_db);
        print_message("pond, water block %u: %.2f dB over still water without refraction, %.2f with; %.2f whole\n",
                      block, flat_db, refracted_db, whole_db);
        assert_true(refracted_db > flat_db + 8.0);
        assert_true(refracted_db > whole_db - 0.5);
    }
    tarn_frame_config config = fast_config(&loaded, 2);
    config.quality.refraction_apron = TARN_APRON_FULL;
    tarn_backdrop_scene b;
    still_make(&loaded.scene, &config, &b);
    assert_true(b.image.backdrop.depth_count > 5000u);
    uint8_t *at_40 = test_render_rgb(&b.water.scene, &config, "tiles of 40");
    config.quality.tile_size = 8;
    uint8_t *at_8 = test_render_rgb(&b.water.scene, &config, "tiles of 8");
    assert_memory_equal(at_40, at_8, 3u * config.width * config.height);
    free(at_40);
    free(at_8);
    tarn_backdrop_scene_free(&b);
    tarn_scene_free(&loaded);
}

/* The pond at the fast preset with the full apron and `water_block`, at 1750 ms. */
static tarn_frame_config refracting_pond(tarn_loaded_scene *loaded, uint8_t water_block)
{
    load("scenes/pond.json", loaded);
    tarn_frame_config config = fast_config(loaded, water_block);
    config.quality.refraction_apron = TARN_APRON_FULL;
    config.time_ms = 1750;
    return config;
}

/* A refracted sample that lands where no water draws (the bank behind the water,
 * the sphere standing in it) is taken where it lies behind the water it moved from,
 * as the scene drawn whole takes it: the backdrop keeps the opaque near/d of such
 * pixels, and the frame without them (each turned back to "none kept") is further
 * from the float reference, by at least 1 dB on the pond. */
static void test_samples_beside_the_water_are_taken(void **state)
{
    (void)state;
    tarn_loaded_scene loaded;
    const tarn_frame_config config = refracting_pond(&loaded, 2);
    tarn_backdrop_scene b;
    still_make(&loaded.scene, &config, &b);
    uint8_t *beside = test_render_rgb(&b.water.scene, &config, "samples beside the water taken");
    const tarn_backdrop *backdrop = &b.image.backdrop;
    uint16_t *kept = b.image.depth;
    size_t turned_back = 0;
    for (int32_t j = 0; j < config.height; j++)
        for (uint32_t k = backdrop->row_spans[j]; k < backdrop->row_spans[j + 1]; k++)
            for (int32_t i = backdrop->spans[k].x0; i < backdrop->spans[k].x1; i++) {
                const uint32_t colour = tarn__backdrop_colour_at(backdrop, config.width, i, j);
                uint16_t *value = &kept[backdrop->spans[k].first + (uint32_t)(i - backdrop->spans[k].x0)];
                if ((colour & TARN_BACKDROP_STILL_OBJECT) != 0u || *value == 0xFFFFu) continue;
                *value = 0xFFFFu;
                turned_back++;
            }
    uint8_t *refused = test_render_rgb(&b.water.scene, &config, "samples beside the water refused");
    const double beside_db = psnr_against_reference(&loaded.scene, &config, beside);
    const double refused_db = psnr_against_reference(&loaded.scene, &config, refused);
    print_message("pond: %zu pixels beside the water keep their depth; %.2f dB taking samples there, %.2f refusing\n",
                  turned_back, beside_db, refused_db);
    assert_true(turned_back > 1000u);
    assert_true(beside_db > refused_db + 1.0);
    free(beside);
    free(refused);
    tarn_backdrop_scene_free(&b);
    tarn_scene_free(&loaded);
}

/* A refracted sample that lands on water whose bed lies a unit or more below it,
 * seen from farther water, may lie within that water's foam band: the backdrop
 * keeps the depth of water there as deep as --landing-depth asks. On the pond, 4
 * units keep thousands more pixels than 1, and bring the frame nearer the float
 * reference by at least 1 dB: the far shore's foam line, seen through the water. */
static void test_samples_landing_on_deep_water_find_the_foam_band(void **state)
{
    (void)state;
    tarn_loaded_scene loaded;
    const tarn_frame_config config = refracting_pond(&loaded, 1);
    double db[2];
    uint32_t kept[2];
    static const uint32_t depths[2] = {TARN_LANDING_DEPTH_MIN_Q16, TARN_LANDING_DEPTH_MAX_Q16};
    for (int k = 0; k < 2; k++) {
        tarn_backdrop_request request = tarn_backdrop_of(TARN_BACKDROP_STILL);
        request.landing_depth_q16 = depths[k];
        tarn_backdrop_scene b;
        tarn_error err;
        if (tarn_backdrop_scene_make(&loaded.scene, &config, request, 0, &b, &err) != 0) fail_msg("%s", err.message);
        uint8_t *over = test_render_rgb(&b.water.scene, &config, "over still water");
        db[k] = psnr_against_reference(&loaded.scene, &config, over);
        kept[k] = b.image.backdrop.depth_count;
        free(over);
        tarn_backdrop_scene_free(&b);
    }
    print_message("pond: landing depth 1: %u values kept, %.2f dB; 4: %u, %.2f dB\n", kept[0], db[0], kept[1], db[1]);
    assert_true(kept[1] > kept[0] + 5000u);
    assert_true(db[1] > db[0] + 1.0);
    tarn_scene_free(&loaded);
}

/* Still water draws flat water only, whose texture coordinates are an affine map
 * of its plane, and a plane the camera does not lie in. */
static void test_water_still_water_cannot_draw_is_refused(void **state)
{
    (void)state;
    tarn_loaded_scene loaded;
    load("scenes/pond.json", &loaded);
    const tarn_frame_config config = fast_config(&loaded, 2);
    const uint32_t water = loaded.scene.object_count - 1u, sphere = 9u;
    assert_non_null(loaded.scene.objects[water].material->water);
    tarn_object *objects = malloc(loaded.scene.object_count * sizeof *objects);
    assert_non_null(objects);
    memcpy(objects, loaded.scene.objects, loaded.scene.object_count * sizeof *objects);
    tarn_scene changed = loaded.scene;
    changed.objects = objects;
    objects[water].mesh = objects[sphere].mesh;
    assert_refused(&changed, &config, "--backdrop still: water object objects[11] is not flat");
    tarn_mesh mesh = *loaded.scene.objects[water].mesh;
    tarn_uv *uvs = malloc(mesh.vertex_count * sizeof *uvs);
    assert_non_null(uvs);
    memcpy(uvs, mesh.uvs, mesh.vertex_count * sizeof *uvs);
    uvs[mesh.vertex_count / 2u].u += 65536 / 4;
    mesh.uvs = uvs;
    objects[water].mesh = &mesh;
    assert_refused(&changed, &config, "objects[11] has texture coordinates that are not an affine map of its plane");
    objects[water].mesh = loaded.scene.objects[water].mesh;
    changed.camera.position.y = objects[water].position.y;
    assert_refused(&changed, &config, "objects[11] comes so close to the camera");
    free(uvs);
    free(objects);
    tarn_scene_free(&loaded);
}

/* A frame whose knobs shape the still terms otherwise is refused; the tile size
 * and the apron change nothing of them. */
static void test_another_quality_is_refused(void **state)
{
    (void)state;
    static pond_still pond;
    pond_still_make(&pond);
    const tarn_frame_config config = pond.config;
    tarn_backdrop_scene *b = &pond.b;
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_OK);
    tarn_frame_config other = config;
    other.quality.water_block = 1;
    assert_int_equal(test_render_status(&b->water.scene, &other), TARN_ERR_SCENE);
    other = config;
    other.quality.fog_argument_bits = 8;
    assert_int_equal(test_render_status(&b->water.scene, &other), TARN_ERR_SCENE);
    other = config;
    other.quality.exp2.entries = 64;
    assert_int_equal(test_render_status(&b->water.scene, &other), TARN_ERR_SCENE);
    other = config;
    other.quality.exp2.interpolate = 1;
    assert_int_equal(test_render_status(&b->water.scene, &other), TARN_ERR_SCENE);
    other = config; /* the apron shapes no still term: refraction reads the picture */
    other.quality.refraction_apron = 4;
    assert_int_equal(test_render_status(&b->water.scene, &other), TARN_OK);
    other = config;
    other.quality.tile_size = 16;
    assert_int_equal(test_render_status(&b->water.scene, &other), TARN_OK);
    /* malformed: a still_water other than 0 or 1, a palette with the pass's mark */
    tarn_backdrop *backdrop = &b->image.backdrop;
    backdrop->still_water = 2;
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    backdrop->still_water = 1;
    const uint32_t colour = b->image.palette[0];
    b->image.palette[0] |= 0x01000000u;
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    b->image.palette[0] = colour;
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_OK);
    /* a plane's lit colour past 255.0, which the water's products do not hold */
    b->image.planes[0].lit[2] = 65281u;
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_ERR_SCENE);
    b->image.planes[0].lit[2] = 65280u;
    assert_int_equal(test_render_status(&b->water.scene, &config), TARN_OK);
    pond_still_free(&pond);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_scene_keeps_its_still_colours),
        cmocka_unit_test(test_pond_is_as_close_to_the_reference),
        cmocka_unit_test(test_overlapping_water_objects_are_told_apart),
        cmocka_unit_test(test_backdrop_keeps_the_still_water),
        cmocka_unit_test(test_underwater_is_refused_at_bake),
        cmocka_unit_test(test_refraction_reads_the_picture),
        cmocka_unit_test(test_samples_beside_the_water_are_taken),
        cmocka_unit_test(test_samples_landing_on_deep_water_find_the_foam_band),
        cmocka_unit_test(test_water_still_water_cannot_draw_is_refused),
        cmocka_unit_test(test_another_quality_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
