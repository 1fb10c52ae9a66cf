/* test_display_links.c: every backend's own code, driving the panel emulator.
 *
 * The spidev backend with its ioctl answered by the emulated module, the bit-banged
 * SPI on emulated lines and the MCP2210 protocol against the MCP2210 emulator, each
 * opened through display.c exactly as `tarn show --display emulator:... --via` does:
 * the emulated glass must equal the rendered frame through tarn_rgb565, byte for
 * byte, for every panel model, rotated and not, every tile size and every send
 * path. Then what each link must get right on its own: spidev's transfer limit and
 * its two clocks; the MCP2210's changed-tile path, its busy and late-finish replies,
 * an external bus master, an unplugged bridge mid-frame; the real error paths of
 * spidev and libgpiod on this machine's real devices. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "display.h"
#include "frame_sender.h"
#include "scene_load.h"

#define SCENE_PATH "scenes/pond.json"
#define WIDE_SCENE_PATH "scenes/effects/none.json"

static const unsigned tile_sizes[] = {8, 16, 32, 64};

typedef struct {
    uint16_t width, height;
    uint32_t *rgb; /* 0x00RRGGBB, the core's frame */
} frame;

static tarn_loaded_scene pond, wide;

static int load_scenes(void **state)
{
    (void)state;
    tarn_error err;
    if (tarn_scene_load(SCENE_PATH, &pond, &err) != 0 || tarn_scene_load(WIDE_SCENE_PATH, &wide, &err) != 0)
        fail_msg("%s", err.message);
    return 0;
}

static int free_scenes(void **state)
{
    (void)state;
    tarn_scene_free(&pond);
    tarn_scene_free(&wide);
    return 0;
}

static int store_tile(void *user, const tarn_tile *tile)
{
    frame *f = user;
    for (uint16_t row = 0; row < tile->height; row++)
        memcpy(f->rgb + (size_t)(tile->y + row) * f->width + tile->x, tile->rgb + (size_t)row * tile->stride,
               tile->width * sizeof(uint32_t));
    return 0;
}

/* The pond's refraction reaches too far for the apron at 320 pixels wide: other
 * sizes render the opaque scene. */
static frame render(uint16_t width, uint16_t height, uint32_t time_ms)
{
    const tarn_scene *scene = width == 240 ? &pond.scene : &wide.scene;
    frame f = {width, height, malloc(sizeof(uint32_t) * width * height)};
    tarn_frame_config config = {width, height, tarn_quality_default(), time_ms};
    size_t bytes = tarn_frame_memory_bytes(&config, scene);
    void *memory = malloc(bytes);
    assert_int_equal(tarn_render_frame(scene, &config, memory, bytes, store_tile, &f), TARN_OK);
    free(memory);
    return f;
}

static tarn_show_options options_for(tarn_display_kind via, tarn_panel panel, tarn_send_mode send, unsigned tile)
{
    tarn_show_options o;
    memset(&o, 0, sizeof o);
    o.display = TARN_DISPLAY_EMULATOR;
    o.display_text = "emulator:test.png";
    o.target = "test.png";
    o.via = via;
    o.panel = panel;
    o.panel_name = "test";
    o.hz = 62500000;
    o.send = send;
    o.quality = tarn_quality_default();
    o.quality.tile_size = (uint8_t)tile;
    return o;
}

/* A display through `via`, initialised by the driver. */
typedef struct {
    tarn_show_options options;
    tarn_display display;
    tarn_frame_sender sender;
} link_under_test;

static link_under_test *open_link(tarn_display_kind via, tarn_panel panel, tarn_send_mode send, unsigned tile)
{
    link_under_test *l = calloc(1, sizeof *l);
    assert_non_null(l);
    l->options = options_for(via, panel, send, tile);
    tarn_error err;
    if (tarn_display_open(&l->display, &l->options, &err) != 0) fail_msg("%s", err.message);
    assert_int_equal(tarn_frame_sender_init(&l->sender, &l->options.panel, &l->display.transport, send, 0, tile, &err),
                     0);
    assert_int_equal(tarn_panel_init(&l->options.panel, &l->display.transport), TARN_OK);
    const tarn_panel_emulator_counts *c = &l->display.emulator->counts;
    assert_int_equal(c->commands_too_early + c->unknown_commands + c->parameters_incomplete + c->data_ignored, 0);
    return l;
}

