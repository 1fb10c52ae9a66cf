/* test_panel.c: the panel drivers against the panel emulator.
 *
 * tarn_rgb565 is checked for every channel value; the emulator's controller model
 * command by command; then a scene rendered through tarn_render_frame into each panel
 * model in each rotation, for tile sizes 8 to 64, must show on the emulated glass
 * exactly the frame tarn_core_render draws, converted with tarn_rgb565 - while a
 * wrong offset or MADCTL byte must not. The stream format round-trips a frame and
 * reports every malformation with its byte offset; a transport that fails stops
 * the tile and the frame. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "core_render.h"
#include "panel_emulator.h"
#include "panel_stream.h"
#include "scene_load.h"
#include "tarn/tarn_panel.h"

#define SCENE_PATH "scenes/effects/none.json"
#define POISON 0xF81Fu /* magenta: RAM the driver never wrote */

static const unsigned tile_sizes[] = {8, 16, 32, 64};

/* ---- RGB565 ---- */

/* round(value * levels / 255), with a division: the definition tarn_rgb565 must meet */
static unsigned rounded(unsigned value, unsigned levels)
{
    return (2u * value * levels + 255u) / 510u;
}

static unsigned channel(uint16_t pixel, unsigned which)
{
    static const unsigned shift[3] = {11, 5, 0}, mask[3] = {31, 63, 31};
    return (pixel >> shift[which]) & mask[which];
}

static const unsigned levels_of[3] = {31, 63, 31};

static void test_rgb565_rounds_every_value_to_nearest(void **state)
{
    (void)state;
    for (unsigned which = 0; which < 3; which++) {
        for (unsigned v = 0; v < 256; v++) {
            uint32_t others = (v * 0x9E3779B9u) & 0xFFFFFFu; /* the other channels vary too */
            uint32_t rgb = (others & ~(0xFFu << (16 - 8 * which))) | (v << (16 - 8 * which));
            for (unsigned p = 0; p < 16; p++) {
                uint16_t pixel = tarn_rgb565(rgb, (uint16_t)(p & 3), (uint16_t)(p >> 2), 0);
                assert_int_equal(channel(pixel, which), rounded(v, levels_of[which]));
            }
        }
    }
}

/* Each dithered channel is the exact value rounded down or up, and a 4x4 block
 * averages to within 1/16 of a step of it; the block is fixed to frame positions. */
static void test_rgb565_dither_stays_within_a_step(void **state)
{
    (void)state;
    for (unsigned which = 0; which < 3; which++) {
        unsigned levels = levels_of[which];
        for (unsigned v = 0; v < 256; v++) {
            uint32_t rgb = v << (16 - 8 * which);
            unsigned floor_exact = v * levels / 255u, ceil_exact = (v * levels + 254u) / 255u;
            long sum = 0;
            for (unsigned p = 0; p < 16; p++) {
                uint16_t x = (uint16_t)(p & 3), y = (uint16_t)(p >> 2);
                unsigned got = channel(tarn_rgb565(rgb, x, y, 1), which);
                assert_true(got == floor_exact || got == ceil_exact);
                assert_int_equal(tarn_rgb565(rgb, (uint16_t)(x + 4 * 37), (uint16_t)(y + 4 * 11), 1),
                                 tarn_rgb565(rgb, x, y, 1));
                sum += got;
            }
            long error = 255 * sum - 16L * (long)(v * levels); /* 255 * 16 * (mean - exact) */
            assert_true(error >= -255 && error <= 255);
        }
    }
    assert_int_equal(tarn_rgb565(0xFFFFFF, 3, 3, 1), 0xFFFF);
    assert_int_equal(tarn_rgb565(0x000000, 0, 0, 1), 0x0000);
}

/* ---- Presets ---- */

static void expect_preset(tarn_panel_model model, unsigned rotation, unsigned width,
                          unsigned height, unsigned column_offset, unsigned row_offset,
                          unsigned madctl)
{
    tarn_panel p = tarn_panel_preset(model, rotation);
    assert_int_equal(p.model, model);
    assert_int_equal(p.rotation, rotation & 3u);
    assert_int_equal(p.width, width);
    assert_int_equal(p.height, height);
    assert_int_equal(p.column_offset, column_offset);
    assert_int_equal(p.row_offset, row_offset);
    assert_int_equal(p.madctl, madctl);
}

/* The table of docs/panels.md. */
static void test_presets_match_the_documented_table(void **state)
{
    (void)state;
    expect_preset(TARN_PANEL_ST7789_240X240, 0, 240, 240, 0, 0, 0x00);
    expect_preset(TARN_PANEL_ST7789_240X240, 1, 240, 240, 0, 0, 0x60);
    expect_preset(TARN_PANEL_ST7789_240X240, 2, 240, 240, 0, 80, 0xC0);
    expect_preset(TARN_PANEL_ST7789_240X240, 3, 240, 240, 80, 0, 0xA0);
    expect_preset(TARN_PANEL_ST7789_240X240, 6, 240, 240, 0, 80, 0xC0); /* modulo 4 */
    expect_preset(TARN_PANEL_ST7789_240X320, 0, 240, 320, 0, 0, 0x00);
    expect_preset(TARN_PANEL_ST7789_240X320, 1, 320, 240, 0, 0, 0x60);
    expect_preset(TARN_PANEL_ST7789_240X320, 2, 240, 320, 0, 0, 0xC0);
    expect_preset(TARN_PANEL_ST7789_240X320, 3, 320, 240, 0, 0, 0xA0);
    expect_preset(TARN_PANEL_ILI9341_320X240, 0, 320, 240, 0, 0, 0x28);
    expect_preset(TARN_PANEL_ILI9341_320X240, 1, 240, 320, 0, 0, 0x88);
    expect_preset(TARN_PANEL_ILI9341_320X240, 2, 320, 240, 0, 0, 0xE8);
    expect_preset(TARN_PANEL_ILI9341_320X240, 3, 240, 320, 0, 0, 0x48);
    assert_int_equal(tarn_panel_preset((tarn_panel_model)7, 0).width, 0);
}

