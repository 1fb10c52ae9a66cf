/* test_static_view.c: a scene drawn with static vertices and bins (tarn_scene.h)
 * gives the frame it gives without them, byte for byte: on every scene, at each
 * preset and two times, with the meshes' positions kept or left out, and in a frame
 * other than the one their screen positions and bins were made for. The bins take
 * the place of found ones; a moved camera drops the static view (or, without
 * positions, refuses the scene); a vertex not projected keeps the clip planes it
 * lies outside, which drop its triangles; static vertices out of their ranges are
 * refused. */
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

/* a scene whose floor crosses the near plane: its triangles are clipped */
#define CLIPPED_SCENE "scenes/extremes/huge-near.json"

/* The loaded scene with its static view made for `made_for`. */
typedef struct {
    tarn_loaded_scene loaded;
    tarn_static_scene with_view;
    tarn_scene scene; /* with_view.scene, which a test may change */
    tarn_static_vertices *vertices;
} static_scene;

static void static_scene_make(static_scene *s, const char *path, const tarn_frame_config *made_for,
                              int without_positions)
{
    tarn_error err;
    if (tarn_scene_load(path, &s->loaded, &err) != 0) fail_msg("%s", err.message);
    if (tarn_static_scene_make(&s->loaded.scene, made_for, !without_positions, &s->with_view, &err) != 0)
        fail_msg("%s: %s", path, err.message);
    s->scene = s->with_view.scene;
    s->vertices = &s->with_view.vertices;
}

static void static_scene_free(static_scene *s)
{
    tarn_static_scene_free(&s->with_view);
    tarn_scene_free(&s->loaded);
}

/* The frame of `config` from the scene as loaded and with static vertices made for
 * `made_for`: equal, byte for byte. */
static void assert_same_frame(const char *path, const tarn_frame_config *config, const tarn_frame_config *made_for,
                              int without_positions)
{
    static_scene s;
    static_scene_make(&s, path, made_for, without_positions);
    uint8_t *plain = test_render_rgb(&s.loaded.scene, config, path);
    uint8_t *with_static = test_render_rgb(&s.scene, config, path);
    const size_t bytes = 3u * config->width * config->height;
    if (memcmp(plain, with_static, bytes) != 0)
        fail_msg("%s (subpixel bits %u, %u ms): static vertices change the frame", path,
                 config->quality.subpixel_bits, (unsigned)config->time_ms);
    free(plain);
    free(with_static);
    static_scene_free(&s);
}

static tarn_frame_config scene_config(const char *path, tarn_preset preset, uint32_t time_ms)
{
    tarn_loaded_scene loaded;
    tarn_error err;
    if (tarn_scene_load(path, &loaded, &err) != 0) fail_msg("%s", err.message);
    tarn_frame_config config = {loaded.width, loaded.height, tarn_quality_preset(preset), time_ms};
    tarn_scene_free(&loaded);
    return config;
}

static void test_every_scene_draws_the_same_frame(void **state)
{
    (void)state;
    static const uint32_t times[] = {0, 1500};
    for (size_t k = 0; k < TEST_FRAME_SCENE_COUNT; k++)
        for (int preset = 0; preset < TARN_PRESET_COUNT; preset++)
            for (size_t t = 0; t < 2; t++) {
                const tarn_frame_config config = scene_config(test_frame_scenes[k], (tarn_preset)preset, times[t]);
                assert_same_frame(test_frame_scenes[k], &config, &config, (int)t);
                /* made at the coarsest precision: this one projects and bins again */
                tarn_frame_config coarse = config;
                coarse.quality.subpixel_bits = TARN_SUBPIXEL_BITS_MIN;
                assert_same_frame(test_frame_scenes[k], &config, &coarse, (int)t);
            }
}

/* Screen positions made at 4 subpixel bits are not used at 5: the frame projects. */
static void test_another_frame_projects_again(void **state)
{
    (void)state;
    const tarn_frame_config fast = scene_config("scenes/pond.json", TARN_PRESET_FAST, 700);
    const tarn_frame_config exact = scene_config("scenes/pond.json", TARN_PRESET_EXACT, 700);
    assert_int_not_equal(fast.quality.subpixel_bits, exact.quality.subpixel_bits);
    assert_same_frame("scenes/pond.json", &exact, &fast, 1);
    tarn_frame_config smaller = fast;
    smaller.width = 200;
    assert_same_frame("scenes/pond.json", &smaller, &fast, 0);
}

/* In their own frame the static bins are read, not found: no memory for them, and
 * emptied they leave nothing to draw. A frame of another size or precision finds its
 * own. */
