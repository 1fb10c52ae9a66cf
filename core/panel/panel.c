/* panel.c: the panel drivers: presets, init, tile windows and the RGB565 conversion.
 * The facts per model live in panel_tables.c; this file only walks them. */
#include "tarn/tarn_panel.h"

#include "panel/panel_tables_internal.h"

/* The reset pulse: the datasheets ask for at least 10 us low, then 5 ms before the
 * first command (120 ms when the controller was awake); we hold and wait generously
 * because it happens once. */
#define RESET_HOLD_MS 10u
#define RESET_RECOVERY_MS 120u

tarn_panel tarn_panel_preset(tarn_panel_model model, unsigned rotation)
{
    tarn_panel panel = {0};
    const tarn_panel_model_facts *facts = tarn__panel_model_facts_of((unsigned)model);
    if (facts == NULL) return panel; /* width 0: init and send_tile reject it */
    rotation &= 3u;
    panel.model = (uint8_t)model;
    panel.rotation = (uint8_t)rotation;
    panel.width = (rotation & 1u) ? facts->height : facts->width;
    panel.height = (rotation & 1u) ? facts->width : facts->height;
    panel.column_offset = facts->column_offset[rotation];
    panel.row_offset = facts->row_offset[rotation];
    panel.madctl = facts->madctl[rotation];
    return panel;
}

static int send_command(const tarn_panel_transport *transport, uint8_t command,
                        const uint8_t *data, size_t count)
{
    if (transport->command(transport->user, command) != 0) return -1;
    return count == 0 ? 0 : transport->data(transport->user, data, count);
}

static int wait_ms(const tarn_panel_transport *transport, uint16_t milliseconds)
{
    return milliseconds == 0 ? 0 : transport->delay_ms(transport->user, milliseconds);
}

static int reset_pulse(const tarn_panel_transport *transport)
{
    if (transport->reset(transport->user, 1) != 0) return -1;
    if (wait_ms(transport, RESET_HOLD_MS) != 0) return -1;
    if (transport->reset(transport->user, 0) != 0) return -1;
    return wait_ms(transport, RESET_RECOVERY_MS);
}

/* One packed step (panel_tables.h); returns its size in bytes, or 0 on failure. */
static size_t send_init_step(const tarn_panel *panel, const tarn_panel_transport *transport,
                             const uint8_t *step)
{
    const uint8_t command = step[0], length = step[1], delay_ms = step[2];
    /* MADCTL is the one step that depends on the rotation; the table holds a placeholder */
    const uint8_t *data = command == TARN_PANEL_MADCTL ? &panel->madctl : step + TARN_PANEL_STEP_HEADER;
    if (send_command(transport, command, data, length) != 0 || wait_ms(transport, delay_ms) != 0) return 0;
    return TARN_PANEL_STEP_HEADER + length;
}

static int transport_complete(const tarn_panel_transport *transport)
{
    return transport != NULL && transport->command != NULL && transport->data != NULL;
}

tarn_status tarn_panel_init(const tarn_panel *panel, const tarn_panel_transport *transport)
{
    const tarn_panel_model_facts *facts = panel ? tarn__panel_model_facts_of(panel->model) : NULL;
    if (facts == NULL || panel->width == 0 || !transport_complete(transport) ||
        transport->delay_ms == NULL)
        return TARN_ERR_CONFIG;
    if (transport->reset != NULL && reset_pulse(transport) != 0) return TARN_ERR_SINK;
    for (size_t at = 0; at < facts->init_bytes;) {
        const size_t step = send_init_step(panel, transport, facts->init + at);
        if (step == 0) return TARN_ERR_SINK;
        at += step;
    }
    return TARN_OK;
}

static void put_u16_be(uint8_t *out, uint16_t value)
{
    out[0] = (uint8_t)(value >> 8);
    out[1] = (uint8_t)value;
}

/* CASET or RASET: first and last address, big-endian. */
static int set_address_range(const tarn_panel_transport *transport, uint8_t command,
                             uint16_t first, uint16_t count)
{
    uint8_t range[4];
    put_u16_be(range, first);
    put_u16_be(range + 2, (uint16_t)(first + count - 1u));
    return send_command(transport, command, range, sizeof range);
}

static int tile_fits(const tarn_panel *panel, const tarn_tile *tile)
{
    return tile->width > 0 && tile->height > 0 && tile->rgb != NULL &&
           (uint32_t)tile->x + tile->width <= panel->width &&
           (uint32_t)tile->y + tile->height <= panel->height;
}

/* Dither thresholds, the 4x4 Bayer matrix indexed by (y & 3) * 4 + (x & 3). */
static const uint8_t bayer4[16] = {0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5};

