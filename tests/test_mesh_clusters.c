/* test_mesh_clusters.c: clusters are an optimisation only. The runs must cover
 * every triangle once, each sphere must hold its run, and skipping runs per tile
 * must never change a pixel. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "core_render.h"
#include "mesh_clusters.h"
#include "scene_load.h"

static tarn_loaded_scene *load_pond(void)
{
    tarn_loaded_scene *s = malloc(sizeof *s);
    tarn_error err;
    if (tarn_scene_load("scenes/pond.json", s, &err) != 0) fail_msg("%s", err.message);
    return s;
}

static double distance_q16(const tarn_vec3 *a, const tarn_vec3 *b)
{
    double dx = (a->x - (double)b->x) / 65536, dy = (a->y - (double)b->y) / 65536,
           dz = (a->z - (double)b->z) / 65536;
    return dx * dx + dy * dy + dz * dz;
}

static void test_runs_cover_triangles_and_spheres_hold_them(void **state)
{
    (void)state;
    tarn_loaded_scene *pond = load_pond();
    for (size_t o = 0; o < pond->object_count; o++) {
        const tarn_mesh *mesh = pond->objects[o].mesh;
        assert_non_null(mesh->clusters);
        uint32_t next = 0;
        for (uint32_t c = 0; c < mesh->cluster_count; c++) {
            const tarn_cluster *run = &mesh->clusters[c];
            assert_int_equal(run->first_triangle, next);
            assert_true(run->triangle_count >= 1 && run->triangle_count <= TARN_CLUSTER_TRIANGLES);
            next += run->triangle_count;
            double radius = run->radius / 65536.0;
            for (uint32_t k = 0; k < 3u * run->triangle_count; k++) {
                const tarn_vec3 *p = &mesh->positions[mesh->indices[3u * run->first_triangle + k]];
                assert_true(distance_q16(p, &run->centre) <= radius * radius);
            }
        }
        assert_int_equal(next, mesh->triangle_count);
    }
    tarn_scene_free(pond);
    free(pond);
}

/* The same scene with every mesh's clusters removed draws the same bytes. */
static void test_skipping_runs_changes_no_pixel(void **state)
{
    (void)state;
    tarn_loaded_scene *pond = load_pond();
    static const uint8_t tiles[] = {8, 16, 64};
    static const uint16_t sizes[][2] = {{240, 240}, {97, 61}};
    for (size_t z = 0; z < 2; z++) {
        const size_t bytes = 3u * sizes[z][0] * sizes[z][1];
        uint8_t *clustered = malloc(bytes), *plain = malloc(bytes);
        for (size_t t = 0; t < sizeof tiles; t++) {
            tarn_frame_config config = {sizes[z][0], sizes[z][1], tarn_quality_default(), 0};
            config.quality.tile_size = tiles[t];
            tarn_error err;
            assert_int_equal(tarn_core_render(&pond->scene, &config, clustered, NULL, &err), 0);
            for (size_t o = 0; o < pond->object_count; o++) pond->meshes[o].mesh.clusters = NULL;
            assert_int_equal(tarn_core_render(&pond->scene, &config, plain, NULL, &err), 0);
            for (size_t o = 0; o < pond->object_count; o++)
                pond->meshes[o].mesh.clusters = pond->meshes[o].clusters;
            assert_memory_equal(clustered, plain, bytes);
        }
        free(clustered);
        free(plain);
    }
    tarn_scene_free(pond);
    free(pond);
}

/* A run list that skips or repeats triangles is malformed scene data. */
static void test_malformed_runs_are_rejected(void **state)
{
    (void)state;
    tarn_loaded_scene *pond = load_pond();
    tarn_mesh *mesh = &pond->meshes[0].mesh;
    tarn_frame_config config = {64, 64, tarn_quality_default(), 0};
    size_t need = tarn_frame_memory_bytes(&config, &pond->scene);
    void *memory = malloc(need);
    mesh->cluster_count--; /* the last triangles are in no run */
    assert_int_equal(tarn_render_frame(&pond->scene, &config, memory, need, NULL, NULL), TARN_ERR_SCENE);
    mesh->cluster_count++;
    pond->meshes[0].clusters[1].first_triangle++; /* a gap */
    assert_int_equal(tarn_render_frame(&pond->scene, &config, memory, need, NULL, NULL), TARN_ERR_SCENE);
    pond->meshes[0].clusters[1].first_triangle--;
    assert_int_equal(tarn_render_frame(&pond->scene, &config, memory, need, NULL, NULL), TARN_OK);
    free(memory);
    tarn_scene_free(pond);
    free(pond);
}

/* Huge scales make huge spheres: the sphere test must saturate, not overflow (the
 * sanitizer build runs this), and still draw what is in view. */
static void test_huge_spheres_stay_in_range(void **state)
{
    (void)state;
    tarn_loaded_scene *pond = load_pond();
    for (size_t o = 0; o < pond->object_count; o++) {
        pond->objects[o].scale = INT32_MAX;
        for (uint32_t c = 0; c < pond->meshes[o].mesh.cluster_count; c++)
            pond->meshes[o].clusters[c].radius = INT32_MAX;
    }
    pond->scene.camera.fov_y_degrees = 65536; /* 1 degree: a long focal length, large plane norms */
    tarn_frame_config config = {64, 64, tarn_quality_default(), 0};
    uint8_t rgb[64 * 64 * 3], covered[64 * 64];
    tarn_error err;
    assert_int_equal(tarn_core_render(&pond->scene, &config, rgb, covered, &err), 0);
    tarn_scene_free(pond);
    free(pond);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_runs_cover_triangles_and_spheres_hold_them),
        cmocka_unit_test(test_skipping_runs_changes_no_pixel),
        cmocka_unit_test(test_malformed_runs_are_rejected),
        cmocka_unit_test(test_huge_spheres_stay_in_range),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
