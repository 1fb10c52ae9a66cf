/* test_water_plane.c: flat water's texture coordinates from its plane
 * (tarn_uv_plane, core/water/water_plane.c). The loader finds the plane of each
 * flat water mesh whose coordinates stay within TARN_UV_PLANE_REPEATS_MAX, and no
 * other; the core's integers give, at every pixel, the coordinates the float
 * reference finds where the ray through the pixel's centre meets the plane, for a
 * still camera and a moving one, the object turned, scaled and seen from below;
 * a plane whose numbers would leave their ranges is not used, and one a build
 * without planes would draw otherwise is refused. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <cmocka.h>

#include "frame_render.h"
#include "ref_geometry.h"
#include "scene_load.h"
#include "tarn_internal.h"
#include "uv_plane.h"

/* Farther than this (in repeats) from the reference's coordinates, a 64-texel map
 * at scale 8 would be 1/2000 of a texel off: the pond measures 3e-7 (the
 * coordinates at the eye rounded to Q16.16, as first written, put 8e-6). */
#define COORDINATE_TOLERANCE 1e-6

static void load(const char *path, tarn_loaded_scene *loaded)
{
    tarn_error err;
    if (tarn_scene_load(path, loaded, &err) != 0) fail_msg("%s", err.message);
}

static const tarn_object *water_object(const tarn_scene *scene)
{
    for (uint32_t k = 0; k < scene->object_count; k++)
        if (scene->objects[k].material->water != NULL) return &scene->objects[k];
    fail_msg("the scene has no water object");
    return NULL;
}

/* The object's plane in the frame of `scene` (posed) at width x height. */
static tarn_water_plane frame_plane(const tarn_scene *scene, const tarn_object *object, uint16_t width,
                                    uint16_t height)
{
    const tarn_frame_config config = {width, height, tarn_quality_preset(TARN_PRESET_EXACT), 0};
    tarn_view view;
    tarn__view_setup(scene, &config, &view);
    tarn_water_plane plane;
    tarn__water_plane_setup(&plane, &view, TARN_WATER_UV_PLANE, object);
    return plane;
}

/* Whether uv lies within the coordinates of the mesh's vertices: on the water, not
 * on its plane beyond it, where the pixel's denominator may be far smaller. */
static int on_the_mesh(const tarn_mesh *mesh, const double uv[2])
{
    double low[2] = {HUGE_VAL, HUGE_VAL}, high[2] = {-HUGE_VAL, -HUGE_VAL};
    for (uint32_t k = 0; k < mesh->vertex_count; k++) {
        const double at[2] = {mesh->uvs[k].u / 65536.0, mesh->uvs[k].v / 65536.0};
        for (int axis = 0; axis < 2; axis++) low[axis] = fmin(low[axis], at[axis]), high[axis] = fmax(high[axis], at[axis]);
    }
    return uv[0] >= low[0] && uv[0] <= high[0] && uv[1] >= low[1] && uv[1] <= high[1];
}

/* The largest distance, in repeats, between the core's coordinates and the
 * reference's over the pixels that see the water (every third pixel each way);
 * fails when too few do. */
