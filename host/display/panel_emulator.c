#include "panel_emulator.h"

#include <string.h>

enum {
    MADCTL_MY = 0x80,
    MADCTL_MX = 0x40,
    MADCTL_MV = 0x20,
    MADCTL_BGR = 0x08,
    COLMOD_16_BIT = 0x55,
    COLMOD_AFTER_RESET = 0x66, /* 18-bit, both datasheets */
    CMD_SLPIN = 0x10,
    CMD_INVOFF = 0x20,
    CMD_DISPOFF = 0x28
};

/* The datasheets' waits: 5 ms after a reset or SLPOUT before any command, 120 ms
 * after a reset before SLPOUT. */
#define READY_AFTER_RESET_MS 5u
#define READY_AFTER_SLPOUT_MS 5u
#define SLEEP_OUT_AFTER_RESET_MS 120u

/* How a module's glass shows the controller's RAM. Upright means as the datasheet
 * draws the glass: portrait, RAM row 0 at the top. */
typedef struct {
    uint16_t width, height; /* upright glass, pixels */
    uint16_t first_row;     /* the RAM row on the glass's top line */
    uint8_t columns_mirrored; /* glass column g shows RAM column width - 1 - g */
    uint8_t bgr;            /* subpixels blue-green-red: MADCTL's BGR bit must match */
    uint8_t inverts;        /* IPS glass: true colours only with INVON */
    uint8_t rotation0_turn; /* quarter turns clockwise of the picture in rotation 0 */
} module_glass;

/* The ST7789 240x240 glass shows RAM rows 0..239; the ILI9341 modules are wired
 * right to left (the reason Adafruit's upright portrait needs MX) and are used
 * landscape by tarn, the picture a quarter turn from the glass's portrait. */
static const module_glass glasses[] = {
    [TARN_PANEL_ST7789_240X240] = {240, 240, 0, 0, 0, 1, 0},
    [TARN_PANEL_ST7789_240X320] = {240, 320, 0, 0, 0, 1, 0},
    [TARN_PANEL_ILI9341_320X240] = {240, 320, 0, 1, 1, 0, 1},
};

#define MODEL_COUNT (sizeof glasses / sizeof glasses[0])

/* Commands that configure power, timing or gamma: accepted with their parameters
 * and not modelled, because they do not change which pixel lands where. */
static const uint8_t settings_not_modelled[] = {
    0x26, 0x37, 0xB1, 0xB2, 0xB6, 0xB7, 0xBB, 0xC0, 0xC1, 0xC2, 0xC3, 0xC4,
    0xC5, 0xC6, 0xC7, 0xCB, 0xCF, 0xD0, 0xE0, 0xE1, 0xE8, 0xEA, 0xED, 0xF2, 0xF7};

static int is_setting_not_modelled(uint8_t command)
{
    for (size_t i = 0; i < sizeof settings_not_modelled; i++)
        if (settings_not_modelled[i] == command) return 1;
    return 0;
}

static unsigned parameters_needed(uint8_t command)
{
    switch (command) {
    case TARN_PANEL_CASET:
    case TARN_PANEL_RASET: return 4;
    case TARN_PANEL_MADCTL:
    case TARN_PANEL_COLMOD: return 1;
    default: return 0;
    }
}

static void controller_reset(tarn_panel_emulator *e)
{
    e->madctl = 0;
    e->colmod = COLMOD_AFTER_RESET;
    e->sleeping = 1;
    e->display_on = 0;
    e->inverted = 0;
    e->column_start = 0;
    e->column_end = TARN_PANEL_RAM_COLUMNS - 1;
    e->row_start = 0;
    e->row_end = TARN_PANEL_RAM_ROWS - 1;
    e->column = e->row = 0;
    e->have_command = e->writing = 0;
    e->parameter_count = e->have_pixel_high = 0;
    e->busy_ms = READY_AFTER_RESET_MS;
    e->sleep_out_ms = SLEEP_OUT_AFTER_RESET_MS;
    e->counts.resets++;
}