static void close_link(link_under_test *l)
{
    tarn_frame_sender_free(&l->sender);
    tarn_display_close(&l->display);
    free(l);
}

/* Pixels of the emulated glass that differ from the frame in RGB565. */
static size_t pixels_differing(const tarn_display *d, const frame *f)
{
    const tarn_panel_emulator *e = d->emulator;
    if (tarn_panel_emulator_width(e) != f->width || tarn_panel_emulator_height(e) != f->height)
        return (size_t)f->width * f->height;
    uint16_t *image = malloc(sizeof *image * f->width * f->height);
    tarn_panel_emulator_image(e, image);
    size_t differing = 0;
    for (uint16_t y = 0; y < f->height; y++)
        for (uint16_t x = 0; x < f->width; x++)
            differing += image[(size_t)y * f->width + x] != tarn_rgb565(f->rgb[(size_t)y * f->width + x], x, y, 0);
    free(image);
    return differing;
}

static void shows_every_frame_through(tarn_display_kind via, const unsigned *tiles, size_t tile_count)
{
    static const tarn_panel_model models[] = {TARN_PANEL_ST7789_240X240, TARN_PANEL_ST7789_240X320,
                                              TARN_PANEL_ILI9341_320X240};
    static const tarn_send_mode sends[] = {TARN_SEND_BANDS, TARN_SEND_TILES, TARN_SEND_CHANGED};
    for (size_t m = 0; m < 3; m++) {
        for (unsigned rotation = 0; rotation < 4; rotation += 3) {
            tarn_panel panel = tarn_panel_preset(models[m], rotation);
            frame f = render(panel.width, panel.height, 0);
            for (size_t t = 0; t < tile_count; t++) {
                for (size_t s = 0; s < 3; s++) {
                    link_under_test *l = open_link(via, panel, sends[s], tiles[t]);
                    assert_int_equal(tarn_frame_sender_send(&l->sender, f.rgb), TARN_OK);
                    size_t differing = pixels_differing(&l->display, &f);
                    if (differing != 0)
                        fail_msg("via %d model %u rotation %u tile %u send %d: %zu pixels differ", via,
                                 panel.model, rotation, tiles[t], sends[s], differing);
                    assert_int_equal(l->display.emulator->counts.pixels_outside_ram, 0);
                    close_link(l);
                }
            }
            free(f.rgb);
        }
    }
}

#define SHOW_PNG "build/test_show.png"
#define SHOW_OUT "build/test_show.out"

/* The whole file a command wrote, NUL-terminated (at most 4 KB). */
static void read_text(const char *path, char *text, size_t size)
{
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    size_t length = fread(text, 1, size - 1, f);
    fclose(f);
    text[length] = '\0';
}

/* tarn show end to end, through the real binary: three frames animated through the
 * spidev backend into the emulator, the figures reported, and the picture written
 * is the last frame (time 100 + 2 frames at 10 fps = 300 ms) through tarn_rgb565
 * with dither, pixel for pixel, and not the first. */
