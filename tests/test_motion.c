/* test_motion.c: moving scenes (tarn_motion.h). The core's integer pose agrees with
 * the float reference's double one; key curves pass through their keys, hold or
 * wrap at their ends and run on smoothly; a frame of a moving scene is the frame of
 * its pose, in memory aligned only to 4 bytes; motion that breaks the rules is
 * refused. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "frame_render.h"
#include "ref_motion.h"
#include "scene_load.h"
#include "tarn/tarn_motion.h"

static const char *const moving_scenes[] = { "scenes/pond-orbit.json", "scenes/lake-drift.json" };
#define MOVING_SCENES (sizeof moving_scenes / sizeof moving_scenes[0])
static const uint32_t times_ms[] = { 0u, 1u, 1234u, 4000u, 5000u, 7999u, 8000u, 123457u, 2147483648u, 4294967295u };
#define TIMES (sizeof times_ms / sizeof times_ms[0])

static void load(const char *path, tarn_loaded_scene *out)
{
    tarn_error err;
    if (tarn_scene_load(path, out, &err) != 0) fail_msg("%s", err.message);
}

static int32_t distance_q16(const tarn_vec3 *a, const tarn_vec3 *b)
{
    const int32_t d[3] = { abs(a->x - b->x), abs(a->y - b->y), abs(a->z - b->z) };
    return d[0] > d[1] ? (d[0] > d[2] ? d[0] : d[2]) : (d[1] > d[2] ? d[1] : d[2]);
}

/* The core's pose of every moving part against the reference's, in Q16.16 units. */
static void test_core_pose_is_the_reference_pose(void **state)
{
    (void)state;
    for (size_t s = 0; s < MOVING_SCENES; s++) {
        tarn_loaded_scene loaded;
        load(moving_scenes[s], &loaded);
        assert_true(tarn_scene_moves(&loaded.scene));
        const uint16_t n = loaded.scene.object_count;
        tarn_object *core_objects = calloc(n, sizeof *core_objects), *ref_objects = calloc(n, sizeof *ref_objects);
        assert_true(core_objects != NULL && ref_objects != NULL);
        for (size_t t = 0; t < TIMES; t++) {
            tarn_scene core, ref;
            assert_int_equal(tarn_scene_pose(&loaded.scene, times_ms[t], &core, core_objects), TARN_OK);
            tarn_ref_scene_pose(&loaded.scene, times_ms[t], &ref, ref_objects);
            const int32_t camera = distance_q16(&core.camera.position, &ref.camera.position);
            const int32_t target = distance_q16(&core.camera.target, &ref.camera.target);
            const int32_t light = distance_q16(&core.light.direction, &ref.light.direction);
            if (camera > 1 || target > 1 || light > 2)
                fail_msg("%s at %u ms: the core's camera is %d, its target %d and its light %d units of 2^-16 "
                         "from the reference's (at most 1, 1 and 2)", moving_scenes[s], times_ms[t], camera, target,
                         light);
            for (uint16_t i = 0; i < n; i++) {
                const int32_t moved = distance_q16(&core_objects[i].position, &ref_objects[i].position);
                int32_t turned = 0;
                for (int r = 0; r < 3; r++)
                    for (int c = 0; c < 3; c++) {
                        const int32_t d = abs(core_objects[i].rotation[r][c] - ref_objects[i].rotation[r][c]);
                        turned = d > turned ? d : turned;
                    }
                if (moved > 1 || turned > 2)
                    fail_msg("%s at %u ms: objects[%u] is %d units of 2^-16 from the reference's place and its "
                             "rotation %d (at most 1 and 2)", moving_scenes[s], times_ms[t], i, moved, turned);
                assert_null(core_objects[i].motion);
            }
            assert_null(core.camera_path);
            assert_null(core.static_view);
        }
        free(core_objects);
        free(ref_objects);
        tarn_scene_free(&loaded);
    }
}

/* A curve of one channel over `keys` (ms, value in units). */
typedef struct {
    uint32_t times[4];
    tarn_q16 values[4];
    tarn_key_curve curve;
} one_channel;

