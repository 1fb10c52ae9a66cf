/* test_vertex_pass.c: a frame that finds its vertices once, into its memory (the
 * quality's vertex_pass TARN_VERTICES_PER_FRAME, or TARN_VERTICES_PER_FRAME_VIEW
 * with their view positions), is the frame whose walks find them, byte for byte: on
 * every scene two ways of drawing are tested on and the moving ones, at each preset
 * and two times, in tiles and in strips. It takes the bytes tarn_render.h states
 * (16 a vertex, 28 with the view position, and the scene, its objects and the view
 * that names them), and none where a baked static view holds the vertices already. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "frame_render.h"
#include "scene_load.h"
#include "static_view.h"
#include "tarn_internal.h"

#define WIDTH 160
#define HEIGHT 120

static const char *const moving_scenes[] = {"scenes/pond-orbit.json", "scenes/lake-drift.json"};
static const char *const preset_names[] = {"exact", "balanced", "fast"};

static void load(const char *path, tarn_loaded_scene *loaded)
{
    tarn_error err;
    if (tarn_scene_load(path, loaded, &err) != 0) fail_msg("%s", err.message);
}

static tarn_frame_config config_of(int preset, uint32_t time_ms)
{
    tarn_frame_config c = {WIDTH, HEIGHT, tarn_quality_preset((tarn_preset)preset), time_ms};
    return c;
}

/* The frame with the vertex pass, in the preset's tiles and in 16-row strips,
 * equals the frame without it. */
static void assert_pass_draws_the_same_frame(const char *path)
{
    tarn_loaded_scene loaded;
    load(path, &loaded);
    static const uint32_t times[] = {0, 1234};
    for (int p = 0; p < TARN_PRESET_COUNT; p++)
        for (size_t t = 0; t < sizeof times / sizeof times[0]; t++) {
            tarn_frame_config config = config_of(p, times[t]);
            uint8_t *walked = test_render_rgb(&loaded.scene, &config, path);
            for (int strips = 0; strips <= 1; strips++)
                for (int view = 0; view <= 1; view++) {
                    config.quality.vertex_pass = view ? TARN_VERTICES_PER_FRAME_VIEW : TARN_VERTICES_PER_FRAME;
                    config.quality.frame_shape = strips ? TARN_FRAME_STRIPS : TARN_FRAME_TILES;
                    config.quality.tile_size = strips ? 16 : config.quality.tile_size;
                    uint8_t *passed = test_render_rgb(&loaded.scene, &config, path);
                    if (memcmp(walked, passed, 3u * WIDTH * HEIGHT) != 0)
                        fail_msg("%s (%s, %u ms, %s, %s): the vertex pass changes the frame", path, preset_names[p],
                                 (unsigned)times[t], strips ? "strips" : "tiles",
                                 view ? "view positions kept" : "clipped triangles transform again");
                    free(passed);
                }
            free(walked);
        }
    tarn_scene_free(&loaded);
}

static void test_vertex_pass_draws_the_same_frame(void **state)
{
    (void)state;
    for (size_t i = 0; i < TEST_FRAME_SCENE_COUNT; i++) assert_pass_draws_the_same_frame(test_frame_scenes[i]);
    for (size_t i = 0; i < sizeof moving_scenes / sizeof moving_scenes[0]; i++)
        assert_pass_draws_the_same_frame(moving_scenes[i]);
}

/* The bytes the pass adds to a still scene: its copy, its objects', the view it
 * makes and every vertex (with its view position, if kept), rounded to 4 bytes
 * with room to align the copy. */
static size_t pass_bytes(const tarn_scene *scene, int view_positions)
{
    size_t vertices = 0;
    for (uint32_t i = 0; i < scene->object_count; i++) vertices += scene->objects[i].mesh->vertex_count;
    const size_t vertex = sizeof(tarn_static_vertex) + (view_positions ? sizeof(tarn_vec3) : 0u);
    const size_t bytes = sizeof(void *) - 4u + sizeof(tarn_scene) + scene->object_count * sizeof(tarn_object) +
                         sizeof(tarn_static_view) + vertices * vertex;
    return (bytes + 3u) & ~(size_t)3u;
}

