/* test_firmware_sweep.c: what a board's sweep (`make firmware-sweep`,
 * firmware/sweep_main.c) reports equals what the host's core renders.
 *
 * The run is found in $SWEEP_DIR, or build/firmware-sweep-check/qemu-m0, where
 * tests/check_firmware_sweep.sh (run by `make test`) leaves it; without a run the
 * test is skipped. firmware.conf names the scene, the bake flags and the points
 * file; report.txt must hold one `point` line per point, in order, each with
 * status=ok, the working memory tarn_frame_memory_bytes gives, and the checksum the
 * host computes (tarn_checksum_pixel summed over its own render of the scene at the
 * same size, quality and time, 1000 ms); points whose images differ must have
 * different checksums. Then the `sweep` line, with the point count. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "bake_points.h"
#include "cli_options.h"
#include "core_render.h"
#include "firmware_conf.h"
#include "image_checksum.h"
#include "scene_load.h"
#include "static_view.h"
#include "tarn/tarn_checksum.h"

#define SWEEP_DIR_DEFAULT "build/firmware-sweep-check/qemu-m0"
#define SWEEP_TIME_MS 1000u /* FW_TIME_1 */

/* The `point index=I ...` line of the report, or NULL. */
static const char *point_line(const char *report, size_t index)
{
    char prefix[48];
    int n = snprintf(prefix, sizeof prefix, "point index=%zu ", index);
    for (const char *line = report; line != NULL && *line != '\0';) {
        if (strncmp(line, prefix, (size_t)n) == 0) return line;
        line = strchr(line, '\n');
        if (line) line++;
    }
    return NULL;
}

/* The value of ` KEY=` in one line, as text up to the next space or newline. */
static void field(const char *line, const char *key, char *out, size_t size)
{
    char pattern[64];
    snprintf(pattern, sizeof pattern, " %s=", key);
    const char *end_of_line = strchr(line, '\n');
    const char *at = strstr(line, pattern);
    if (at == NULL || (end_of_line && at > end_of_line)) fail_msg("no %s in: %.200s", key, line);
    at += strlen(pattern);
    size_t n = strcspn(at, " \n");
    if (n >= size) n = size - 1;
    memcpy(out, at, n);
    out[n] = '\0';
}

static void test_sweep_matches_host(void **state)
{
    (void)state;
    const char *dir = getenv("SWEEP_DIR") && *getenv("SWEEP_DIR") ? getenv("SWEEP_DIR") : SWEEP_DIR_DEFAULT;
    char path[1024], scene_path[512], bake_flags[512], points_path[512], board[64], program[16];
    snprintf(path, sizeof path, "%s/firmware.conf", dir);
    char *conf = firmware_read_file(path, NULL);
    snprintf(path, sizeof path, "%s/report.txt", dir);
    char *report = firmware_read_file(path, NULL);
    if (conf == NULL || report == NULL) {
        print_message("no sweep in %s: tests/check_firmware_sweep.sh runs one (make test does it)\n", dir);
        free(conf);
        free(report);
        skip();
    }
    firmware_conf_value(scene_path, sizeof scene_path, conf, "scene");
    firmware_conf_value(bake_flags, sizeof bake_flags, conf, "bake_flags");
    firmware_conf_value(points_path, sizeof points_path, conf, "points");
    firmware_conf_value(board, sizeof board, conf, "board");
    firmware_conf_value(program, sizeof program, conf, "program");
    free(conf);
    if (strcmp(program, "sweep") != 0) fail_msg("%s/firmware.conf: program=%s, expected sweep", dir, program);
    print_message("%s", report);

    tarn_loaded_scene scene;
    tarn_error err;
    if (tarn_scene_load(scene_path, &scene, &err) != 0) fail_msg("%s", err.message);
    tarn_frame_config config = firmware_bake_config(scene_path, bake_flags, &scene, SWEEP_TIME_MS, NULL);
    tarn_bake_points points;
    if (tarn_bake_points_load(points_path, &config.quality, &points, &err) != 0) fail_msg("%s", err.message);

    const size_t pixels = (size_t)config.width * config.height;
    uint8_t *images = malloc(3 * pixels * points.count);
    uint32_t *sums = malloc(points.count * sizeof *sums);
    assert_true(images != NULL && sums != NULL);
    for (size_t i = 0; i < points.count; i++) {
        const char *line = point_line(report, i);
        if (line == NULL) fail_msg("%s/report.txt: no line for point %zu", dir, i);
        char value[96];
        field(line, "status", value, sizeof value);
        if (strcmp(value, "ok") != 0) fail_msg("point %zu: status=%s", i, value);
        tarn_frame_config point = config;
        point.quality = points.qualities[i];
        field(line, "memory_bytes", value, sizeof value);
        assert_int_equal(strtoul(value, NULL, 10), tarn_static_memory_bytes(&point, &scene.scene, &config));
        field(line, "insn_per_pixel", value, sizeof value);
        unsigned long per_pixel = strtoul(value, NULL, 10);
        field(line, "frame_insn", value, sizeof value);
        unsigned long long frame = strtoull(value, NULL, 10);
        assert_true(per_pixel > 0);
        assert_int_equal(per_pixel, (frame + pixels / 2) / pixels);
        field(line, "checksum", value, sizeof value);
        unsigned long board_sum = strtoul(value, NULL, 16);
        uint8_t *rgb = images + 3 * pixels * i;
        if (tarn_core_render(&scene.scene, &point, rgb, NULL, &err) != 0) fail_msg("%s", err.message);
        sums[i] = tarn_image_checksum(rgb, point.width, point.height);
        print_message("point %zu (%s:%u): board %08lx, host %08x\n", i, points.path, points.lines[i], board_sum,
                      sums[i]);
        assert_int_equal(board_sum, sums[i]);
    }
    assert_null(point_line(report, points.count)); /* no more points than the file's */
    size_t differing = 0;
    for (size_t i = 0; i < points.count; i++)
        for (size_t j = i + 1; j < points.count; j++) {
            if (memcmp(images + 3 * pixels * i, images + 3 * pixels * j, 3 * pixels) == 0) continue;
            differing++;
            if (sums[i] == sums[j]) fail_msg("points %zu and %zu differ in image, not in checksum", i, j);
        }
    print_message("%zu pairs of points render different images\n", differing);

    char expected[256];
    snprintf(expected, sizeof expected, "sweep board=%s scene=", board);
    const char *last = strstr(report, expected);
    if (last == NULL) fail_msg("%s/report.txt: no '%s' line", dir, expected);
    char value[64];
    field(last, "points", value, sizeof value);
    assert_int_equal(strtoul(value, NULL, 10), points.count);
    snprintf(expected, sizeof expected, " size=%ux%u ", config.width, config.height);
    assert_non_null(strstr(last, expected));

    free(images);
    free(sums);
    tarn_bake_points_free(&points);
    tarn_scene_free(&scene);
    free(report);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sweep_matches_host),
    };
    return cmocka_run_group_tests_name("firmware sweep", tests, NULL, NULL);
}