static void test_show_animates_into_the_emulator(void **state)
{
    (void)state;
    const char *tarn = getenv("TARN_BIN") != NULL ? getenv("TARN_BIN") : "build/release/tarn";
    remove(SHOW_PNG);
    char command[1024];
    snprintf(command, sizeof command,
             "%s show " SCENE_PATH " --panel st7789-240x240 --display emulator:" SHOW_PNG
             " --via spidev --frames 3 --fps 10 --time 100 --dither > " SHOW_OUT,
             tarn);
    assert_int_equal(system(command), 0);
    char text[4096];
    read_text(SHOW_OUT, text, sizeof text);
    assert_non_null(strstr(text, "show panel=st7789-240x240"));
    assert_non_null(strstr(text, " frames=3 "));
    assert_non_null(strstr(text, " bytes_per_frame="));
    assert_non_null(strstr(text, " link_fps="));
    png_image image;
    memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    assert_true(png_image_begin_read_from_file(&image, SHOW_PNG));
    assert_int_equal(image.width, 240);
    assert_int_equal(image.height, 240);
    image.format = PNG_FORMAT_RGB;
    uint8_t *rgb = malloc(PNG_IMAGE_SIZE(image));
    assert_true(png_image_finish_read(&image, NULL, rgb, 0, NULL));
    frame last = render(240, 240, 300), first = render(240, 240, 100);
    size_t differing_last = 0, differing_first = 0;
    for (uint16_t y = 0; y < 240; y++)
        for (uint16_t x = 0; x < 240; x++) {
            const size_t p = (size_t)y * 240 + x;
            uint8_t want[3], other[3];
            tarn_rgb565_to_rgb888(tarn_rgb565(last.rgb[p], x, y, 1), want);
            tarn_rgb565_to_rgb888(tarn_rgb565(first.rgb[p], x, y, 1), other);
            differing_last += memcmp(rgb + 3 * p, want, 3) != 0;
            differing_first += memcmp(rgb + 3 * p, other, 3) != 0;
        }
    assert_int_equal(differing_last, 0);
    assert_true(differing_first > 1000);
    free(rgb);
    free(last.rgb);
    free(first.rgb);
    remove(SHOW_PNG);
    remove(SHOW_OUT);
}

static void test_spidev_shows_the_frame(void **state)
{
    (void)state;
    shows_every_frame_through(TARN_DISPLAY_SPIDEV, tile_sizes, 4);
}

static void test_mcp2210_shows_the_frame(void **state)
{
    (void)state;
    shows_every_frame_through(TARN_DISPLAY_MCP2210, tile_sizes, 4);
}

/* Bit-banging clocks every bit through the emulated lines: one tile size. */
static void test_gpio_spi_shows_the_frame(void **state)
{
    (void)state;
    static const unsigned one[] = {32};
    shows_every_frame_through(TARN_DISPLAY_GPIO_SPI, one, 1);
}

/* spidev: no message over the driver's bufsiz, commands at the slow clock, pixels at --hz. */
static void test_spidev_splits_and_clocks(void **state)
{
    (void)state;
    tarn_panel panel = tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0);
    frame f = render(240, 240, 0);
    link_under_test *l = open_link(TARN_DISPLAY_SPIDEV, panel, TARN_SEND_BANDS, 32);
    uint64_t before = l->display.counts->transfers;
    assert_int_equal(tarn_frame_sender_send(&l->sender, f.rgb), TARN_OK);
    const tarn_panel_wiring *w = &l->display.wiring;
    assert_true(w->largest_transfer <= TARN_SPIDEV_BUFSIZ_DEFAULT);
    assert_int_equal(w->largest_transfer, TARN_SPIDEV_BUFSIZ_DEFAULT);
    assert_int_equal(w->slowest_pixel_hz, 62500000);
    assert_true(w->fastest_command_hz > 0 && w->fastest_command_hz <= 10000000);
    assert_true(w->fastest_parameter_hz > 0 && w->fastest_parameter_hz <= 10000000); /* CASET, RASET */
    assert_int_equal(w->spi_mode, 0); /* what the module samples (panel_wiring.h) */
    /* 7 bands of 15 360 bytes (4 transfers each), one of 7 680 (2), CASET and RASET
     * (a command and its parameters each) and RAMWR */
    assert_int_equal(l->display.counts->transfers - before, 7 * 4 + 2 + 5);
    print_message("spidev, 240x240 in bands of 32 rows: %llu transfers, largest %zu bytes\n",
                  (unsigned long long)(l->display.counts->transfers - before), w->largest_transfer);
    close_link(l);
    free(f.rgb);
}

