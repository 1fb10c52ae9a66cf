/* test_firmware.c: what each emulated board sent its panel equals the host's integer
 * render, byte for byte, at each of three times.
 *
 * For every board run found in build/firmware/ (made by `make firmware-run`, which
 * `make test` runs first): build/firmware/BOARD for a board's first scene,
 * build/firmware/BOARD@SCENE for each of its others. firmware.conf names the scene,
 * the bake flags, the animation times and the dither; panel.stream is the byte
 * stream the board wrote (ST7789 commands and data, tarn_panel.h) and report.txt its
 * report line. The stream is replayed into the host panel emulator; the picture as
 * each frame's last pixel lands is compared with the host's render of the same
 * scene, quality and time (through the same backdrop for a bake with still water,
 * whose frames the host draws the same way), converted with tarn_rgb565. The
 * emulator must also have ignored nothing: no early command, no unknown command, no
 * stray data. */
#include <dirent.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <cmocka.h>

#include "cli_options.h"
#include "backdrop.h"
#include "core_render.h"
#include "firmware_conf.h"
#include "panel_emulator.h"
#include "panel_stream.h"
#include "scene_load.h"
#include "tarn/tarn_panel.h"

#define FIRMWARE_DIR "build/firmware"
#define RUNS_MAX 32
#define TIMES 3

typedef struct {
    char board[64];
    char scene[256];
    char label[64];
    char bake_flags[256];
    uint32_t times[TIMES];
    int dither;
} firmware_conf;

/* The conf of the run in FIRMWARE_DIR/run: the board named by the run's directory
 * (BOARD, or BOARD@SCENE for the board's other scenes), and three distinct times. */
static void read_conf(const char *run, firmware_conf *conf)
{
    char path[512], value[64];
    snprintf(path, sizeof path, FIRMWARE_DIR "/%s/firmware.conf", run);
    char *text = firmware_read_file(path, NULL);
    if (text == NULL) fail_msg("%s: cannot read it", path);
    memset(conf, 0, sizeof *conf);
    firmware_conf_value(conf->board, sizeof conf->board, text, "board");
    firmware_conf_value(conf->scene, sizeof conf->scene, text, "scene");
    firmware_conf_value(conf->label, sizeof conf->label, text, "label");
    firmware_conf_value(conf->bake_flags, sizeof conf->bake_flags, text, "bake_flags");
    firmware_conf_value(value, sizeof value, text, "times");
    unsigned t[TIMES];
    char end;
    if (sscanf(value, "%u,%u,%u%c", &t[0], &t[1], &t[2], &end) != TIMES || t[0] == t[1] || t[1] == t[2] ||
        t[0] == t[2])
        fail_msg("%s: times: expected three distinct times T0,T1,T2 in ms, got '%s'", path, value);
    for (unsigned i = 0; i < TIMES; i++) conf->times[i] = t[i];
    firmware_conf_value(value, sizeof value, text, "dither");
    conf->dither = strcmp(value, "1") == 0;
    free(text);
    size_t board_length = strcspn(run, "@");
    if (strlen(conf->board) != board_length || strncmp(conf->board, run, board_length) != 0 ||
        conf->scene[0] == '\0')
        fail_msg("%s: expected board=%.*s and a scene", path, (int)board_length, run);
}

/* The emulator behind a transport that photographs the picture as soon as each
 * frame's last pixel has arrived. */
typedef struct {
    tarn_panel_emulator emulator;
    tarn_panel_transport inner;
    uint32_t frame_pixels;
    uint16_t *pictures[TIMES]; /* the picture after (i + 1) * frame_pixels pixels, NULL until then */
    unsigned taken;
    size_t picture_words;
} recording_panel;

static int record_command(void *user, uint8_t command)
{
    recording_panel *p = user;
    return p->inner.command(p->inner.user, command);
}

static int record_data(void *user, const uint8_t *bytes, size_t count)
{
    recording_panel *p = user;
    int status = p->inner.data(p->inner.user, bytes, count);
    if (p->taken < TIMES && p->emulator.counts.pixels_written >= (p->taken + 1u) * p->frame_pixels) {
        uint16_t *picture = malloc(p->picture_words * sizeof *picture);
        assert_non_null(picture);
        tarn_panel_emulator_image(&p->emulator, picture);
        p->pictures[p->taken++] = picture;
    }
    return status;
}