int tarn_panel_emulator_init(tarn_panel_emulator *e, tarn_panel_model model, unsigned rotation)
{
    if ((unsigned)model >= MODEL_COUNT) return -1;
    memset(e, 0, sizeof *e);
    e->model = (uint8_t)model;
    e->rotation = (uint8_t)(rotation & 3u);
    controller_reset(e);
    e->busy_ms = e->sleep_out_ms = 0; /* power-on: the first reset is the driver's job */
    e->counts.resets = 0;
    return 0;
}

/* ---- Commands and parameters ---- */

/* The command before this one ends: one that lacked parameters had no effect. */
static void end_command(tarn_panel_emulator *e)
{
    if (e->have_command && e->parameter_count < parameters_needed(e->command))
        e->counts.parameters_incomplete++;
    e->have_command = e->writing = 0;
    e->parameter_count = e->have_pixel_high = 0;
}

static int accepts_command(tarn_panel_emulator *e, uint8_t command)
{
    if (e->reset_held || e->busy_ms > 0) return 0;
    return !(command == TARN_PANEL_SLPOUT && e->sleep_out_ms > 0);
}

static void run_command(tarn_panel_emulator *e, uint8_t command)
{
    switch (command) {
    case TARN_PANEL_SWRESET: controller_reset(e); return;
    case TARN_PANEL_SLPOUT:
        e->sleeping = 0;
        e->busy_ms = READY_AFTER_SLPOUT_MS;
        return;
    case CMD_SLPIN: e->sleeping = 1; return;
    case TARN_PANEL_INVON: e->inverted = 1; return;
    case CMD_INVOFF: e->inverted = 0; return;
    case TARN_PANEL_DISPON: e->display_on = 1; return;
    case CMD_DISPOFF: e->display_on = 0; return;
    case TARN_PANEL_RAMWR:
        e->column = e->column_start;
        e->row = e->row_start;
        e->writing = 1;
        return;
    case TARN_PANEL_RAMWRC: e->writing = 1; return;
    case TARN_PANEL_NOP:
    case TARN_PANEL_NORON:
    case TARN_PANEL_CASET:
    case TARN_PANEL_RASET:
    case TARN_PANEL_MADCTL:
    case TARN_PANEL_COLMOD: return;
    default:
        if (!is_setting_not_modelled(command)) e->counts.unknown_commands++;
    }
}

int tarn_panel_emulator_command(tarn_panel_emulator *e, uint8_t command)
{
    e->counts.commands++;
    end_command(e);
    if (!accepts_command(e, command)) {
        e->counts.commands_too_early++;
        return 0;
    }
    e->command = command;
    e->have_command = 1;
    run_command(e, command);
    return 0;
}

static uint16_t u16_be(const uint8_t *bytes)
{
    return (uint16_t)((bytes[0] << 8) | bytes[1]);
}

/* A start after the end leaves the window as it was. */
static void set_range(const uint8_t p[4], uint16_t *start, uint16_t *end)
{
    if (u16_be(p) > u16_be(p + 2)) return;
    *start = u16_be(p);
    *end = u16_be(p + 2);
}

static void apply_parameters(tarn_panel_emulator *e)
{
    const uint8_t *p = e->parameters;
    switch (e->command) {
    case TARN_PANEL_CASET: set_range(p, &e->column_start, &e->column_end); break;
    case TARN_PANEL_RASET: set_range(p, &e->row_start, &e->row_end); break;
    case TARN_PANEL_MADCTL: e->madctl = p[0]; break;
    case TARN_PANEL_COLMOD: e->colmod = p[0]; break;
    }
}

static void take_parameters(tarn_panel_emulator *e, const uint8_t *bytes, size_t count)
{
    unsigned needed = parameters_needed(e->command);
    for (size_t i = 0; i < count; i++) {
        if (e->parameter_count == needed) {
            e->counts.data_ignored += (uint32_t)(count - i);
            return;
        }
        e->parameters[e->parameter_count++] = bytes[i];
        if (e->parameter_count == needed) apply_parameters(e);
    }
}