/* Tiles of the two frames whose RGB565 differs: what the changed path must send. */
static unsigned tiles_differing(const frame *a, const frame *b, unsigned tile, uint64_t *bytes)
{
    unsigned count = 0;
    *bytes = 0;
    for (unsigned ty = 0; ty < a->height; ty += tile) {
        for (unsigned tx = 0; tx < a->width; tx += tile) {
            unsigned w = a->width - tx < tile ? a->width - tx : tile, h = a->height - ty < tile ? a->height - ty : tile;
            int differs = 0;
            for (unsigned y = ty; y < ty + h && !differs; y++)
                for (unsigned x = tx; x < tx + w; x++) {
                    size_t i = (size_t)y * a->width + x;
                    differs |= tarn_rgb565(a->rgb[i], (uint16_t)x, (uint16_t)y, 0) !=
                               tarn_rgb565(b->rgb[i], (uint16_t)x, (uint16_t)y, 0);
                }
            count += (unsigned)differs;
            *bytes += differs ? 2u * w * h + 11u : 0u;
        }
    }
    return count;
}

static void test_mcp2210_sends_only_changed_tiles(void **state)
{
    (void)state;
    tarn_panel panel = tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0);
    frame first = render(240, 240, 0), second = render(240, 240, 500);
    link_under_test *l = open_link(TARN_DISPLAY_MCP2210, panel, TARN_SEND_CHANGED, 16);
    assert_int_equal(tarn_frame_sender_send(&l->sender, first.rgb), TARN_OK);
    assert_int_equal(l->sender.tiles_sent, 225);
    uint64_t expected_bytes;
    unsigned changed = tiles_differing(&first, &second, 16, &expected_bytes);
    assert_true(changed > 0 && changed < 225);
    uint64_t bytes_before = l->display.counts->spi_bytes;
    assert_int_equal(tarn_frame_sender_send(&l->sender, second.rgb), TARN_OK);
    assert_int_equal(l->sender.tiles_sent, 225 + changed);
    assert_int_equal(l->display.counts->spi_bytes - bytes_before, expected_bytes);
    assert_int_equal(pixels_differing(&l->display, &second), 0);
    print_message("second frame through the MCP2210: %u of 225 tiles changed, %llu bytes\n", changed,
                  (unsigned long long)expected_bytes);
    /* the same frame again sends nothing */
    bytes_before = l->display.counts->spi_bytes;
    assert_int_equal(tarn_frame_sender_send(&l->sender, second.rgb), TARN_OK);
    assert_int_equal(l->display.counts->spi_bytes, bytes_before);
    close_link(l);
    free(first.rgb);
    free(second.rgb);
}

static void test_mcp2210_recovers_from_busy_replies(void **state)
{
    (void)state;
    tarn_panel panel = tarn_panel_preset(TARN_PANEL_ILI9341_320X240, 1);
    frame f = render(panel.width, panel.height, 0);
    link_under_test *l = open_link(TARN_DISPLAY_MCP2210, panel, TARN_SEND_BANDS, 16);
    tarn_mcp2210_emulator *e = &l->display.mcp2210_emulator;
    e->busy_next = 50;  /* a run of busy answers */
    e->busy_every = 7;  /* and one every few reports after that */
    e->finish_late = 1; /* and the engine still clocks after the last chunk, until polled */
    assert_int_equal(tarn_frame_sender_send(&l->sender, f.rgb), TARN_OK);
    assert_int_equal(pixels_differing(&l->display, &f), 0);
    assert_true(e->busy_answers > 50);
    assert_int_equal(e->gpio_while_clocking, 0); /* D/CX waits for the engine */
    assert_int_equal(e->spi_mode, 0);
    assert_int_equal(l->display.counts->busy_replies, e->busy_answers);
    close_link(l);
    free(f.rgb);
}

/* A link that fails in the middle of the pond's frame: the frame stops, and the one
 * line it gives contains each of `says` (a NULL-terminated list). */