static int record_reset(void *user, int asserted)
{
    recording_panel *p = user;
    return p->inner.reset(p->inner.user, asserted);
}

static int record_delay(void *user, uint16_t milliseconds)
{
    recording_panel *p = user;
    return p->inner.delay_ms(p->inner.user, milliseconds);
}

static time_t modified(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? st.st_mtime : (time_t)-1;
}

/* Compares the panel's picture (panel_width wide) with the host render of the frame
 * at `time_ms`; prints and counts the pixels that differ. */
static size_t compare_frame(const firmware_conf *conf, const tarn_loaded_scene *scene,
                            tarn_frame_config config, uint32_t time_ms, const uint16_t *picture,
                            uint16_t panel_width)
{
    tarn_error err;
    size_t pixels = (size_t)config.width * config.height, differ = 0;
    uint8_t *rgb = malloc(3 * pixels);
    assert_non_null(rgb);
    config.time_ms = time_ms;
    if (tarn_core_render(&scene->scene, &config, rgb, NULL, &err) != 0)
        fail_msg("%s: host render: %s", conf->board, err.message);
    for (uint16_t y = 0; y < config.height; y++)
        for (uint16_t x = 0; x < config.width; x++) {
            const uint8_t *p = rgb + 3 * ((size_t)y * config.width + x);
            uint16_t want = tarn_rgb565(((uint32_t)p[0] << 16) | ((uint32_t)p[1] << 8) | p[2], x, y,
                                        conf->dither);
            uint16_t got = picture[(size_t)y * panel_width + x];
            if (want != got && differ++ < 5)
                print_message("%s %s t=%u: pixel (%u, %u): board 0x%04x, host 0x%04x\n", conf->board,
                              conf->label, time_ms, x, y, got, want);
        }
    free(rgb);
    return differ;
}

static void test_board_matches_host(void **state)
{
    const char *run = *state;
    char path[512];
    firmware_conf conf;
    read_conf(run, &conf);
    const char *board = conf.board;

    snprintf(path, sizeof path, FIRMWARE_DIR "/%s/report.txt", run);
    char *report = firmware_read_file(path, NULL);
    if (report == NULL) fail_msg("%s: no report: run make firmware-run BOARD=%s", path, board);
    char expected[160];
    snprintf(expected, sizeof expected, "target board=%s scene=%s ", board, conf.label);
    if (strncmp(report, expected, strlen(expected)) != 0) fail_msg("%s: expected '%s...', got %s", path, expected, report);
    print_message("%s", report);
    free(report);

    char conf_path[512];
    snprintf(conf_path, sizeof conf_path, FIRMWARE_DIR "/%s/firmware.conf", run);
    snprintf(path, sizeof path, FIRMWARE_DIR "/%s/panel.stream", run);
    if (modified(path) < modified(conf_path))
        fail_msg("%s is older than its build: run make firmware-run BOARD=%s", path, board);

    tarn_loaded_scene scene;
    tarn_error err;
    if (tarn_scene_load(conf.scene, &scene, &err) != 0) fail_msg("%s", err.message);
    tarn_backdrop_request backdrop;
    tarn_frame_config config = firmware_bake_config(conf.scene, conf.bake_flags, &scene, 0, &backdrop);
    const int still_water = backdrop.kind == TARN_BACKDROP_STILL;
    /* over still water, the host draws through the same backdrop; every other
     * bake draws the scene's frame itself */
    tarn_backdrop_scene still;
    if (still_water && tarn_backdrop_scene_make(&scene.scene, &config, backdrop, 0, &still, &err) != 0)
        fail_msg("%s: %s", conf.scene, err.message);
    tarn_loaded_scene drawn = scene;
    if (still_water) drawn.scene = still.water.scene;

    recording_panel *panel = calloc(1, sizeof *panel);
    assert_non_null(panel);
    assert_int_equal(tarn_panel_emulator_init(&panel->emulator, TARN_PANEL_ST7789_240X240, 0), 0);
    panel->inner = tarn_panel_emulator_transport(&panel->emulator);
    panel->frame_pixels = (uint32_t)config.width * config.height;
    uint16_t width = tarn_panel_emulator_width(&panel->emulator);
    panel->picture_words = (size_t)width * tarn_panel_emulator_height(&panel->emulator);
    tarn_panel_transport transport = {panel, record_command, record_data, record_reset, record_delay};
    if (tarn_panel_stream_decode_file(path, &transport, &err) != 0) fail_msg("%s", err.message);

    const tarn_panel_emulator_counts *c = &panel->emulator.counts;
    print_message("%s: %u commands, %u data bytes, %u pixels, %u ms of delays\n", run, c->commands,
                  c->data_bytes, c->pixels_written, c->delay_ms);
    assert_int_equal(c->pixels_written, TIMES * panel->frame_pixels);
    assert_int_equal(panel->taken, TIMES);
    assert_int_equal(c->pixels_outside_ram, 0);
    assert_int_equal(c->pixel_bytes_ignored, 0);
    assert_int_equal(c->data_ignored, 0);
    assert_int_equal(c->parameters_incomplete, 0);
    assert_int_equal(c->unknown_commands, 0);
    assert_int_equal(c->commands_too_early, 0);
    assert_true(config.width <= width);

    /* Each time's picture equals the host's frame at that time: where the scene
     * moves, the pictures differ between times as the host's do, which shows the
     * clock reached the firmware (a scene where nothing moves, like pond-opaque,
     * draws one picture at every time, on the board as on the host). */
    size_t differ[TIMES], differ_total = 0;
    for (unsigned i = 0; i < TIMES; i++) {
        differ[i] = compare_frame(&conf, &drawn, config, conf.times[i], panel->pictures[i], width);
        differ_total += differ[i];
        print_message("%s: %s %ux%u at %u ms: %zu pixels differ from the host\n", run, conf.scene, config.width,
                      config.height, conf.times[i], differ[i]);
        if (i == 0) continue;
        size_t changed = 0;
        for (size_t k = 0; k < panel->picture_words; k++) changed += panel->pictures[i - 1][k] != panel->pictures[i][k];
        print_message("%s: %zu pixels change from %u ms to %u ms\n", run, changed, conf.times[i - 1], conf.times[i]);
    }
    for (unsigned i = 0; i < TIMES; i++) free(panel->pictures[i]);
    free(panel);
    if (still_water) tarn_backdrop_scene_free(&still);
    tarn_scene_free(&scene);
    assert_int_equal(differ_total, 0);
}