/* Rounding to nearest is the threshold 127 (255 is odd, so there are no ties). The
 * dither replaces it with 16 * bayer + 8, from 8 to 248: the same as adding between
 * -0.47 and +0.47 of an output step before rounding, evenly spread over each 4x4 block.
 * value * levels + threshold never reaches 256 * levels, so the result cannot leave
 * the channel's range: the saturation is built in. This is the threshold of pixel
 * (x, y) of the frame. */
static uint32_t dither_threshold(uint32_t x, uint32_t y, int dither)
{
    return dither ? 16u * bayer4[(y & 3u) * 4u + (x & 3u)] + 8u : 127u;
}

/* What a threshold adds before the division by 255: to red and blue side by side
 * in the halves of a word, and to green, each with the 1 of halves_over_255. */
typedef struct {
    uint32_t rb, g;
} rgb565_threshold;

static rgb565_threshold threshold_of(uint32_t threshold)
{
    const rgb565_threshold t = {(threshold + 1u) * 0x00010001u, threshold + 1u};
    return t;
}

/* Each channel floor((value * levels + threshold) / 255), with floor(n / 255) as
 * floor((n + 1 + floor(n / 256)) / 256), exact for n below 65535: no division,
 * which the Cortex-M0 lacks. Red and blue (31 levels) share the halves of one word,
 * as 31 * 255 + 255 stays below 2^16; green (63 levels) goes alone. */
static inline uint16_t rgb565_with(uint32_t rgb, rgb565_threshold t)
{
    uint32_t rb = rgb & 0x00FF00FFu;
    rb = (rb << 5) - rb + t.rb;
    rb = (rb + ((rb >> 8) & 0x00FF00FFu)) >> 8; /* red in bits 16..20, blue in 0..4 */
    uint32_t g = (rgb >> 8) & 0xFFu;
    g = (g << 6) - g + t.g;
    g = (g + (g >> 8)) >> 8;
    return (uint16_t)(((rb >> 5) & 0xF800u) | (g << 5) | (rb & 0x1Fu));
}

uint16_t tarn_rgb565(uint32_t rgb, uint16_t x, uint16_t y, int dither)
{
    return rgb565_with(rgb, threshold_of(dither_threshold(x, y, dither)));
}

/* A row of pixels at `rgb` to RGB565 at `out`, high byte first, pixel i at the
 * dither phase i % 4. Four at a time: the phases' thresholds stay put. */
static void convert_row(uint8_t *out, const uint32_t *rgb, uint32_t width, const rgb565_threshold t[4])
{
    const uint32_t *const end = rgb + width, *const whole_groups_end = rgb + (width & ~3u);
    for (; rgb != whole_groups_end; rgb += 4, out += 8) {
        put_u16_be(out, rgb565_with(rgb[0], t[0]));
        put_u16_be(out + 2, rgb565_with(rgb[1], t[1]));
        put_u16_be(out + 4, rgb565_with(rgb[2], t[2]));
        put_u16_be(out + 6, rgb565_with(rgb[3], t[3]));
    }
    for (uint32_t k = 0; rgb != end; rgb++, out += 2, k++) put_u16_be(out, rgb565_with(*rgb, t[k]));
}

/* Rows [first, first + count) of the tile as RGB565, high byte first, dithered at
 * frame positions, `out_stride` bytes apart in `out`. A row's four thresholds are
 * looked up once: they repeat every four pixels. */
static void convert_rows(uint8_t *out, size_t out_stride, const tarn_tile *tile, uint16_t first,
                         uint16_t count, int dither)
{
    for (uint32_t row = first; row < (uint32_t)first + count; row++, out += out_stride) {
        rgb565_threshold t[4];
        for (uint32_t k = 0; k < 4u; k++) t[k] = threshold_of(dither_threshold(tile->x + k, tile->y + row, dither));
        convert_row(out, tile->rgb + (size_t)row * tile->stride, tile->width, t);
    }
}

/* CASET, RASET and RAMWR for the rectangle at (x, y), in panel coordinates. */
static int set_window(const tarn_panel *panel, const tarn_panel_transport *transport, uint16_t x,
                      uint16_t y, uint16_t width, uint16_t height)
{
    return set_address_range(transport, TARN_PANEL_CASET, (uint16_t)(panel->column_offset + x), width) != 0 ||
           set_address_range(transport, TARN_PANEL_RASET, (uint16_t)(panel->row_offset + y), height) != 0 ||
           transport->command(transport->user, TARN_PANEL_RAMWR) != 0;
}

/* The first rows are converted before the window is set: a transport that sends
 * data by DMA and waits for it before its next command gets the conversion done
 * while the previous tile is still going out. */