static void one_channel_make(one_channel *c, const uint32_t times[4], const double values[4], uint16_t count,
                             uint32_t loop_ms)
{
    for (int i = 0; i < count; i++) {
        c->times[i] = times[i];
        c->values[i] = (tarn_q16)(values[i] * 65536.0);
    }
    tarn_key_curve curve = { c->times, c->values, count, 1, loop_ms };
    c->curve = curve;
}

/* A scene of nothing but a camera on the curve's keys: the curve read through the
 * public pose, so no internal function is needed. */
static tarn_q16 curve_at(const one_channel *c, uint32_t time_ms)
{
    /* the camera's x follows the curve; target and the other channels are fixed */
    static uint32_t times[4];
    static tarn_q16 values[4 * 6];
    for (int i = 0; i < c->curve.key_count; i++) {
        times[i] = c->times[i];
        const tarn_q16 key[6] = { c->values[i], 65536, 5 * 65536, 0, 0, 0 };
        memcpy(&values[6 * i], key, sizeof key);
    }
    tarn_camera_path path;
    memset(&path, 0, sizeof path);
    path.kind = TARN_CAMERA_KEYS;
    tarn_key_curve keys = { times, values, c->curve.key_count, 6, c->curve.loop_ms };
    path.keys = keys;
    tarn_scene scene;
    memset(&scene, 0, sizeof scene);
    scene.camera.fov_y_degrees = 60 * 65536;
    scene.camera.near = 6554;
    scene.camera.far = 100 * 65536;
    scene.camera_path = &path;
    tarn_scene posed;
    assert_int_equal(tarn_scene_pose(&scene, time_ms, &posed, NULL), TARN_OK);
    return posed.camera.position.x;
}

static void test_curves_pass_through_keys_and_hold_or_wrap(void **state)
{
    (void)state;
    static const uint32_t times[4] = { 1000u, 2000u, 4000u, 5000u };
    static const double values[4] = { 1.0, -2.0, 3.5, 0.25 };
    for (uint32_t loop = 0; loop <= 6000u; loop += 6000u) {
        one_channel c;
        one_channel_make(&c, times, values, 4, loop);
        for (int i = 0; i < 4; i++) assert_int_equal(curve_at(&c, times[i]), c.values[i]);
        if (loop == 0u) { /* clamped: the ends held */
            assert_int_equal(curve_at(&c, 0u), c.values[0]);
            assert_int_equal(curve_at(&c, 4294967295u), c.values[3]);
        } else { /* a loop later, the same; across the wrap, no jump */
            for (int i = 0; i < 4; i++) assert_int_equal(curve_at(&c, times[i] + 3u * loop), c.values[i]);
            const int32_t before = curve_at(&c, 5999u), after = curve_at(&c, 6000u);
            assert_true(abs(before - after) < 65536 / 100);
        }
        /* smooth: no step between neighbouring milliseconds larger than the curve's
         * steepest slope could make (a few hundredths of a unit a millisecond) */
        for (uint32_t t = 0; t < 7000u; t++) {
            const int32_t step = abs(curve_at(&c, t + 1u) - curve_at(&c, t));
            if (step > 65536 / 100) fail_msg("loop %u: the curve jumps by %d/65536 from %u to %u ms", loop, step, t, t + 1u);
        }
        /* the float reference's curve, to a unit of 2^-16 */
        for (uint32_t t = 0; t < 7000u; t += 37u) {
            double v;
            tarn_ref_key_curve_at(&c.curve, t, &v);
            const double got = curve_at(&c, t) / 65536.0;
            if (got - v > 1.5 / 65536 || v - got > 1.5 / 65536)
                fail_msg("loop %u at %u ms: the core's curve gives %.6f, the reference's %.6f", loop, t, got, v);
        }
    }
}

/* The frame of a moving scene is the frame of the scene the pose gives, byte for
 * byte, and its memory need only be 4-byte aligned. */