static void test_static_bins_stand_in_for_found_ones(void **state)
{
    (void)state;
    const tarn_frame_config fast = scene_config("scenes/pond.json", TARN_PRESET_FAST, 0);
    const tarn_frame_config exact = scene_config("scenes/pond.json", TARN_PRESET_EXACT, 0);
    assert_true(fast.quality.cluster_bins && exact.quality.cluster_bins);
    static_scene s;
    static_scene_make(&s, "scenes/pond.json", &fast, 1);
    assert_true(s.vertices->bin_count > 0);
    assert_int_equal(tarn_frame_memory_bytes(&fast, &s.scene),
                     tarn_frame_memory_bytes(&fast, &s.loaded.scene) - 4u * s.vertices->bin_count);
    assert_int_equal(tarn_frame_memory_bytes(&exact, &s.scene), tarn_frame_memory_bytes(&exact, &s.loaded.scene));
    tarn_frame_config smaller = fast;
    smaller.width = 200;
    assert_int_equal(tarn_frame_memory_bytes(&smaller, &s.scene), tarn_frame_memory_bytes(&smaller, &s.loaded.scene));
    uint8_t *drawn = test_render_rgb(&s.scene, &fast, "pond");
    for (uint32_t i = 0; i < s.vertices->bin_count; i++) {
        const tarn_cluster_bin empty = {255, 255, 0, 0};
        s.vertices->bins[i] = empty;
    }
    uint8_t *binned_out = test_render_rgb(&s.scene, &fast, "pond, empty bins");
    const uint8_t background[3] = {0x87, 0xce, 0xeb};
    for (size_t p = 0; p < (size_t)fast.width * fast.height; p++)
        assert_memory_equal(&binned_out[3 * p], background, 3);
    assert_memory_not_equal(drawn, binned_out, 3u * fast.width * fast.height);
    free(drawn);
    free(binned_out);
    static_scene_free(&s);
}

/* A camera moved after the bake: with positions the frame computes every vertex
 * (and draws what the loaded scene draws from there); without, it refuses. */
static void test_moved_camera_drops_static_vertices(void **state)
{
    (void)state;
    const tarn_frame_config config = scene_config("scenes/pond.json", TARN_PRESET_FAST, 0);
    static_scene kept, bare;
    static_scene_make(&kept, "scenes/pond.json", &config, 0);
    static_scene_make(&bare, "scenes/pond.json", &config, 1);
    kept.scene.camera.position.x += 65536;
    bare.scene.camera.position.x += 65536;
    kept.loaded.scene.camera.position.x += 65536;
    uint8_t *moved = test_render_rgb(&kept.loaded.scene, &config, "moved");
    uint8_t *with_static = test_render_rgb(&kept.scene, &config, "moved, static");
    assert_memory_equal(moved, with_static, 3u * config.width * config.height);
    assert_int_equal(test_render_status(&bare.scene, &config), TARN_ERR_SCENE);
    bare.scene.light.colour_rgb ^= 1u;
    bare.scene.camera = bare.vertices->view.camera;
    assert_int_equal(test_render_status(&bare.scene, &config), TARN_ERR_SCENE);
    free(moved);
    free(with_static);
    static_scene_free(&kept);
    static_scene_free(&bare);
}

/* A triangle the frame clips reads its vertices' view positions from the static
 * view: moved, they move what it draws. Without them it finds them from the meshes
 * (the same frame), and a scene whose meshes have no positions either is refused. */
static void test_clipped_triangles_read_view_positions(void **state)
{
    (void)state;
    const char *path = CLIPPED_SCENE;
    const tarn_frame_config config = scene_config(path, TARN_PRESET_BALANCED, 0);
    static_scene kept, bare;
    static_scene_make(&kept, path, &config, 0);
    static_scene_make(&bare, path, &config, 1);
    uint8_t *plain = test_render_rgb(&kept.loaded.scene, &config, path);
    tarn_static_view unplaced = kept.vertices->view;
    unplaced.positions = NULL;
    kept.scene.static_view = &unplaced;
    uint8_t *from_meshes = test_render_rgb(&kept.scene, &config, "positions from the meshes");
    assert_memory_equal(plain, from_meshes, 3u * config.width * config.height);
    kept.scene.static_view = &kept.vertices->view;
    const size_t vertices = tarn__scene_vertex_count(&kept.scene);
    for (size_t i = 0; i < vertices; i++) kept.vertices->positions[i].z += 65536; /* a unit farther */
    uint8_t *moved = test_render_rgb(&kept.scene, &config, "moved positions");
    assert_memory_not_equal(plain, moved, 3u * config.width * config.height);
    bare.vertices->view.positions = NULL;
    assert_int_equal(test_render_status(&bare.scene, &config), TARN_ERR_SCENE);
    free(plain);
    free(from_meshes);
    free(moved);
    static_scene_free(&kept);
    static_scene_free(&bare);
}

/* A vertex the frame could not project keeps the clip planes it lies outside
 * (tarn_static_vertex), and a triangle whose three vertices claim one plane draws
 * nothing: the pond with its water's vertices all claiming the near plane draws
 * the pond without its water, its clusters' bins and walks past them unread. */