/* ---- Pixels ---- */

/* Where the logical address lands in the physical RAM under MADCTL; 0 if outside. */
static int physical_index(uint8_t madctl, uint16_t column, uint16_t row, size_t *index)
{
    unsigned c = (madctl & MADCTL_MV) ? row : column;
    unsigned r = (madctl & MADCTL_MV) ? column : row;
    if (c >= TARN_PANEL_RAM_COLUMNS || r >= TARN_PANEL_RAM_ROWS) return 0;
    if (madctl & MADCTL_MX) c = TARN_PANEL_RAM_COLUMNS - 1u - c;
    if (madctl & MADCTL_MY) r = TARN_PANEL_RAM_ROWS - 1u - r;
    *index = (size_t)r * TARN_PANEL_RAM_COLUMNS + c;
    return 1;
}

static void advance_write_pointer(tarn_panel_emulator *e)
{
    if (e->column < e->column_end) {
        e->column++;
        return;
    }
    e->column = e->column_start;
    e->row = e->row < e->row_end ? (uint16_t)(e->row + 1u) : e->row_start;
}

static void write_pixel(tarn_panel_emulator *e, uint16_t pixel)
{
    size_t index;
    if (physical_index(e->madctl, e->column, e->row, &index)) {
        e->ram[index] = pixel;
        e->counts.pixels_written++;
    } else {
        e->counts.pixels_outside_ram++;
    }
    advance_write_pointer(e);
}

static void write_pixels(tarn_panel_emulator *e, const uint8_t *bytes, size_t count)
{
    if (e->colmod != COLMOD_16_BIT) {
        e->counts.pixel_bytes_ignored += (uint32_t)count;
        return;
    }
    for (size_t i = 0; i < count; i++) {
        if (!e->have_pixel_high) {
            e->pixel_high = bytes[i];
            e->have_pixel_high = 1;
        } else {
            write_pixel(e, (uint16_t)((e->pixel_high << 8) | bytes[i]));
            e->have_pixel_high = 0;
        }
    }
}

int tarn_panel_emulator_data(tarn_panel_emulator *e, const uint8_t *bytes, size_t count)
{
    e->counts.data_bytes += (uint32_t)count;
    if (!e->have_command || e->reset_held)
        e->counts.data_ignored += (uint32_t)count;
    else if (e->writing)
        write_pixels(e, bytes, count);
    else if (parameters_needed(e->command) > 0)
        take_parameters(e, bytes, count);
    else if (!is_setting_not_modelled(e->command))
        e->counts.data_ignored += (uint32_t)count;
    return 0;
}

int tarn_panel_emulator_reset(tarn_panel_emulator *e, int asserted)
{
    if (asserted) {
        end_command(e);
        e->reset_held = 1;
    } else if (e->reset_held) {
        e->reset_held = 0;
        controller_reset(e); /* the timers start when the line is released */
    }
    return 0;
}

static uint32_t elapse(uint32_t remaining, uint16_t milliseconds)
{
    return remaining > milliseconds ? remaining - milliseconds : 0;
}

int tarn_panel_emulator_delay(tarn_panel_emulator *e, uint16_t milliseconds)
{
    e->counts.delay_ms += milliseconds;
    e->busy_ms = elapse(e->busy_ms, milliseconds);
    e->sleep_out_ms = elapse(e->sleep_out_ms, milliseconds);
    return 0;
}

static int transport_command(void *user, uint8_t command)
{
    return tarn_panel_emulator_command(user, command);
}

static int transport_data(void *user, const uint8_t *bytes, size_t count)
{
    return tarn_panel_emulator_data(user, bytes, count);
}

static int transport_reset(void *user, int asserted)
{
    return tarn_panel_emulator_reset(user, asserted);
}