/* ---- The emulator, command by command ---- */

static tarn_panel_emulator *new_emulator(tarn_panel_model model, unsigned rotation)
{
    tarn_panel_emulator *e = malloc(sizeof *e);
    assert_non_null(e);
    assert_int_equal(tarn_panel_emulator_init(e, model, rotation), 0);
    return e;
}

static void send(tarn_panel_emulator *e, uint8_t command, const uint8_t *data, size_t count)
{
    tarn_panel_emulator_command(e, command);
    if (count > 0) tarn_panel_emulator_data(e, data, count);
}

/* Reset, wake, 16-bit colour, display on: the least a driver must do. */
static tarn_panel_emulator *awake_emulator(void)
{
    tarn_panel_emulator *e = new_emulator(TARN_PANEL_ST7789_240X320, 0);
    static const uint8_t colmod = 0x55;
    send(e, TARN_PANEL_SWRESET, NULL, 0);
    tarn_panel_emulator_delay(e, 120);
    send(e, TARN_PANEL_SLPOUT, NULL, 0);
    tarn_panel_emulator_delay(e, 5);
    send(e, TARN_PANEL_COLMOD, &colmod, 1);
    send(e, TARN_PANEL_DISPON, NULL, 0);
    assert_int_equal(e->counts.commands_too_early, 0);
    return e;
}

static void set_window(tarn_panel_emulator *e, uint16_t c0, uint16_t c1, uint16_t r0, uint16_t r1)
{
    uint8_t columns[4] = {(uint8_t)(c0 >> 8), (uint8_t)c0, (uint8_t)(c1 >> 8), (uint8_t)c1};
    uint8_t rows[4] = {(uint8_t)(r0 >> 8), (uint8_t)r0, (uint8_t)(r1 >> 8), (uint8_t)r1};
    send(e, TARN_PANEL_CASET, columns, 4);
    send(e, TARN_PANEL_RASET, rows, 4);
}

/* `count` pixels 1, 2, 3... as bytes, high first. */
static void write_numbered_pixels(tarn_panel_emulator *e, unsigned first, unsigned count)
{
    for (unsigned i = 0; i < count; i++) {
        uint8_t pixel[2] = {(uint8_t)((first + i) >> 8), (uint8_t)(first + i)};
        tarn_panel_emulator_data(e, pixel, 2);
    }
}

static uint16_t ram_at(const tarn_panel_emulator *e, unsigned column, unsigned row)
{
    return e->ram[(size_t)row * TARN_PANEL_RAM_COLUMNS + column];
}

static void test_emulator_fills_the_window_and_wraps(void **state)
{
    (void)state;
    tarn_panel_emulator *e = awake_emulator();
    set_window(e, 10, 12, 20, 21);
    send(e, TARN_PANEL_RAMWR, NULL, 0);
    write_numbered_pixels(e, 1, 8); /* 6 fill the window, 7 and 8 start over */
    assert_int_equal(ram_at(e, 10, 20), 7);
    assert_int_equal(ram_at(e, 11, 20), 8);
    assert_int_equal(ram_at(e, 12, 20), 3);
    assert_int_equal(ram_at(e, 10, 21), 4);
    assert_int_equal(ram_at(e, 12, 21), 6);
    assert_int_equal(ram_at(e, 13, 20), 0);
    /* RAMWRC continues after pixel 8; a NOP ends the write, later data is ignored */
    send(e, TARN_PANEL_RAMWRC, NULL, 0);
    write_numbered_pixels(e, 9, 1);
    assert_int_equal(ram_at(e, 12, 20), 9);
    send(e, TARN_PANEL_NOP, NULL, 0);
    write_numbered_pixels(e, 10, 1);
    assert_int_equal(e->counts.data_ignored, 2);
    assert_int_equal(e->counts.pixels_written, 9);
    free(e);
}

static void test_emulator_joins_pixels_split_across_calls(void **state)
{
    (void)state;
    tarn_panel_emulator *e = awake_emulator();
    set_window(e, 0, 1, 0, 0);
    send(e, TARN_PANEL_RAMWR, NULL, 0);
    static const uint8_t bytes[4] = {0x12, 0x34, 0x56, 0x78};
    tarn_panel_emulator_data(e, bytes, 1);
    tarn_panel_emulator_data(e, bytes + 1, 2);
    tarn_panel_emulator_data(e, bytes + 3, 1);
    assert_int_equal(ram_at(e, 0, 0), 0x1234);
    assert_int_equal(ram_at(e, 1, 0), 0x5678);
    free(e);
}

