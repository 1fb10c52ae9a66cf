/* The parts of tarn view that need no window: its clock, keys and knobs, scripts,
 * the camera the mouse turns, the files it watches, and --camera's text. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "camera_override.h"
#include "cli_run.h"
#include "view_camera.h"
#include "view_script.h"
#include "view_state.h"
#include "view_watch.h"

static tarn_view_state fresh_state(uint8_t fps)
{
    tarn_view_state s;
    const tarn_quality balanced = tarn_quality_default();
    tarn_view_state_init(&s, &balanced, TARN_PRESET_BALANCED, 0, fps);
    return s;
}

static void press(tarn_view_state *s, const char *key)
{
    const tarn_view_key *k = tarn_view_find_key(key);
    if (k == NULL) fail_msg("no key '%s'", key);
    tarn_view_press(s, k);
}

static void test_a_scripts_frames_keep_renders_clock(void **state)
{
    (void)state;
    tarn_view_state s = fresh_state(30);
    for (int k = 0; k < 3; k++) tarn_view_run_frame(&s);
    assert_int_equal(tarn_view_time_ms(&s), 100); /* floor(3 * 1000 / 30) */
    press(&s, "=");
    tarn_view_run_frame(&s);
    assert_int_equal(tarn_view_time_ms(&s), 166); /* two frames' worth at double speed */
    for (int k = 0; k < 8; k++) press(&s, "-");
    assert_int_equal(s.speed_log2, TARN_VIEW_SPEED_LOG2_MIN);
    tarn_view_run_ms(&s, 1600);
    assert_int_equal(tarn_view_time_ms(&s), 266); /* 1600 ms at 1/16 */
    press(&s, "space");
    tarn_view_run_ms(&s, 5000);
    assert_int_equal(tarn_view_time_ms(&s), 266);
    for (int k = 0; k < 20; k++) press(&s, "Left");
    assert_int_equal(tarn_view_time_ms(&s), 0);
    s.start_ms = UINT32_MAX - 10;
    press(&s, "Right");
    assert_int_equal(tarn_view_time_ms(&s), UINT32_MAX);
}

static void test_knob_keys_cycle_what_the_other_knobs_allow(void **state)
{
    (void)state;
    tarn_view_state s = fresh_state(30);
    char text[512];
    tarn_view_quality_text(&s, text, sizeof text);
    assert_string_equal(text, "balanced");
    press(&s, "b");
    assert_int_equal(s.quality.water_block, 2);
    tarn_view_quality_text(&s, text, sizeof text);
    assert_string_equal(text, "balanced, --water-block 2");
    press(&s, "B");
    press(&s, "B");
    assert_int_equal(s.quality.water_block, 1);
    s.quality.tile_size = 9; /* no block of 2 or 4 fits */
    press(&s, "B");
    assert_int_equal(s.quality.water_block, 1);
    assert_non_null(s.message);
    press(&s, "3");
    tarn_view_quality_text(&s, text, sizeof text);
    assert_string_equal(text, "exact");
    assert_null(s.message);
}

static void test_pictures_and_camera_keys(void **state)
{
    (void)state;
    tarn_view_state s = fresh_state(30);
    press(&s, "v");
    assert_int_equal(s.picture, TARN_VIEW_REFERENCE);
    press(&s, "v");
    press(&s, "v");
    assert_int_equal(s.picture, TARN_VIEW_CORE);
    tarn_view_drag(&s, 40, 1000);
    assert_false(tarn_view_own_camera(&s));
    assert_true(s.pitch_degrees <= 80.0);
    tarn_view_wheel(&s, 1000);
    assert_true(s.zoom > 0.04);
    press(&s, "r");
    assert_true(tarn_view_own_camera(&s));
    assert_null(tarn_view_find_key("NoSuchKey"));
}

static tarn_scene still_scene(void)
{
    tarn_scene scene;
    memset(&scene, 0, sizeof scene);
    scene.camera.position = (tarn_vec3){3 << 16, 2 << 16, 4 << 16};
    scene.camera.target = (tarn_vec3){1 << 16, 0, 0};
    scene.camera.fov_y_degrees = 60 << 16;
    scene.camera.near = 1 << 12;
    scene.camera.far = 100 << 16;
    return scene;
}

static void test_the_mouse_turns_the_camera_about_its_target(void **state)
{
    (void)state;
    const tarn_scene scene = still_scene();
    tarn_camera c;
    tarn_error err;
    assert_int_equal(tarn_view_camera(&scene, 0, 0, 0, 1.0, &c, &err), 0);
    assert_memory_equal(&c.position, &scene.camera.position, sizeof c.position);
    assert_int_equal(tarn_view_camera(&scene, 0, 180, 0, 1.0, &c, &err), 0);
    /* half a turn about the target at (1, 0, 0): x and z mirrored, height kept */
    assert_true(labs((long)c.position.x - (-65536L)) <= 1 && labs((long)c.position.z - (-4 * 65536L)) <= 1);
    assert_true(labs((long)c.position.y - (2 << 16)) <= 1);
    assert_int_equal(tarn_view_camera(&scene, 0, 0, 0, 0.5, &c, &err), 0);
    assert_true(labs((long)c.position.x - (2 << 16)) <= 1 && labs((long)c.position.z - (2 << 16)) <= 1);
    assert_int_equal(tarn_view_camera(&scene, 0, 0, 0, 1e5, &c, &err), -1);
    assert_non_null(strstr(err.message, "leave the world"));
}