static void test_vertex_pass_takes_its_vertices_bytes(void **state)
{
    (void)state;
    tarn_loaded_scene loaded;
    load("scenes/pond.json", &loaded);
    tarn_frame_config config = config_of(TARN_PRESET_BALANCED, 0);
    const size_t walked = tarn_frame_memory_bytes(&config, &loaded.scene);
    for (int view = 1; view >= 0; view--) {
        config.quality.vertex_pass = view ? TARN_VERTICES_PER_FRAME_VIEW : TARN_VERTICES_PER_FRAME;
        const size_t passed = tarn_frame_memory_bytes(&config, &loaded.scene);
        if (passed - walked != pass_bytes(&loaded.scene, view))
            fail_msg("the vertex pass%s adds %zu bytes, not %zu", view ? " with view positions" : "",
                     passed - walked, pass_bytes(&loaded.scene, view));
        assert_int_equal(test_render_status(&loaded.scene, &config), TARN_OK);
    }

    /* baked for this frame, the scene's own static view holds the vertices */
    tarn_static_scene baked;
    tarn_error err;
    if (tarn_static_scene_make(&loaded.scene, &config, 1, &baked, &err) != 0) fail_msg("%s", err.message);
    tarn_frame_config walk = config;
    walk.quality.vertex_pass = TARN_VERTICES_PER_TILE;
    assert_int_equal(tarn_frame_memory_bytes(&config, &baked.scene), tarn_frame_memory_bytes(&walk, &baked.scene));
    tarn_static_scene_free(&baked);
    tarn_scene_free(&loaded);
}

/* The scene a frame with the pass draws: a copy in the frame's memory whose static
 * view is made for this frame, every object's vertices in that memory as the
 * frame's camera sees them, and their view positions where the quality keeps them. */
static void assert_pass_holds_every_vertex(tarn_vertex_pass mode)
{
    tarn_loaded_scene loaded;
    load("scenes/pond-orbit.json", &loaded);
    tarn_frame_config config = config_of(TARN_PRESET_EXACT, 1234);
    config.quality.vertex_pass = (uint8_t)mode;
    const size_t bytes = tarn_frame_memory_bytes(&config, &loaded.scene);
    uint8_t *memory = malloc(bytes);
    assert_non_null(memory);
    void *next = memory;
    const tarn_scene *own = tarn__frame_scene(&loaded.scene, &config, &next);
    assert_true((const uint8_t *)own >= memory && (uint8_t *)next <= memory + bytes);
    assert_true(tarn__static_screen_applies(own, &config));
    tarn_view view;
    tarn_scene plain = *own;
    plain.static_view = NULL;
    tarn__view_setup(&plain, &config, &view);
    const tarn_vec3 *positions = own->static_view->positions;
    if ((positions != NULL) != (mode == TARN_VERTICES_PER_FRAME_VIEW))
        fail_msg("the pass %s view positions", positions != NULL ? "kept" : "did not keep");
    for (uint32_t i = 0; i < own->object_count; i++) {
        const tarn_object *object = &own->objects[i];
        assert_true((const uint8_t *)object->static_vertices >= memory &&
                    (const uint8_t *)(object->static_vertices + object->mesh->vertex_count) <= (uint8_t *)next);
        tarn_object_xform xform;
        tarn__object_xform_setup(&view, object, &xform);
        for (uint32_t k = 0; k < object->mesh->vertex_count; k += 97u) {
            tarn_vec3 position;
            const tarn_static_vertex expected =
                tarn__static_vertex_of(&view, &xform, object->mesh, (uint16_t)k, &position);
            if (memcmp(&expected, &object->static_vertices[k], sizeof expected) != 0)
                fail_msg("object %u, vertex %u: the pass kept another vertex than the frame's camera sees",
                         (unsigned)i, (unsigned)k);
            if (positions != NULL && memcmp(&position, &positions[k], sizeof position) != 0)
                fail_msg("object %u, vertex %u: the pass kept another view position", (unsigned)i, (unsigned)k);
        }
        if (positions != NULL) positions += object->mesh->vertex_count;
    }
    free(memory);
    tarn_scene_free(&loaded);
}

static void test_vertex_pass_scene_holds_every_vertex(void **state)
{
    (void)state;
    assert_pass_holds_every_vertex(TARN_VERTICES_PER_FRAME);
    assert_pass_holds_every_vertex(TARN_VERTICES_PER_FRAME_VIEW);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vertex_pass_draws_the_same_frame),
        cmocka_unit_test(test_vertex_pass_takes_its_vertices_bytes),
        cmocka_unit_test(test_vertex_pass_scene_holds_every_vertex),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