static void assert_frame_stops_saying(link_under_test *l, const char *const says[])
{
    frame f = render(240, 240, 0);
    assert_int_equal(tarn_frame_sender_send(&l->sender, f.rgb), TARN_ERR_SINK);
    const char *message = tarn_display_failure(&l->display);
    for (size_t i = 0; says[i] != NULL; i++)
        if (strstr(message, says[i]) == NULL) fail_msg("'%s' does not say '%s'", message, says[i]);
    assert_null(strchr(message, '\n'));
    free(f.rgb);
}

static void test_mcp2210_unplugged_mid_frame(void **state)
{
    (void)state;
    link_under_test *l = open_link(TARN_DISPLAY_MCP2210, tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0),
                                   TARN_SEND_CHANGED, 32);
    l->display.mcp2210_emulator.unplug_after = l->display.mcp2210_emulator.reports + 500;
    static const char *const says[] = {"the bridge is gone (unplugged?", NULL};
    assert_frame_stops_saying(l, says);
    assert_int_equal(l->sender.shown_valid, 0); /* the next frame goes out whole */
    close_link(l);
}

/* spidev's device gone in the middle of a frame: one line naming the device and
 * what to check. */
static void test_spidev_vanishes_mid_frame(void **state)
{
    (void)state;
    link_under_test *l = open_link(TARN_DISPLAY_SPIDEV, tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0),
                                   TARN_SEND_TILES, 16);
    l->display.wiring.vanish_after_messages = l->display.wiring.ioctls + 100;
    static const char *const says[] = {"spidev:emulated: a transfer of", "No such device (was the device removed?)",
                                       NULL};
    assert_frame_stops_saying(l, says);
    close_link(l);
}

/* An MCP2210 that answers busy for ever: the frame stops after a bounded number of
 * tries, with one line, instead of hanging. */
static void test_mcp2210_stalled_ends_the_frame(void **state)
{
    (void)state;
    link_under_test *l = open_link(TARN_DISPLAY_MCP2210, tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0),
                                   TARN_SEND_BANDS, 32);
    l->display.mcp2210_emulator.busy_every = 1;
    static const char *const says[] = {"stayed busy (0xF8)", NULL};
    assert_frame_stops_saying(l, says);
    close_link(l);
}

/* Straight through the seam: the answers the datasheet gives. */
static void test_mcp2210_emulator_answers_as_the_datasheet(void **state)
{
    (void)state;
    tarn_panel_emulator *panel = malloc(sizeof *panel);
    tarn_panel_emulator_init(panel, TARN_PANEL_ST7789_240X240, 0);
    tarn_panel_wiring wiring;
    tarn_panel_wiring_init(&wiring, tarn_panel_emulator_transport(panel));
    tarn_mcp2210_emulator e;
    tarn_mcp2210_emulator_init(&e, &wiring);
    tarn_mcp2210_seam seam = tarn_mcp2210_emulator_seam(&e);
    uint8_t command[64] = {0x99}, reply[64];
    assert_int_equal(seam.read(seam.user, reply, 10), 0); /* nothing asked: a timeout */
    assert_int_equal(seam.write(seam.user, command), 0);
    assert_int_equal(seam.read(seam.user, reply, 10), 64);
    assert_int_equal(reply[0], 0x99);
    assert_int_equal(reply[1], TARN_MCP2210_UNKNOWN_COMMAND);
    /* setup writes chip and SPI settings the get commands read back */
    tarn_mcp2210 bridge;
    tarn_mcp2210_wiring pins = {3, 4, 5, 12000000};
    tarn_error err;
    assert_int_equal(tarn_mcp2210_setup(&bridge, seam, &pins, "mcp2210", &err), 0);
    assert_int_equal(e.designation[3], 1);
    assert_int_equal(e.designation[4], 0);
    assert_int_equal(e.gpio_directions & (1u << 4 | 1u << 5), 0);
    uint8_t data[70];
    memset(data, 0xA5, sizeof data);
    tarn_panel_transport t = tarn_mcp2210_transport(&bridge);
    assert_int_equal(t.data(t.user, data, sizeof data), 0); /* one transaction, two chunks */
    memset(command, 0, sizeof command);
    command[0] = TARN_MCP2210_GET_SPI_SETTINGS;
    seam.write(seam.user, command);
    seam.read(seam.user, reply, 10);
    assert_int_equal(reply[4] | reply[5] << 8 | reply[6] << 16 | (uint32_t)reply[7] << 24, 12000000);
    assert_int_equal(reply[18] | reply[19] << 8, 70);
    assert_int_equal(reply[10] | reply[11] << 8, 0x01FF & ~(1u << 3));
    /* an external master on the bus: setup says so */
    e.external_master = 1;
    assert_int_equal(tarn_mcp2210_setup(&bridge, seam, &pins, "mcp2210", &err), -1);
    assert_non_null(strstr(err.message, "external master"));
    free(panel);
}