static double largest_coordinate_error(const tarn_scene *scene, const tarn_object *object, uint16_t width,
                                       uint16_t height)
{
    const tarn_water_plane plane = frame_plane(scene, object, width, height);
    if (!plane.holds) fail_msg("the plane does not hold in this frame");
    const tarn_ref_camera cam = tarn_ref_camera_make(&scene->camera, height);
    double worst = 0;
    size_t measured = 0;
    for (int32_t j = 0; j < height; j += 3)
        for (int32_t i = 0; i < width; i += 3) {
            double uv[2];
            const uint32_t denominator = tarn__fine_affine_at(&plane.denominator, i, j);
            if ((int32_t)denominator <= 0 || !tarn_ref_plane_uv(&cam, object, i + 0.5, j + 0.5, width, height, uv) ||
                !on_the_mesh(object->mesh, uv))
                continue; /* behind the eye, along the horizon, or beyond the water */
            tarn_water_input in;
            tarn__plane_coordinates(tarn__plane_denominator(denominator), tarn__fine_affine_at(&plane.u, i, j),
                                    tarn__fine_affine_at(&plane.v, i, j), plane.uv_shift, TARN_RECIP_STEPS_MAX, &in);
            const double core[2] = {((int32_t)in.u + in.u_low / 65536.0) / 65536.0,
                                    ((int32_t)in.v + in.v_low / 65536.0) / 65536.0};
            for (int axis = 0; axis < 2; axis++) worst = fmax(worst, fabs(core[axis] - uv[axis]));
            measured++;
        }
    if (measured < 100u) fail_msg("only %zu pixels see the plane", measured);
    return worst;
}

static void test_the_loader_finds_flat_water_only(void **state)
{
    (void)state;
    tarn_loaded_scene pond, scaled;
    load("scenes/pond.json", &pond);
    for (uint32_t k = 0; k < pond.scene.object_count; k++) {
        const tarn_object *o = &pond.scene.objects[k];
        if ((o->mesh->plane != NULL) != (o->material->water != NULL))
            fail_msg("pond objects[%u]: %s", k, o->mesh->plane != NULL ? "an opaque mesh has a plane" : "the water has none");
    }
    /* the normal maps repeat 2048 times a coordinate unit: past 256 repeats */
    load("scenes/extremes/uv-scale.json", &scaled);
    assert_null(water_object(&scaled.scene)->mesh->plane);
    tarn_scene_free(&pond);
    tarn_scene_free(&scaled);
}

static void test_a_mesh_that_is_not_flat_has_no_plane(void **state)
{
    (void)state;
    tarn_mesh_buffer box;
    memset(&box, 0, sizeof box);
    tarn_error err;
    if (tarn_mesh_box(&box, 1, 1, 1, "a box", &err) != 0) fail_msg("%s", err.message);
    tarn_uv_plane_fit fit;
    const char *why = NULL;
    assert_int_equal(tarn_uv_plane_find(&box.mesh, &fit, &why), 0);
    assert_string_equal(why, "is not flat");
    tarn_mesh_buffer_free(&box);
}

static void test_coordinates_match_the_reference(void **state)
{
    (void)state;
    tarn_loaded_scene pond;
    load("scenes/pond.json", &pond);
    const double worst = largest_coordinate_error(&pond.scene, water_object(&pond.scene), pond.width, pond.height);
    print_message("pond: coordinates within %.3g repeats of the reference\n", worst);
    assert_true(worst < COORDINATE_TOLERANCE);
    tarn_scene_free(&pond);
}

static void test_a_moving_camera_is_followed(void **state)
{
    (void)state;
    tarn_loaded_scene orbit;
    load("scenes/pond-orbit.json", &orbit);
    tarn_object *objects = calloc(orbit.scene.object_count, sizeof *objects);
    assert_non_null(objects);
    for (uint32_t t = 0; t < 20000u; t += 2500u) {
        tarn_scene posed;
        assert_int_equal(tarn_scene_pose(&orbit.scene, t, &posed, objects), TARN_OK);
        const double worst = largest_coordinate_error(&posed, water_object(&posed), orbit.width, orbit.height);
        if (!(worst < COORDINATE_TOLERANCE)) fail_msg("pond-orbit at %u ms: %.3g repeats off", t, worst);
    }
    free(objects);
    tarn_scene_free(&orbit);
}

/* The pond's water turned 30 degrees about x, scaled 2.5 and moved, then seen from
 * below its plane. */