static void test_unprojected_vertices_keep_their_planes(void **state)
{
    (void)state;
    const tarn_frame_config clipped = scene_config(CLIPPED_SCENE, TARN_PRESET_BALANCED, 0);
    static_scene near;
    static_scene_make(&near, CLIPPED_SCENE, &clipped, 0);
    size_t unprojected = 0;
    for (uint32_t o = 0; o < near.vertices->object_count; o++)
        for (uint32_t k = 0; k < near.scene.objects[o].mesh->vertex_count; k++) {
            const tarn_static_vertex *v = &near.vertices->vertices[o][k];
            if (v->inv_depth != 0u) continue;
            unprojected++;
            if (v->screen_x <= 0 || (unsigned)v->screen_x > TARN_CLIP_PLANE_BITS || v->screen_y != 0)
                fail_msg("%s: vertex %u of object %u not projected keeps planes 0x%x and row %d", CLIPPED_SCENE,
                         (unsigned)k, (unsigned)o, (unsigned)(uint16_t)v->screen_x, v->screen_y);
        }
    assert_true(unprojected > 0);
    static_scene_free(&near);

    const tarn_frame_config config = scene_config("scenes/pond.json", TARN_PRESET_FAST, 0);
    static_scene s;
    static_scene_make(&s, "scenes/pond.json", &config, 0);
    const uint32_t water = s.scene.object_count - 1u;
    assert_non_null(s.scene.objects[water].material->water);
    for (uint32_t k = 0; k < s.scene.objects[water].mesh->vertex_count; k++) {
        tarn_static_vertex *v = &s.vertices->vertices[water][k];
        v->inv_depth = 0u;
        v->screen_x = 1; /* the near plane, tarn__clip_outcode's bit 0 */
        v->screen_y = 0;
    }
    uint8_t *claimed = test_render_rgb(&s.scene, &config, "pond, its water's vertices beyond the near plane");
    s.loaded.scene.object_count = water;
    uint8_t *without = test_render_rgb(&s.loaded.scene, &config, "pond without its water");
    if (memcmp(claimed, without, 3u * config.width * config.height) != 0)
        fail_msg("pond: triangles whose vertices all lie beyond the near plane still drew");
    free(claimed);
    free(without);
    s.loaded.scene.object_count = water + 1u;
    static_scene_free(&s);
}

/* Each out-of-range field of a static vertex, or of the static view, is refused. */
static void test_out_of_range_static_vertices_are_refused(void **state)
{
    (void)state;
    const tarn_frame_config config = scene_config("scenes/pond.json", TARN_PRESET_FAST, 0);
    static_scene s;
    static_scene_make(&s, "scenes/pond.json", &config, 1);
    assert_int_equal(test_render_status(&s.scene, &config), TARN_OK);
    tarn_static_vertex *v = &s.vertices->vertices[0][0];
    const tarn_static_vertex saved = *v;
    v->lit[1] = 65281;
    assert_int_equal(test_render_status(&s.scene, &config), TARN_ERR_SCENE);
    *v = saved;
    v->fresnel = 32769;
    assert_int_equal(test_render_status(&s.scene, &config), TARN_ERR_SCENE);
    *v = saved;
    v->inv_depth = (1u << 30) + 1u;
    assert_int_equal(test_render_status(&s.scene, &config), TARN_ERR_SCENE);
    *v = saved;
    v->inv_depth = 1u;
    v->screen_x = INT16_MAX;
    assert_int_equal(test_render_status(&s.scene, &config), TARN_ERR_SCENE);
    v->screen_x = 0;
    v->screen_y = INT16_MIN;
    assert_int_equal(test_render_status(&s.scene, &config), TARN_ERR_SCENE);
    v->inv_depth = 0u; /* not projected: clip planes in screen_x, and nothing in screen_y */
    v->screen_x = (int16_t)(TARN_CLIP_PLANE_BITS + 1u);
    v->screen_y = 0;
    assert_int_equal(test_render_status(&s.scene, &config), TARN_ERR_SCENE);
    v->screen_x = -1;
    assert_int_equal(test_render_status(&s.scene, &config), TARN_ERR_SCENE);
    v->screen_x = (int16_t)TARN_CLIP_PLANE_BITS;
    v->screen_y = 1;
    assert_int_equal(test_render_status(&s.scene, &config), TARN_ERR_SCENE);
    *v = saved;
    assert_int_equal(test_render_status(&s.scene, &config), TARN_OK);
    s.vertices->view.subpixel_bits = 0;
    assert_int_equal(test_render_status(&s.scene, &config), TARN_ERR_SCENE);
    s.vertices->view.subpixel_bits = config.quality.subpixel_bits;
    s.vertices->view.width = 0;
    assert_int_equal(test_render_status(&s.scene, &config), TARN_ERR_SCENE);
    static_scene_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_scene_draws_the_same_frame),
        cmocka_unit_test(test_another_frame_projects_again),
        cmocka_unit_test(test_static_bins_stand_in_for_found_ones),
        cmocka_unit_test(test_moved_camera_drops_static_vertices),
        cmocka_unit_test(test_clipped_triangles_read_view_positions),
        cmocka_unit_test(test_unprojected_vertices_keep_their_planes),
        cmocka_unit_test(test_out_of_range_static_vertices_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