static size_t open_fds(void)
{
    size_t count = 0;
    DIR *d = opendir("/proc/self/fd");
    assert_non_null(d);
    while (readdir(d) != NULL) count++;
    closedir(d);
    return count;
}

/* The real devices of this machine: /dev/null is no SPI device, spidev9.9 is missing. */
static void test_spidev_real_error_paths(void **state)
{
    (void)state;
    tarn_spidev spi;
    tarn_error err;
    size_t fds = open_fds();
    assert_int_equal(tarn_spidev_open(&spi, "/dev/null", 1000000, &err), -1);
    assert_non_null(strstr(err.message, "spidev:/dev/null: not an SPI device"));
    assert_int_equal(tarn_spidev_open(&spi, "/dev/spidev9.9", 1000000, &err), -1);
    assert_non_null(strstr(err.message, "spidev:/dev/spidev9.9: cannot open: No such file or directory"));
    assert_int_equal(open_fds(), fds); /* nothing left open */
    assert_true(tarn_spidev_bufsiz() >= 64);
}

static void test_gpio_real_error_paths(void **state)
{
    (void)state;
    tarn_gpio_line line;
    tarn_error err;
    char chip[32];
    unsigned offset;
    size_t fds = open_fds();
    assert_int_equal(tarn_gpio_line_request("--dc", "gpiochip99", 25, 1, &line, &err), -1);
    print_message("%s backend refuses a chip that is not there, as it must: %s\n", tarn_gpio_backend, err.message);
    assert_non_null(strstr(err.message, "--dc: "));
    assert_non_null(strstr(err.message, "gpiochip99"));
    assert_null(line.set);
    assert_int_equal(open_fds(), fds);
    assert_int_equal(tarn_gpio_parse_spec("--reset", "gpiochip0:24", chip, sizeof chip, &offset, &err), 0);
    assert_string_equal(chip, "gpiochip0");
    assert_int_equal(offset, 24);
    assert_int_equal(tarn_gpio_parse_spec("--reset", "gpiochip0", chip, sizeof chip, &offset, &err), -1);
    assert_string_equal(err.message, "--reset: expected CHIP:LINE, e.g. gpiochip0:25 (see gpioinfo), got 'gpiochip0'");
    assert_int_equal(tarn_gpio_parse_spec("--dc", "gpiochip0:x", chip, sizeof chip, &offset, &err), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_show_animates_into_the_emulator),
        cmocka_unit_test(test_spidev_shows_the_frame),
        cmocka_unit_test(test_mcp2210_shows_the_frame),
        cmocka_unit_test(test_gpio_spi_shows_the_frame),
        cmocka_unit_test(test_spidev_splits_and_clocks),
        cmocka_unit_test(test_mcp2210_sends_only_changed_tiles),
        cmocka_unit_test(test_mcp2210_recovers_from_busy_replies),
        cmocka_unit_test(test_mcp2210_unplugged_mid_frame),
        cmocka_unit_test(test_spidev_vanishes_mid_frame),
        cmocka_unit_test(test_mcp2210_stalled_ends_the_frame),
        cmocka_unit_test(test_mcp2210_emulator_answers_as_the_datasheet),
        cmocka_unit_test(test_spidev_real_error_paths),
        cmocka_unit_test(test_gpio_real_error_paths),
    };
    return cmocka_run_group_tests(tests, load_scenes, free_scenes);
}