static void test_frame_is_its_pose(void **state)
{
    (void)state;
    for (size_t s = 0; s < MOVING_SCENES; s++) {
        tarn_loaded_scene loaded;
        load(moving_scenes[s], &loaded);
        tarn_object *objects = calloc(loaded.scene.object_count, sizeof *objects);
        assert_non_null(objects);
        for (uint32_t time = 0; time <= 5000u; time += 2500u) {
            tarn_frame_config config = { 96, 96, tarn_quality_preset(TARN_PRESET_FAST), time };
            tarn_scene posed;
            assert_int_equal(tarn_scene_pose(&loaded.scene, time, &posed, objects), TARN_OK);
            uint8_t *moving = test_render_rgb(&loaded.scene, &config, moving_scenes[s]);
            uint8_t *still = test_render_rgb(&posed, &config, moving_scenes[s]);
            if (memcmp(moving, still, 3u * 96u * 96u) != 0)
                fail_msg("%s at %u ms: the frame differs from its pose's", moving_scenes[s], time);
            free(moving);
            free(still);
            const size_t bytes = tarn_frame_memory_bytes(&config, &loaded.scene);
            assert_true(bytes > tarn_frame_memory_bytes(&config, &posed)); /* room for the pose */
            uint32_t *memory = malloc(bytes + 8u);
            assert_non_null(memory);
            /* 4 bytes past an 8-byte boundary: the pose must align itself */
            assert_int_equal(tarn_render_frame(&loaded.scene, &config, memory + 1, bytes, NULL, NULL), TARN_OK);
            assert_int_equal(tarn_render_frame(&loaded.scene, &config, memory + 1, bytes - 1u, NULL, NULL),
                             TARN_ERR_MEMORY);
            free(memory);
        }
        free(objects);
        tarn_scene_free(&loaded);
    }
}

static void test_bad_motion_is_refused(void **state)
{
    (void)state;
    tarn_loaded_scene loaded;
    load("scenes/pond-orbit.json", &loaded);
    tarn_frame_config config = { 64, 64, tarn_quality_preset(TARN_PRESET_FAST), 0 };
    assert_int_equal(test_render_status(&loaded.scene, &config), TARN_OK);
    tarn_object *moving = NULL;
    for (uint16_t i = 0; i < loaded.scene.object_count && moving == NULL; i++)
        if (loaded.objects[i].motion != NULL) moving = &loaded.objects[i];
    assert_non_null(moving);
    tarn_object_motion m = *moving->motion;
    moving->motion = &m;
    m.spin_period_ms = 1000u;
    m.spin_axis.x = 65536;
    m.spin_axis.y = 65536; /* not a unit vector */
    assert_int_equal(test_render_status(&loaded.scene, &config), TARN_ERR_SCENE);
    m.spin_axis.y = 0;
    assert_int_equal(test_render_status(&loaded.scene, &config), TARN_OK);
    const uint32_t times[2] = { 500u, 500u };
    const tarn_q16 values[6] = { 0 };
    tarn_key_curve path = { times, values, 2, 3, 0 };
    m.path = path; /* times not ascending */
    assert_int_equal(test_render_status(&loaded.scene, &config), TARN_ERR_SCENE);
    const uint32_t ascending[2] = { 0u, 500u };
    m.path.times_ms = ascending;
    assert_int_equal(test_render_status(&loaded.scene, &config), TARN_OK);
    m.path.loop_ms = 500u; /* the loop no longer than the keys */
    assert_int_equal(test_render_status(&loaded.scene, &config), TARN_ERR_SCENE);
    m.path.loop_ms = 0u;
    m.path.channels = 2u;
    assert_int_equal(test_render_status(&loaded.scene, &config), TARN_ERR_SCENE);
    m.path.channels = 3u;
    tarn_camera_path orbit = *loaded.scene.camera_path;
    loaded.scene.camera_path = &orbit;
    orbit.period_ms = 0u;
    assert_int_equal(test_render_status(&loaded.scene, &config), TARN_ERR_SCENE);
    orbit.period_ms = 1u;
    orbit.kind = 3u;
    assert_int_equal(test_render_status(&loaded.scene, &config), TARN_ERR_SCENE);
    tarn_scene_free(&loaded);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_core_pose_is_the_reference_pose),
        cmocka_unit_test(test_curves_pass_through_keys_and_hold_or_wrap),
        cmocka_unit_test(test_frame_is_its_pose),
        cmocka_unit_test(test_bad_motion_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