static void test_a_turned_scaled_plane_from_either_side(void **state)
{
    (void)state;
    tarn_loaded_scene pond;
    load("scenes/pond.json", &pond);
    tarn_object *water = (tarn_object *)water_object(&pond.scene);
    const double c = cos(acos(-1.0) / 6), s = sin(acos(-1.0) / 6);
    const double rows[3][3] = {{1, 0, 0}, {0, c, -s}, {0, s, c}};
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++) water->rotation[r][k] = (tarn_q16)lround(rows[r][k] * 65536);
    water->scale = 5 * 65536 / 2;
    water->position.y -= 65536;
    double worst = largest_coordinate_error(&pond.scene, water, pond.width, pond.height);
    print_message("turned and scaled: within %.3g repeats\n", worst);
    assert_true(worst < COORDINATE_TOLERANCE);
    pond.scene.camera.position.y = water->position.y - 3 * 65536; /* below it, looking up through it */
    pond.scene.camera.target.y = water->position.y + 65536;
    worst = largest_coordinate_error(&pond.scene, water, pond.width, pond.height);
    print_message("from below: within %.3g repeats\n", worst);
    assert_true(worst < COORDINATE_TOLERANCE);
    tarn_scene_free(&pond);
}

/* The eye on the plane sees it edge on; a map that reaches past Q16.16 at the eye
 * would wrap: neither is used, and the triangles interpolate instead. */
static void test_a_plane_out_of_range_is_not_used(void **state)
{
    (void)state;
    tarn_loaded_scene pond;
    load("scenes/pond.json", &pond);
    const tarn_object *water = water_object(&pond.scene);
    tarn_uv_plane plane = *water->mesh->plane;
    tarn_mesh mesh = *water->mesh;
    mesh.plane = &plane;
    tarn_object object = *water;
    object.mesh = &mesh;
    assert_true(frame_plane(&pond.scene, &object, pond.width, pond.height).holds);
    plane.uv_origin.u = INT32_MAX; /* the map at the eye passes 2^15 repeats */
    plane.uv_gradient[0][0] = (1 << 24) - 1;
    plane.uv_gradient_bits = 0;
    assert_false(frame_plane(&pond.scene, &object, pond.width, pond.height).holds);
    plane = *water->mesh->plane;
    pond.scene.camera.position.y = water->position.y; /* the eye on the water's plane */
    assert_false(frame_plane(&pond.scene, &object, pond.width, pond.height).holds);
    tarn_scene_free(&pond);
}

/* A gradient past 2^24, or more fraction bits than the core's products allow, is
 * refused with the scene. */
static void test_the_scene_check_refuses_a_plane_out_of_its_ranges(void **state)
{
    (void)state;
    tarn_loaded_scene pond;
    load("scenes/pond.json", &pond);
    const tarn_object *water = water_object(&pond.scene);
    tarn_mesh_buffer *buffer = &pond.meshes[water - pond.scene.objects];
    tarn_frame_config config = {pond.width, pond.height, tarn_quality_default(), 0};
    assert_int_equal(test_render_status(&pond.scene, &config), TARN_OK);
    buffer->plane->uv_gradient[1][2] = 1 << 24;
    assert_int_equal(test_render_status(&pond.scene, &config), TARN_ERR_SCENE);
    buffer->plane->uv_gradient[1][2] = 0;
    buffer->plane->uv_gradient_bits = TARN_UV_PLANE_GRADIENT_BITS_MAX + 1u;
    assert_int_equal(test_render_status(&pond.scene, &config), TARN_ERR_SCENE);
    tarn_scene_free(&pond);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_the_loader_finds_flat_water_only),
        cmocka_unit_test(test_a_mesh_that_is_not_flat_has_no_plane),
        cmocka_unit_test(test_coordinates_match_the_reference),
        cmocka_unit_test(test_a_moving_camera_is_followed),
        cmocka_unit_test(test_a_turned_scaled_plane_from_either_side),
        cmocka_unit_test(test_a_plane_out_of_range_is_not_used),
        cmocka_unit_test(test_the_scene_check_refuses_a_plane_out_of_its_ranges),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