static void test_emulator_ignores_what_a_controller_ignores(void **state)
{
    (void)state;
    tarn_panel_emulator *e = new_emulator(TARN_PANEL_ST7789_240X320, 0);
    static const uint8_t bytes[4] = {0, 5, 0, 9};
    tarn_panel_emulator_data(e, bytes, 4); /* no command yet */
    assert_int_equal(e->counts.data_ignored, 4);
    send(e, 0x99, bytes, 2); /* unknown */
    assert_int_equal(e->counts.unknown_commands, 1);
    assert_int_equal(e->counts.data_ignored, 6);
    send(e, TARN_PANEL_CASET, bytes, 3); /* short: the window stays 0..239 */
    send(e, TARN_PANEL_RASET, bytes, 4);
    assert_int_equal(e->counts.parameters_incomplete, 1);
    assert_int_equal(e->column_start, 0);
    assert_int_equal(e->column_end, 239);
    assert_int_equal(e->row_start, 5);
    assert_int_equal(e->row_end, 9);
    send(e, TARN_PANEL_RAMWR, NULL, 0); /* still 18-bit colour after power-on */
    write_numbered_pixels(e, 1, 3);
    assert_int_equal(e->counts.pixel_bytes_ignored, 6);
    assert_int_equal(e->counts.pixels_written, 0);
    free(e);
}

static void test_emulator_needs_the_datasheet_waits(void **state)
{
    (void)state;
    tarn_panel_emulator *e = new_emulator(TARN_PANEL_ST7789_240X320, 0);
    send(e, TARN_PANEL_SWRESET, NULL, 0);
    send(e, TARN_PANEL_SLPOUT, NULL, 0); /* no wait at all */
    assert_int_equal(e->counts.commands_too_early, 1);
    tarn_panel_emulator_delay(e, 10);
    send(e, TARN_PANEL_SLPOUT, NULL, 0); /* 10 ms: commands yes, SLPOUT not yet */
    assert_int_equal(e->counts.commands_too_early, 2);
    assert_int_equal(e->sleeping, 1);
    tarn_panel_emulator_delay(e, 110);
    send(e, TARN_PANEL_SLPOUT, NULL, 0);
    assert_int_equal(e->sleeping, 0);
    /* a hardware reset holds the controller until released, then starts the waits */
    tarn_panel_emulator_reset(e, 1);
    send(e, TARN_PANEL_DISPON, NULL, 0);
    tarn_panel_emulator_reset(e, 0);
    send(e, TARN_PANEL_DISPON, NULL, 0);
    assert_int_equal(e->counts.commands_too_early, 4);
    assert_int_equal(e->sleeping, 1);
    assert_int_equal(e->counts.resets, 2);
    free(e);
}

/* MV exchanges column and row, then MX mirrors within 240 columns, MY within 320 rows. */
static void test_emulator_maps_addresses_through_madctl(void **state)
{
    (void)state;
    static const struct { uint8_t madctl; uint16_t column, row, ram_column, ram_row; } cases[] = {
        {0x00, 3, 5, 3, 5},     {0x40, 3, 5, 236, 5},   {0x80, 3, 5, 3, 314},
        {0x20, 300, 5, 5, 300}, {0x60, 300, 5, 234, 300}, {0xA0, 300, 5, 5, 19},
        {0xC0, 3, 5, 236, 314},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        tarn_panel_emulator *e = awake_emulator();
        send(e, TARN_PANEL_MADCTL, &cases[i].madctl, 1);
        set_window(e, cases[i].column, cases[i].column, cases[i].row, cases[i].row);
        send(e, TARN_PANEL_RAMWR, NULL, 0);
        write_numbered_pixels(e, 0xABCD, 1);
        assert_int_equal(ram_at(e, cases[i].ram_column, cases[i].ram_row), 0xABCD);
        free(e);
    }
    /* without MV, column 300 lies past the RAM */
    tarn_panel_emulator *e = awake_emulator();
    set_window(e, 300, 300, 0, 0);
    send(e, TARN_PANEL_RAMWR, NULL, 0);
    write_numbered_pixels(e, 1, 1);
    assert_int_equal(e->counts.pixels_outside_ram, 1);
    /* SWRESET puts MADCTL, the window and the colour mode back */
    static const uint8_t mv = 0x20;
    send(e, TARN_PANEL_MADCTL, &mv, 1);
    send(e, TARN_PANEL_SWRESET, NULL, 0);
    assert_int_equal(e->madctl, 0);
    assert_int_equal(e->colmod, 0x66);
    assert_int_equal(e->column_start, 0);
    assert_int_equal(e->column_end, 239);
    assert_int_equal(e->row_end, 319);
    free(e);
}

/* ---- Frames through the drivers ---- */

typedef struct {
    tarn_panel panel;
    tarn_panel_emulator *emulator;
    tarn_panel_transport transport;
    int dither;
    tarn_panel_band band;   /* the band path's state and RGB565 buffer */
    uint8_t band_buffer[2 * 320 * TARN_TILE_SIZE_MAX];
} target;