static int transport_delay(void *user, uint16_t milliseconds)
{
    return tarn_panel_emulator_delay(user, milliseconds);
}

tarn_panel_transport tarn_panel_emulator_transport(tarn_panel_emulator *e)
{
    tarn_panel_transport transport = {e, transport_command, transport_data, transport_reset,
                                      transport_delay};
    return transport;
}

/* ---- The glass ---- */

static unsigned picture_turn(const tarn_panel_emulator *e)
{
    return (glasses[e->model].rotation0_turn + e->rotation) & 3u;
}

uint16_t tarn_panel_emulator_width(const tarn_panel_emulator *e)
{
    const module_glass *g = &glasses[e->model];
    return (picture_turn(e) & 1u) ? g->height : g->width;
}

uint16_t tarn_panel_emulator_height(const tarn_panel_emulator *e)
{
    const module_glass *g = &glasses[e->model];
    return (picture_turn(e) & 1u) ? g->width : g->height;
}

/* The upright glass pixel a viewer sees at (x, y) of a picture turned `turn`
 * quarter turns clockwise on the glass. */
static void glass_position(const module_glass *g, unsigned turn, unsigned x, unsigned y,
                           unsigned *column, unsigned *row)
{
    switch (turn) {
    case 0: *column = x; *row = y; break;
    case 1: *column = g->width - 1u - y; *row = x; break;
    case 2: *column = g->width - 1u - x; *row = g->height - 1u - y; break;
    default: *column = y; *row = g->height - 1u - x; break;
    }
}

static uint16_t swap_red_blue(uint16_t pixel)
{
    return (uint16_t)((pixel >> 11) | (pixel & 0x07E0u) | ((pixel & 0x1Fu) << 11));
}

/* What the glass shows for a RAM pixel with the registers as they are now. */
static uint16_t shown_colour(const tarn_panel_emulator *e, const module_glass *g, uint16_t pixel)
{
    if (e->sleeping || !e->display_on) return 0;
    if (((e->madctl & MADCTL_BGR) != 0) != g->bgr) pixel = swap_red_blue(pixel);
    if (e->inverted != g->inverts) pixel = (uint16_t)~pixel;
    return pixel;
}

/* The colour a viewer sees at (x, y) of the picture. */
static uint16_t picture_pixel(const tarn_panel_emulator *e, unsigned x, unsigned y)
{
    const module_glass *g = &glasses[e->model];
    unsigned column, row;
    glass_position(g, picture_turn(e), x, y, &column, &row);
    if (g->columns_mirrored) column = g->width - 1u - column;
    return shown_colour(e, g, e->ram[(size_t)(g->first_row + row) * TARN_PANEL_RAM_COLUMNS + column]);
}

void tarn_panel_emulator_image(const tarn_panel_emulator *e, uint16_t *rgb565)
{
    unsigned width = tarn_panel_emulator_width(e), height = tarn_panel_emulator_height(e);
    for (unsigned y = 0; y < height; y++)
        for (unsigned x = 0; x < width; x++) *rgb565++ = picture_pixel(e, x, y);
}

void tarn_rgb565_to_rgb888(uint16_t pixel, uint8_t rgb[3])
{
    unsigned r = pixel >> 11, g = (pixel >> 5) & 0x3Fu, b = pixel & 0x1Fu;
    rgb[0] = (uint8_t)((r << 3) | (r >> 2));
    rgb[1] = (uint8_t)((g << 2) | (g >> 4));
    rgb[2] = (uint8_t)((b << 3) | (b >> 2));
}

void tarn_panel_emulator_image_rgb888(const tarn_panel_emulator *e, uint8_t *rgb)
{
    unsigned width = tarn_panel_emulator_width(e), height = tarn_panel_emulator_height(e);
    for (unsigned y = 0; y < height; y++)
        for (unsigned x = 0; x < width; x++, rgb += 3) tarn_rgb565_to_rgb888(picture_pixel(e, x, y), rgb);
}