static void test_a_camera_reads_back_from_its_text(void **state)
{
    (void)state;
    tarn_camera camera = still_scene().camera;
    camera.position = (tarn_vec3){-2147483647, 1, -65537};
    camera.fov_y_degrees = (tarn_q16)(59.3 * 65536);
    char text[TARN_CAMERA_TEXT_MAX];
    tarn_camera_override_text(&camera, text, sizeof text);
    tarn_camera_override o;
    tarn_error err;
    if (tarn_camera_override_parse(text, &o, &err) != 0) fail_msg("'%s': %s", text, err.message);
    assert_memory_equal(&o.position, &camera.position, sizeof o.position);
    assert_memory_equal(&o.target, &camera.target, sizeof o.target);
    assert_int_equal(o.fov_y_degrees, camera.fov_y_degrees);
    assert_int_equal(tarn_camera_override_parse("1,2,3:1,2,3", &o, &err), -1);
    assert_int_equal(tarn_camera_override_parse("1,2,3:4,5", &o, &err), -1);
    assert_int_equal(tarn_camera_override_parse("1,2,3:4,5,6:180", &o, &err), -1);
    assert_int_equal(tarn_camera_override_parse("1,2,40000:4,5,6", &o, &err), -1);
    assert_int_equal(tarn_camera_override_parse("1,2,3:4,5,6", &o, &err), 0);
    assert_int_equal(o.fov_y_degrees, 0);
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

static void test_scripts_load_or_name_the_line(void **state)
{
    (void)state;
    tarn_script script;
    tarn_error err;
    write_text(cli_in_folder("ok.txt"), "# a comment\n0 key Space\n\n2 drag -5 7 # trailing\n2 wheel -3\n3 screenshot\n"
                                        "3 wait-edit\n9 quit\n");
    if (tarn_script_load(cli_in_folder("ok.txt"), &script, &err) != 0) fail_msg("%s", err.message);
    assert_int_equal(script.count, 6);
    assert_int_equal(script.events[1].dx, -5);
    assert_int_equal(script.events[2].dy, -3);
    assert_non_null(tarn_script_take(&script, 0));
    assert_null(tarn_script_take(&script, 1));
    assert_non_null(tarn_script_take(&script, 2));
    tarn_script_free(&script);
    static const struct {
        const char *text, *message;
    } bad[] = {
        {"3 quit\n2 quit\n", "b.txt:2: expected a frame number"},
        {"0 jump\n", "b.txt:1: expected an event"},
        {"0 drag 5\n", "b.txt:1: expected drag DX DY"},
        {"0\n", "b.txt:1: expected an event"},
        {"0 screenshot now\n", "b.txt:1: expected nothing after"},
        {"x quit\n", "b.txt:1: expected a frame number"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        write_text(cli_in_folder("b.txt"), bad[k].text);
        assert_int_equal(tarn_script_load(cli_in_folder("b.txt"), &script, &err), -1);
        if (strstr(err.message, bad[k].message) == NULL)
            fail_msg("'%s' gave '%s', not '%s'", bad[k].text, err.message, bad[k].message);
    }
}

static void test_a_watch_sees_an_edit_in_place(void **state)
{
    (void)state;
    tarn_view_watch watch = {NULL, 0};
    write_text(cli_in_folder("s.json"), "{}");
    assert_int_equal(tarn_view_watch_set(&watch, cli_in_folder("s.json"), NULL), 0);
    assert_false(tarn_view_watch_changed(&watch));
    struct timespec pause = {0, 2000000};
    nanosleep(&pause, NULL);
    write_text(cli_in_folder("s.json"), "[]"); /* the same size */
    assert_true(tarn_view_watch_changed(&watch));
    assert_false(tarn_view_watch_changed(&watch));
    unlink(cli_in_folder("s.json"));
    assert_true(tarn_view_watch_changed(&watch));
    tarn_view_watch_free(&watch);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_scripts_frames_keep_renders_clock),
        cmocka_unit_test(test_knob_keys_cycle_what_the_other_knobs_allow),
        cmocka_unit_test(test_pictures_and_camera_keys),
        cmocka_unit_test(test_the_mouse_turns_the_camera_about_its_target),
        cmocka_unit_test(test_a_camera_reads_back_from_its_text),
        cmocka_unit_test_setup_teardown(test_scripts_load_or_name_the_line, cli_make_folder, cli_remove_folder),
        cmocka_unit_test_setup_teardown(test_a_watch_sees_an_edit_in_place, cli_make_folder, cli_remove_folder),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