/* The tile sink of tarn_render_frame: every tile to every target. */
typedef struct {
    target *targets;
    size_t count;
    uint8_t line[2 * TARN_TILE_SIZE_MAX];
} fan_out;

static int send_to_every_target(void *user, const tarn_tile *tile)
{
    fan_out *f = user;
    for (size_t i = 0; i < f->count; i++) {
        target *t = &f->targets[i];
        if (tarn_panel_send_tile(&t->panel, &t->transport, tile, t->dither, f->line,
                                 sizeof f->line) != TARN_OK)
            return 1;
    }
    return 0;
}

/* The same, through the band path. */
static int send_bands_to_every_target(void *user, const tarn_tile *tile)
{
    fan_out *f = user;
    for (size_t i = 0; i < f->count; i++) {
        if (tarn_panel_band_add_tile(&f->targets[i].band, tile) != TARN_OK) return 1;
    }
    return 0;
}

/* A fresh emulator for the target's model and rotation, initialised by the driver,
 * its RAM poisoned so that pixels nobody wrote stand out. */
static void power_up(target *t, tarn_panel panel, int dither)
{
    t->panel = panel;
    t->dither = dither;
    if (t->emulator == NULL) t->emulator = malloc(sizeof *t->emulator);
    assert_non_null(t->emulator);
    assert_int_equal(tarn_panel_emulator_init(t->emulator, panel.model, panel.rotation), 0);
    t->transport = tarn_panel_emulator_transport(t->emulator);
    assert_int_equal(tarn_panel_init(&t->panel, &t->transport), TARN_OK);
    tarn_panel_emulator_counts c = t->emulator->counts;
    assert_int_equal(c.commands_too_early + c.unknown_commands + c.parameters_incomplete +
                         c.data_ignored + c.pixel_bytes_ignored, 0);
    for (size_t i = 0; i < TARN_PANEL_RAM_ROWS * TARN_PANEL_RAM_COLUMNS; i++)
        t->emulator->ram[i] = POISON;
    assert_int_equal(tarn_panel_band_init(&t->band, &t->panel, &t->transport, dither, t->band_buffer,
                                          sizeof t->band_buffer),
                     TARN_OK);
}

typedef struct {
    tarn_loaded_scene scene;
    uint16_t width, height;
    uint8_t *rgb; /* tarn_core_render's frame */
} reference_frame;

static void render_reference(reference_frame *ref, uint16_t width, uint16_t height)
{
    tarn_error err;
    if (tarn_scene_load(SCENE_PATH, &ref->scene, &err) != 0) fail_msg("%s", err.message);
    ref->width = width;
    ref->height = height;
    ref->rgb = malloc(3u * width * height);
    tarn_frame_config config = {width, height, tarn_quality_default(), 0};
    if (tarn_core_render(&ref->scene.scene, &config, ref->rgb, NULL, &err) != 0)
        fail_msg("%s", err.message);
}

static void free_reference(reference_frame *ref)
{
    free(ref->rgb);
    tarn_scene_free(&ref->scene);
}

static tarn_status render_through(const reference_frame *ref, unsigned tile_size, tarn_tile_sink sink_tile,
                                  fan_out *sink)
{
    tarn_frame_config config = {ref->width, ref->height, tarn_quality_default(), 0};
    config.quality.tile_size = (uint8_t)tile_size;
    size_t bytes = tarn_frame_memory_bytes(&config, &ref->scene.scene);
    assert_true(bytes > 0);
    void *memory = malloc(bytes);
    tarn_status status = tarn_render_frame(&ref->scene.scene, &config, memory, bytes,
                                           sink_tile, sink);
    free(memory);
    return status;
}

static tarn_status render_to(const reference_frame *ref, unsigned tile_size, fan_out *sink)
{
    return render_through(ref, tile_size, send_to_every_target, sink);
}

/* Pixels where the target's glass differs from the reference frame in RGB565. */
static size_t pixels_differing(const reference_frame *ref, const target *t)
{
    const tarn_panel_emulator *e = t->emulator;
    if (tarn_panel_emulator_width(e) != ref->width || tarn_panel_emulator_height(e) != ref->height)
        return (size_t)ref->width * ref->height;
    uint16_t *image = malloc(sizeof *image * ref->width * ref->height);
    tarn_panel_emulator_image(e, image);
    size_t differing = 0;
    for (uint16_t y = 0; y < ref->height; y++) {
        for (uint16_t x = 0; x < ref->width; x++) {
            const uint8_t *p = ref->rgb + 3u * ((size_t)y * ref->width + x);
            uint32_t rgb = ((uint32_t)p[0] << 16) | ((uint32_t)p[1] << 8) | p[2];
            differing += image[(size_t)y * ref->width + x] != tarn_rgb565(rgb, x, y, t->dither);
        }
    }
    free(image);
    return differing;
}

/* Every model and rotation whose picture is width x height, with and without dither. */
static size_t targets_of_size(target *targets, uint16_t width, uint16_t height)
{
    static const tarn_panel_model models[] = {TARN_PANEL_ST7789_240X240, TARN_PANEL_ST7789_240X320,
                                              TARN_PANEL_ILI9341_320X240};
    size_t count = 0;
    for (size_t m = 0; m < sizeof models / sizeof models[0]; m++) {
        for (unsigned rotation = 0; rotation < 4; rotation++) {
            tarn_panel panel = tarn_panel_preset(models[m], rotation);
            if (panel.width != width || panel.height != height) continue;
            for (int dither = 0; dither < 2; dither++, count++) {
                targets[count].panel = panel;
                targets[count].dither = dither;
            }
        }
    }
    return count;
}