static void test_no_board_has_run(void **state)
{
    (void)state;
    print_message("no board runs in " FIRMWARE_DIR ": make firmware-run (make test does it)\n");
    skip();
}

/* The runs (a directory for each board and scene) whose build says they run under an
 * emulator (firmware.conf has emulated=1). */
static size_t find_runs(char names[][64], size_t max)
{
    DIR *dir = opendir(FIRMWARE_DIR);
    size_t n = 0;
    if (dir == NULL) return 0;
    for (struct dirent *e; (e = readdir(dir)) != NULL && n < max;) {
        char path[512], value[8];
        if (e->d_name[0] == '.' || strlen(e->d_name) >= 64) continue;
        snprintf(path, sizeof path, FIRMWARE_DIR "/%s/firmware.conf", e->d_name);
        char *text = firmware_read_file(path, NULL);
        if (text == NULL) continue;
        firmware_conf_value(value, sizeof value, text, "emulated");
        char program[16];
        firmware_conf_value(program, sizeof program, text, "program"); /* a sweep streams no frames */
        free(text);
        if (strcmp(value, "1") == 0 && strcmp(program, "sweep") != 0)
            memcpy(names[n++], e->d_name, strlen(e->d_name) + 1);
    }
    closedir(dir);
    firmware_sort_board_names(names, n); /* a stable order */
    return n;
}

int main(void)
{
    static char runs[RUNS_MAX][64];
    static char names[RUNS_MAX][96];
    static const char suffix[] = " matches the host";
    static void *states[RUNS_MAX];
    struct CMUnitTest tests[RUNS_MAX];
    size_t n = find_runs(runs, RUNS_MAX);
    for (size_t i = 0; i < n; i++) {
        memcpy(names[i], runs[i], 64);
        memcpy(names[i] + strlen(runs[i]), suffix, sizeof suffix);
        states[i] = runs[i];
        tests[i] = (struct CMUnitTest){names[i], test_board_matches_host, NULL, NULL, states[i]};
    }
    if (n == 0) {
        tests[0] = (struct CMUnitTest){"no board has run", test_no_board_has_run, NULL, NULL, NULL};
        n = 1;
    }
    return _cmocka_run_group_tests("firmware", tests, n, NULL, NULL);
}
