/* tarn_panel.h: SPI display controllers (ST7789, ILI9341) as command streams.
 *
 * The core speaks to a panel through a transport: command bytes (DC low), data
 * bytes (DC high), the reset line and delays. Every backend (a board's SPI+DMA, Linux
 * spidev, an MCP2210 bridge, the emulated boards' byte stream) implements it; the
 * drivers here are the same code on all of them.
 *
 * A frame goes out tile by tile: a window per tile (CASET, RASET, RAMWR, then the
 * tile's rows), or, the fast path, in bands: a row of tiles collected full-width and
 * sent inside one RAMWR for the whole frame. No frame-sized buffer is needed
 * anywhere. Pixels are RGB565, high byte first. docs/panels.md gives the byte counts, the
 * presets and where their facts come from. */
#ifndef TARN_PANEL_H
#define TARN_PANEL_H

#include <stddef.h>
#include <stdint.h>
#include "tarn_render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* command and data are required; delay_ms is required by tarn_panel_init only. */
typedef struct {
    void *user;
    /* each returns 0, or non-zero when the link failed (the frame stops) */
    int (*command)(void *user, uint8_t command);                      /* DC low */
    int (*data)(void *user, const uint8_t *bytes, size_t count);      /* DC high */
    int (*reset)(void *user, int asserted);                           /* NULL: no line */
    int (*delay_ms)(void *user, uint16_t milliseconds);
} tarn_panel_transport;

typedef enum {
    TARN_PANEL_ST7789_240X240 = 0, /* the 1.3" and 1.54" modules: 240x320 RAM, 240x240 glass */
    TARN_PANEL_ST7789_240X320 = 1,
    TARN_PANEL_ILI9341_320X240 = 2 /* 240x320 RAM used landscape */
} tarn_panel_model;

typedef struct {
    uint8_t model;              /* tarn_panel_model */
    uint8_t rotation;           /* 0..3: the picture turns this many quarter turns clockwise
                                   on the glass (the module turns counterclockwise to
                                   show it upright); numbered as TFT_eSPI's setRotation */
    uint16_t width, height;     /* visible pixels in this rotation */
    uint16_t column_offset;     /* where the glass starts in controller RAM, in this rotation */
    uint16_t row_offset;
    uint8_t madctl;             /* the MADCTL byte for this rotation (MY MX MV ML RGB MH) */
} tarn_panel;

/* The panel as a module of this model is wired and mounted, turned by `rotation`
 * quarter turns (taken modulo 4). An unknown model gives width 0, which init and
 * send_tile reject. */
tarn_panel tarn_panel_preset(tarn_panel_model model, unsigned rotation);

/* Hardware reset (when the transport has a reset line), then the controller's init
 * table: software reset, sleep out, 16-bit colour, MADCTL for the rotation, display
 * on (ST7789: and inversion on, which its IPS glass needs). Takes about 0.3 s of
 * delays. TARN_ERR_SINK if the transport failed. */
tarn_status tarn_panel_init(const tarn_panel *panel, const tarn_panel_transport *transport);

/* Sends one finished tile into its window. `line` is scratch for the RGB565 pixels
 * (2 * tile width bytes at least): the rows go out in as few data calls as it holds,
 * so one row suffices and no frame-sized buffer is needed anywhere, while a buffer
 * of the whole tile sends it in a single data call (for DMA: alternate two such
 * buffers, and let the transport wait for the previous transfer before its next
 * command). With `dither` the RGB565 conversion adds a 4x4 ordered dither fixed to
 * frame coordinates. TARN_ERR_SINK if the transport failed, TARN_ERR_CONFIG if the
 * tile lies outside the panel or `line` is short. */
tarn_status tarn_panel_send_tile(const tarn_panel *panel, const tarn_panel_transport *transport,
                                 const tarn_tile *tile, int dither, uint8_t *line, size_t line_bytes);

/* The fast path: bands. A band is a row of tiles (the sink gets them left to right,
 * top to bottom), collected as full-width RGB565 rows and sent as one data call; the
 * first band of a frame opens one window down to the panel's bottom and each later
 * band continues the same RAMWR, so a whole frame costs 11 bytes besides its pixels
 * and the caller needs one band of RGB565, never a frame. A band that does not
 * follow the last one gets a window of its own. The frame must be the panel's size. */
typedef struct {
    const tarn_panel *panel;
    const tarn_panel_transport *transport;
    uint8_t *buffer;            /* RGB565 of the band being collected */
    size_t buffer_bytes;
    int dither;
    uint16_t y, height;         /* the band being collected */
    uint16_t columns_done;      /* where its next tile starts; 0: no band in progress */
    uint16_t next_row;          /* the row the open RAMWR continues at, 0xFFFF: none */
} tarn_panel_band;

/* Bytes a band of tiles `tile_size` high needs: 2 * panel width * tile_size. */
size_t tarn_panel_band_bytes(const tarn_panel *panel, unsigned tile_size);

/* TARN_ERR_CONFIG for an unknown panel, an incomplete transport or a buffer shorter
 * than one row. The band keeps pointers to panel, transport and buffer. */
tarn_status tarn_panel_band_init(tarn_panel_band *band, const tarn_panel *panel,
                                 const tarn_panel_transport *transport, int dither, uint8_t *buffer,
                                 size_t buffer_bytes);

/* Converts the tile into the band; sends the band when the tile completes it.
 * TARN_ERR_CONFIG (and nothing sent) for a tile out of order, outside the panel, or
 * taller than the buffer holds; TARN_ERR_SINK if the transport failed. */
tarn_status tarn_panel_band_add_tile(tarn_panel_band *band, const tarn_tile *tile);

/* RGB565 of a 0x00RRGGBB pixel at frame position (x, y), rounded to nearest, or
 * ordered-dithered. The host converts frames with this same function so that a
 * panel's image can be compared with a render byte for byte. */
uint16_t tarn_rgb565(uint32_t rgb, uint16_t x, uint16_t y, int dither);

/* The controller commands the drivers use, for backends and emulators. */
enum {
    TARN_PANEL_NOP = 0x00,
    TARN_PANEL_SWRESET = 0x01,
    TARN_PANEL_SLPOUT = 0x11,
    TARN_PANEL_NORON = 0x13,
    TARN_PANEL_INVON = 0x21,
    TARN_PANEL_DISPON = 0x29,
    TARN_PANEL_CASET = 0x2A,
    TARN_PANEL_RASET = 0x2B,
    TARN_PANEL_RAMWR = 0x2C,
    TARN_PANEL_MADCTL = 0x36,
    TARN_PANEL_COLMOD = 0x3A,
    TARN_PANEL_RAMWRC = 0x3C /* write memory continue */
};

/* The emulated boards send the transport's calls as a byte stream (semihosting or a
 * UART), decoded on the host by the panel emulator:
 *   'C' command                     a command byte (DC low)
 *   'D' len_hi len_lo bytes...      data bytes (DC high), 1..65535 of them
 *   'R' level                       reset line asserted (1) or released (0)
 *   'W' ms_hi ms_lo                 a delay
 *   'E' status                      end of stream; status 0 when the firmware finished */
enum {
    TARN_STREAM_COMMAND = 'C',
    TARN_STREAM_DATA = 'D',
    TARN_STREAM_RESET = 'R',
    TARN_STREAM_DELAY = 'W',
    TARN_STREAM_END = 'E'
};

#ifdef __cplusplus
}
#endif

#endif