static void free_targets(target *targets, size_t count)
{
    for (size_t i = 0; i < count; i++) free(targets[i].emulator);
}

/* Every model and rotation, every tile size, with and without dither, tile by tile
 * (`send` = send_to_every_target) or in bands. */
static void every_panel_shows_the_frame(tarn_tile_sink sink_tile)
{
    static const uint16_t sizes[][2] = {{240, 240}, {240, 320}, {320, 240}};
    size_t checked = 0;
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        reference_frame ref;
        render_reference(&ref, sizes[s][0], sizes[s][1]);
        target *targets = calloc(16, sizeof *targets);
        assert_non_null(targets);
        fan_out sink = {targets, targets_of_size(targets, ref.width, ref.height), {0}};
        assert_true(sink.count > 0);
        for (size_t k = 0; k < sizeof tile_sizes / sizeof tile_sizes[0]; k++) {
            for (size_t i = 0; i < sink.count; i++) power_up(&targets[i], targets[i].panel, targets[i].dither);
            assert_int_equal(render_through(&ref, tile_sizes[k], sink_tile, &sink), TARN_OK);
            for (size_t i = 0; i < sink.count; i++) {
                const target *t = &targets[i];
                size_t differing = pixels_differing(&ref, t);
                if (differing != 0)
                    fail_msg("model %u rotation %u dither %d tile %u: %zu pixels differ", t->panel.model,
                             t->panel.rotation, t->dither, tile_sizes[k], differing);
                assert_int_equal(t->emulator->counts.pixels_written, (uint32_t)ref.width * ref.height);
                assert_int_equal(t->emulator->counts.pixels_outside_ram, 0);
                checked++;
            }
        }
        free_targets(targets, sink.count);
        free(targets);
        free_reference(&ref);
    }
    assert_int_equal(checked, 3 * 4 * 8); /* 12 model-rotations, 2 dithers, 4 tile sizes */
}

static void test_every_panel_shows_the_frame(void **state)
{
    (void)state;
    every_panel_shows_the_frame(send_to_every_target);
}

static void test_every_panel_shows_the_frame_in_bands(void **state)
{
    (void)state;
    every_panel_shows_the_frame(send_bands_to_every_target);
}

/* Bands cost one window a frame: 11 bytes besides the pixels, at every tile size;
 * and a second frame opens its own window again. */
static void test_bands_send_one_window_a_frame(void **state)
{
    (void)state;
    reference_frame ref;
    render_reference(&ref, 240, 240);
    target *t = calloc(1, sizeof *t);
    assert_non_null(t);
    power_up(t, tarn_panel_preset(TARN_PANEL_ST7789_240X240, 3), 0);
    fan_out sink = {t, 1, {0}};
    for (size_t k = 0; k < sizeof tile_sizes / sizeof tile_sizes[0]; k++) {
        for (int frame = 0; frame < 2; frame++) {
            tarn_panel_emulator_counts before = t->emulator->counts;
            assert_int_equal(render_through(&ref, tile_sizes[k], send_bands_to_every_target, &sink), TARN_OK);
            uint32_t wire = (t->emulator->counts.commands - before.commands) +
                            (t->emulator->counts.data_bytes - before.data_bytes);
            assert_int_equal(wire, 2u * 240u * 240u + 11u);
            assert_int_equal(t->emulator->counts.commands - before.commands, 3);
        }
        assert_int_equal(pixels_differing(&ref, t), 0);
    }
    free(t->emulator);
    free(t);
    free_reference(&ref);
}

/* Tiles out of order, or taller than the buffer, are refused and send nothing; the
 * next band starts over with a window of its own. */
static void test_bands_refuse_tiles_out_of_order(void **state)
{
    (void)state;
    target *t = calloc(1, sizeof *t);
    assert_non_null(t);
    power_up(t, tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0), 0);
    static const uint32_t pixels[64 * 64];
    tarn_tile first = {0, 0, 120, 16, pixels, NULL, 120, 32};
    tarn_tile skips = {200, 0, 40, 16, pixels, NULL, 40, 32};
    tarn_tile second = {120, 0, 120, 16, pixels, NULL, 120, 32};
    tarn_tile not_left = {16, 16, 16, 16, pixels, NULL, 16, 32};
    tarn_panel_emulator_counts before = t->emulator->counts;
    assert_int_equal(tarn_panel_band_add_tile(&t->band, &not_left), TARN_ERR_CONFIG);
    assert_int_equal(tarn_panel_band_add_tile(&t->band, &first), TARN_OK);
    assert_int_equal(tarn_panel_band_add_tile(&t->band, &skips), TARN_ERR_CONFIG);
    assert_int_equal(t->emulator->counts.commands, before.commands);
    assert_int_equal(tarn_panel_band_add_tile(&t->band, &first), TARN_OK);
    assert_int_equal(tarn_panel_band_add_tile(&t->band, &second), TARN_OK);
    assert_int_equal(t->emulator->counts.pixels_written, 240u * 16u);
    tarn_panel_band small;
    uint8_t buffer[2 * 240 * 8];
    assert_int_equal(tarn_panel_band_init(&small, &t->panel, &t->transport, 0, buffer, sizeof buffer), TARN_OK);
    assert_int_equal(tarn_panel_band_add_tile(&small, &first), TARN_ERR_CONFIG); /* 16 rows, room for 8 */
    assert_int_equal(tarn_panel_band_init(&small, &t->panel, &t->transport, 0, buffer, 100), TARN_ERR_CONFIG);
    free(t->emulator);
    free(t);
}