tarn_status tarn_panel_send_tile(const tarn_panel *panel, const tarn_panel_transport *transport,
                                 const tarn_tile *tile, int dither, uint8_t *line, size_t line_bytes)
{
    if (panel == NULL || tile == NULL || line == NULL || !transport_complete(transport) ||
        !tile_fits(panel, tile) || line_bytes < 2u * (size_t)tile->width)
        return TARN_ERR_CONFIG;
    const size_t row_bytes = 2u * (size_t)tile->width;
    const uint16_t rows_per_call =
        line_bytes / row_bytes < tile->height ? (uint16_t)(line_bytes / row_bytes) : tile->height;
    for (uint16_t row = 0; row < tile->height; row = (uint16_t)(row + rows_per_call)) {
        const uint16_t rows = tile->height - row < rows_per_call ? (uint16_t)(tile->height - row) : rows_per_call;
        convert_rows(line, row_bytes, tile, row, rows, dither);
        if ((row == 0 && set_window(panel, transport, tile->x, tile->y, tile->width, tile->height) != 0) ||
            transport->data(transport->user, line, row_bytes * rows) != 0)
            return TARN_ERR_SINK;
    }
    return TARN_OK;
}

/* ---- Bands: a row of tiles, full panel width, continuing one RAMWR ---- */

#define BAND_NO_WRITE 0xFFFFu /* next_row when no RAMWR is open */

size_t tarn_panel_band_bytes(const tarn_panel *panel, unsigned tile_size)
{
    return panel == NULL ? 0 : 2u * (size_t)panel->width * tile_size;
}

tarn_status tarn_panel_band_init(tarn_panel_band *band, const tarn_panel *panel,
                                 const tarn_panel_transport *transport, int dither, uint8_t *buffer,
                                 size_t buffer_bytes)
{
    if (band == NULL || panel == NULL || panel->width == 0 || buffer == NULL ||
        !transport_complete(transport) || buffer_bytes < 2u * (size_t)panel->width)
        return TARN_ERR_CONFIG;
    band->panel = panel;
    band->transport = transport;
    band->buffer = buffer;
    band->buffer_bytes = buffer_bytes;
    band->dither = dither;
    band->y = band->height = band->columns_done = 0;
    band->next_row = BAND_NO_WRITE;
    return TARN_OK;
}

/* The tile is the next one of the band in progress, or starts a band at the left edge. */
static int band_accepts(const tarn_panel_band *band, const tarn_tile *tile)
{
    if (!tile_fits(band->panel, tile) ||
        2u * (size_t)band->panel->width * tile->height > band->buffer_bytes)
        return 0;
    if (band->columns_done == 0) return tile->x == 0;
    return tile->x == band->columns_done && tile->y == band->y && tile->height == band->height;
}

/* The collected band as pixel data. Its rows continue the open RAMWR when they come
 * right after the last band's, so a frame sent top to bottom needs a single window
 * (rows to the panel's bottom) and the controller's address counter does the rest. */
static int send_band(tarn_panel_band *band)
{
    const tarn_panel *panel = band->panel;
    const tarn_panel_transport *transport = band->transport;
    if (band->y != band->next_row &&
        set_window(panel, transport, 0, band->y, panel->width, (uint16_t)(panel->height - band->y)) != 0)
        return -1;
    band->next_row = BAND_NO_WRITE; /* until the data went out */
    if (transport->data(transport->user, band->buffer, 2u * (size_t)panel->width * band->height) != 0)
        return -1;
    const uint16_t next = (uint16_t)(band->y + band->height);
    band->next_row = next < panel->height ? next : BAND_NO_WRITE;
    return 0;
}

tarn_status tarn_panel_band_add_tile(tarn_panel_band *band, const tarn_tile *tile)
{
    if (band == NULL || band->buffer == NULL || tile == NULL) return TARN_ERR_CONFIG;
    if (!band_accepts(band, tile)) {
        band->columns_done = 0; /* the next band starts afresh, with its own window */
        band->next_row = BAND_NO_WRITE;
        return TARN_ERR_CONFIG;
    }
    if (band->columns_done == 0) {
        band->y = tile->y;
        band->height = tile->height;
    }
    const size_t row_bytes = 2u * (size_t)band->panel->width;
    convert_rows(band->buffer + 2u * (size_t)tile->x, row_bytes, tile, 0, tile->height, band->dither);
    band->columns_done = (uint16_t)(band->columns_done + tile->width);
    if (band->columns_done < band->panel->width) return TARN_OK;
    band->columns_done = 0;
    return send_band(band) == 0 ? TARN_OK : TARN_ERR_SINK;
}