/* A driver that gets an offset or a MADCTL bit wrong draws a different picture. */
static void test_wrong_offsets_and_madctl_show(void **state)
{
    (void)state;
    reference_frame ref;
    render_reference(&ref, 240, 240);
    target targets[6];
    memset(targets, 0, sizeof targets);
    tarn_panel wrong[6] = {tarn_panel_preset(TARN_PANEL_ST7789_240X240, 2),
                           tarn_panel_preset(TARN_PANEL_ST7789_240X240, 3),
                           tarn_panel_preset(TARN_PANEL_ST7789_240X240, 1),
                           tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0),
                           tarn_panel_preset(TARN_PANEL_ST7789_240X240, 1),
                           tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0)};
    wrong[0].row_offset = 0;     /* the 80 rows the glass does not show */
    wrong[1].column_offset = 0;
    wrong[2].row_offset = 1;     /* off by one */
    wrong[3].madctl |= 0x08;     /* BGR on RGB glass */
    wrong[4].madctl ^= 0x40;     /* rotation 1 without MX: mirrored */
    wrong[5].madctl = tarn_panel_preset(TARN_PANEL_ST7789_240X240, 2).madctl; /* upside down */
    static const char *const mistake[6] = {"row offset 0",   "column offset 0", "row offset off by one",
                                           "BGR on RGB glass", "MX left out",     "rotation 2's MADCTL"};
    /* the emulator holds the module as the rotation says; the driver gets it wrong */
    for (size_t i = 0; i < 6; i++) power_up(&targets[i], wrong[i], 0);
    fan_out sink = {targets, 6, {0}};
    assert_int_equal(render_to(&ref, 32, &sink), TARN_OK);
    for (size_t i = 0; i < 6; i++) {
        size_t differing = pixels_differing(&ref, &targets[i]);
        print_message("a driver with %s shows another picture, as it must (%zu of %u pixels changed)\n",
                      mistake[i], differing, 240u * 240u);
        assert_true(differing > 240u * 240u / 4u);
    }
    free_targets(targets, 6);
    free_reference(&ref);
}

/* ---- The byte stream ---- */

/* The whole exchange for one frame: init, then every tile, as a stream. */
static void encode_frame(const reference_frame *ref, tarn_panel panel, unsigned tile_size,
                         tarn_panel_stream_writer *writer, size_t *frame_bytes)
{
    target t = {panel, NULL, tarn_panel_stream_transport(writer), 0, {0}, {0}};
    assert_int_equal(tarn_panel_init(&panel, &t.transport), TARN_OK);
    size_t before = writer->count;
    fan_out sink = {&t, 1, {0}};
    assert_int_equal(render_to(ref, tile_size, &sink), TARN_OK);
    *frame_bytes = writer->count - before;
    assert_int_equal(tarn_panel_stream_end(writer, 0), 0);
}

/* Bytes a frame puts on the SPI wire: commands and data, after init. */
static uint32_t wire_bytes_of_frame(const reference_frame *ref, tarn_panel panel, unsigned tile_size)
{
    target t = {{0}, NULL, {0}, 0, {0}, {0}};
    power_up(&t, panel, 0);
    tarn_panel_emulator_counts before = t.emulator->counts;
    fan_out sink = {&t, 1, {0}};
    assert_int_equal(render_to(ref, tile_size, &sink), TARN_OK);
    uint32_t bytes = (t.emulator->counts.commands - before.commands) +
                     (t.emulator->counts.data_bytes - before.data_bytes);
    free(t.emulator);
    return bytes;
}

static void test_stream_round_trips_a_frame(void **state)
{
    (void)state;
    reference_frame ref;
    render_reference(&ref, 240, 240);
    tarn_panel panel = tarn_panel_preset(TARN_PANEL_ST7789_240X240, 2);
    for (unsigned tile = 16; tile <= 32; tile *= 2) {
        tarn_panel_stream_writer writer = {0};
        size_t stream_bytes;
        encode_frame(&ref, panel, tile, &writer, &stream_bytes);
        target t = {panel, new_emulator(panel.model, panel.rotation), {0}, 0, {0}, {0}};
        t.transport = tarn_panel_emulator_transport(t.emulator);
        tarn_error err;
        if (tarn_panel_stream_decode(writer.bytes, writer.count, &t.transport, &err) != 0)
            fail_msg("%s", err.message);
        assert_int_equal(pixels_differing(&ref, &t), 0);
        uint32_t wire = wire_bytes_of_frame(&ref, panel, tile);
        uint32_t pixels = 2u * 240u * 240u;
        print_message("240x240 frame, tile %u: %u bytes on the wire (%u pixel bytes + %u for windows), "
                      "%zu bytes of stream\n", tile, wire, pixels, wire - pixels, stream_bytes);
        unsigned tiles_across = (240u + tile - 1u) / tile;
        assert_int_equal(wire, pixels + tiles_across * tiles_across * 11u); /* CASET+4, RASET+4, RAMWR */
        free(t.emulator);
        tarn_panel_stream_writer_free(&writer);
    }
    free_reference(&ref);
}

/* Decodes `bytes` into a scratch emulator; returns the error text ("" if none). */
static const char *decode_error(const uint8_t *bytes, size_t count)
{
    static tarn_error err;
    tarn_panel_emulator *e = new_emulator(TARN_PANEL_ST7789_240X240, 0);
    tarn_panel_transport transport = tarn_panel_emulator_transport(e);
    int status = tarn_panel_stream_decode(bytes, count, &transport, &err);
    free(e);
    if (status == 0) return "";
    return err.message;
}

#define BYTES(...) (const uint8_t[]){__VA_ARGS__}, sizeof((const uint8_t[]){__VA_ARGS__})

static void test_stream_errors_name_the_byte(void **state)
{
    (void)state;
    assert_string_equal(decode_error(BYTES('C', 0x2C, 'E', 0)), "");
    assert_string_equal(decode_error(BYTES('C', 0x2C, 'D', 0, 4, 1, 2)),
                        "byte 2: 'D' record of 4 bytes, but the stream ends after 2");
    assert_string_equal(decode_error(BYTES('C', 0x2C, 'D', 0)),
                        "byte 2: 'D' record needs 2 length bytes, but the stream ends after 1 more byte(s)");
    assert_string_equal(decode_error(BYTES('C')),
                        "byte 0: 'C' record needs a command byte, but the stream ends after 0 more byte(s)");
    assert_string_equal(decode_error(BYTES('C', 0x2C)), "byte 2: the stream ends without an 'E' record");
    assert_string_equal(decode_error(BYTES('W', 0, 5, 'X', 1)),
                        "byte 3: unknown record type 0x58 (expected 'C', 'D', 'R', 'W' or 'E')");
    assert_string_equal(decode_error(BYTES('D', 0, 0, 'E', 0)),
                        "byte 0: 'D' record of length 0 (expected 1..65535)");
    assert_string_equal(decode_error(BYTES('R', 2, 'E', 0)), "byte 0: 'R' level 2 (expected 0 or 1)");
    assert_string_equal(decode_error(BYTES('E', 0, 'C', 1)),
                        "byte 2: 2 byte(s) after the 'E' record (expected the stream to end)");
    assert_string_equal(decode_error(BYTES('C', 0, 'E', 3)),
                        "byte 2: 'E' record with status 3: the firmware did not finish");
}

/* A real frame's stream cut anywhere is an error, never a crash or a success. */
static void test_truncated_stream_is_an_error(void **state)
{
    (void)state;
    reference_frame ref;
    render_reference(&ref, 240, 240);
    tarn_panel_stream_writer writer = {0};
    size_t frame_bytes;
    encode_frame(&ref, tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0), 64, &writer, &frame_bytes);
    for (size_t cut = 0; cut < writer.count; cut += 1 + cut / 8)
        assert_true(strncmp(decode_error(writer.bytes, cut), "byte ", 5) == 0);
    char expected[128];
    snprintf(expected, sizeof expected,
             "byte %zu: 'E' record needs a status byte, but the stream ends after 0 more byte(s)",
             writer.count - 2);
    assert_string_equal(decode_error(writer.bytes, writer.count - 1), expected);
    tarn_panel_stream_writer_free(&writer);
    free_reference(&ref);
}

static void test_stream_file_errors_name_the_file(void **state)
{
    (void)state;
    tarn_panel_emulator *e = new_emulator(TARN_PANEL_ST7789_240X240, 0);
    tarn_panel_transport transport = tarn_panel_emulator_transport(e);
    tarn_error err;
    assert_int_equal(tarn_panel_stream_decode_file("build/no-such-stream.bin", &transport, &err), -1);
    assert_string_equal(err.message, "build/no-such-stream.bin: cannot open: No such file or directory");
    char path[] = "/tmp/tarn-stream-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *file = fdopen(fd, "wb");
    fwrite("C\x2C" "D\x00\x04\x01", 1, 6, file);
    fclose(file);
    assert_int_equal(tarn_panel_stream_decode_file(path, &transport, &err), -1);
    char expected[128];
    snprintf(expected, sizeof expected, "%s: byte 2: 'D' record of 4 bytes, but the stream ends after 1", path);
    assert_string_equal(err.message, expected);
    remove(path);
    free(e);
}

/* ---- Failures and bad tiles ---- */

/* The emulator's transport, failing from the `fail_at`-th call on. */
typedef struct {
    tarn_panel_transport inner;
    unsigned calls, fail_at;
} failing_link;

static int failing_command(void *user, uint8_t command)
{
    failing_link *l = user;
    if (++l->calls >= l->fail_at) return -1;
    return l->inner.command(l->inner.user, command);
}

static int failing_data(void *user, const uint8_t *bytes, size_t count)
{
    failing_link *l = user;
    if (++l->calls >= l->fail_at) return -1;
    return l->inner.data(l->inner.user, bytes, count);
}

static int forward_delay(void *user, uint16_t milliseconds)
{
    failing_link *l = user;
    return l->inner.delay_ms(l->inner.user, milliseconds);
}

static void test_transport_failure_stops_tile_and_frame(void **state)
{
    (void)state;
    reference_frame ref;
    render_reference(&ref, 240, 240);
    target t = {{0}, NULL, {0}, 0, {0}, {0}};
    power_up(&t, tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0), 0);
    failing_link link = {t.transport, 0, 0};
    t.transport = (tarn_panel_transport){&link, failing_command, failing_data, NULL, forward_delay};

    static const uint32_t pixels[16 * 16];
    tarn_tile tile = {16, 16, 16, 16, pixels, NULL, 16, 32};
    uint8_t line[32];
    for (unsigned fail_at = 1; fail_at <= 7; fail_at++) { /* CASET, its data, ..., RAMWR, a row */
        link.calls = 0;
        link.fail_at = fail_at;
        assert_int_equal(tarn_panel_send_tile(&t.panel, &t.transport, &tile, 0, line, sizeof line),
                         TARN_ERR_SINK);
    }
    link.calls = 0;
    link.fail_at = 1000; /* mid-frame: a few tiles in */
    fan_out sink = {&t, 1, {0}};
    assert_int_equal(render_to(&ref, 32, &sink), TARN_ERR_SINK);
    assert_int_equal(link.calls, 1000);
    /* init fails the same way */
    link.calls = 0;
    link.fail_at = 3;
    assert_int_equal(tarn_panel_init(&t.panel, &t.transport), TARN_ERR_SINK);
    free(t.emulator);
    free_reference(&ref);
}

static void test_tiles_outside_the_panel_are_rejected(void **state)
{
    (void)state;
    target t = {{0}, NULL, {0}, 0, {0}, {0}};
    power_up(&t, tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0), 0);
    tarn_panel_emulator_counts before = t.emulator->counts;
    static const uint32_t pixels[16 * 16];
    uint8_t line[32];
    tarn_tile past_right = {232, 0, 16, 16, pixels, NULL, 16, 32};
    tarn_tile past_bottom = {0, 230, 16, 16, pixels, NULL, 16, 32};
    tarn_tile empty = {0, 0, 0, 16, pixels, NULL, 16, 32};
    tarn_tile fits = {224, 224, 16, 16, pixels, NULL, 16, 32};
    assert_int_equal(tarn_panel_send_tile(&t.panel, &t.transport, &past_right, 0, line, 32), TARN_ERR_CONFIG);
    assert_int_equal(tarn_panel_send_tile(&t.panel, &t.transport, &past_bottom, 0, line, 32), TARN_ERR_CONFIG);
    assert_int_equal(tarn_panel_send_tile(&t.panel, &t.transport, &empty, 0, line, 32), TARN_ERR_CONFIG);
    assert_int_equal(tarn_panel_send_tile(&t.panel, &t.transport, &fits, 0, line, 31), TARN_ERR_CONFIG);
    tarn_panel unknown = tarn_panel_preset((tarn_panel_model)9, 0);
    assert_int_equal(tarn_panel_send_tile(&unknown, &t.transport, &fits, 0, line, 32), TARN_ERR_CONFIG);
    assert_int_equal(tarn_panel_init(&unknown, &t.transport), TARN_ERR_CONFIG);
    assert_int_equal(t.emulator->counts.commands, before.commands); /* nothing was sent */
    assert_int_equal(tarn_panel_send_tile(&t.panel, &t.transport, &fits, 0, line, 32), TARN_OK);
    assert_int_equal(t.emulator->counts.pixels_written, 256);
    free(t.emulator);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rgb565_rounds_every_value_to_nearest),
        cmocka_unit_test(test_rgb565_dither_stays_within_a_step),
        cmocka_unit_test(test_presets_match_the_documented_table),
        cmocka_unit_test(test_emulator_fills_the_window_and_wraps),
        cmocka_unit_test(test_emulator_joins_pixels_split_across_calls),
        cmocka_unit_test(test_emulator_ignores_what_a_controller_ignores),
        cmocka_unit_test(test_emulator_needs_the_datasheet_waits),
        cmocka_unit_test(test_emulator_maps_addresses_through_madctl),
        cmocka_unit_test(test_every_panel_shows_the_frame),
        cmocka_unit_test(test_every_panel_shows_the_frame_in_bands),
        cmocka_unit_test(test_bands_send_one_window_a_frame),
        cmocka_unit_test(test_bands_refuse_tiles_out_of_order),
        cmocka_unit_test(test_wrong_offsets_and_madctl_show),
        cmocka_unit_test(test_stream_round_trips_a_frame),
        cmocka_unit_test(test_stream_errors_name_the_byte),
        cmocka_unit_test(test_truncated_stream_is_an_error),
        cmocka_unit_test(test_stream_file_errors_name_the_file),
        cmocka_unit_test(test_transport_failure_stops_tile_and_frame),
        cmocka_unit_test(test_tiles_outside_the_panel_are_rejected),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
