/* panel_emulator.h: an ST7789 or ILI9341 controller and the glass of its module, in
 * host memory, driven by the same transport calls as the real thing.
 *
 * The controller: after power-on or a reset it sleeps with the display off, MADCTL
 * 0, colour mode 18-bit (0x66) and the full window. CASET and RASET take four bytes
 * (big-endian start and end; with fewer the command does nothing), MADCTL and
 * COLMOD one. RAMWR starts at the window's top-left corner, pixels (two bytes, high
 * first, only in colour mode 0x55) fill it row by row and wrap to its start when
 * it is full; RAMWRC continues where the last write stopped; any other command ends
 * the write. Data nobody waits for, unknown commands and pixels in another colour
 * mode are ignored and counted. Commands sooner than 5 ms after a reset or SLPOUT,
 * and SLPOUT sooner than 120 ms after a reset, are ignored and counted: time passes
 * only in delay calls, so the emulator is stricter than a real link. Scrolling,
 * partial and idle modes are not modelled.
 *
 * RAM is stored physically, 240 columns by 320 rows: the logical address (column,
 * row) goes through MADCTL as the datasheets' figures show (MV exchanges column and
 * row, then MX mirrors the column within 240, MY the row within 320).
 *
 * The glass is the emulator's own description of each module, independent of the
 * presets in core/: which RAM rows and columns it shows and in which direction,
 * its subpixel order (BGR for the ILI9341 modules), whether it inverts (the ST7789
 * modules are IPS glass, which needs INVON), and how a viewer holds it for a
 * rotation. The image is what that viewer sees, so a wrong offset, MADCTL byte or
 * init sequence in a driver shows up as a different image. */
#ifndef TARN_HOST_PANEL_EMULATOR_H
#define TARN_HOST_PANEL_EMULATOR_H

#include <stddef.h>
#include <stdint.h>
#include "tarn/tarn_panel.h"

#define TARN_PANEL_RAM_COLUMNS 240u
#define TARN_PANEL_RAM_ROWS 320u

typedef struct {
    uint32_t commands;             /* every command byte, even ignored ones */
    uint32_t data_bytes;           /* every data byte, even ignored ones */
    uint32_t pixels_written;       /* pixels stored in RAM */
    uint32_t pixels_outside_ram;   /* addressed past the RAM in the MADCTL of the moment */
    uint32_t pixel_bytes_ignored;  /* RAMWR data in a colour mode other than 0x55 */
    uint32_t data_ignored;         /* bytes no command was waiting for, extra parameters */
    uint32_t parameters_incomplete; /* CASET, RASET, MADCTL, COLMOD ended short: no effect */
    uint32_t unknown_commands;
    uint32_t commands_too_early;   /* sent while the controller was still resetting or waking */
    uint32_t resets;               /* hardware resets and SWRESETs */
    uint32_t delay_ms;             /* sum of all delays */
} tarn_panel_emulator_counts;

typedef struct {
    uint8_t model, rotation; /* the module and how the viewer holds it */

    /* controller registers */
    uint8_t madctl, colmod;
    uint8_t sleeping, display_on, inverted;
    uint16_t column_start, column_end, row_start, row_end; /* the window, logical */

    /* the command in progress */
    uint8_t command, have_command, writing;
    uint8_t parameters[4], parameter_count;
    uint8_t pixel_high, have_pixel_high;   /* a pixel's first byte, across data calls */
    uint16_t column, row;                  /* where the next pixel goes, logical */

    /* the link */
    uint8_t reset_held;
    uint32_t busy_ms;       /* until the controller takes commands again */
    uint32_t sleep_out_ms;  /* until SLPOUT may follow a reset */

    tarn_panel_emulator_counts counts;
    uint16_t ram[TARN_PANEL_RAM_ROWS * TARN_PANEL_RAM_COLUMNS]; /* physical, row-major */
} tarn_panel_emulator;

/* Power-on state: RAM zero, registers as after a reset. 0, or -1 for an unknown
 * model. `rotation` is taken modulo 4, as tarn_panel_preset does. */
int tarn_panel_emulator_init(tarn_panel_emulator *emulator, tarn_panel_model model,
                             unsigned rotation);

/* The transport calls, applied to the emulator; each returns 0. */
int tarn_panel_emulator_command(tarn_panel_emulator *emulator, uint8_t command);
int tarn_panel_emulator_data(tarn_panel_emulator *emulator, const uint8_t *bytes, size_t count);
int tarn_panel_emulator_reset(tarn_panel_emulator *emulator, int asserted);
int tarn_panel_emulator_delay(tarn_panel_emulator *emulator, uint16_t milliseconds);

/* A transport whose calls go to `emulator`. */
tarn_panel_transport tarn_panel_emulator_transport(tarn_panel_emulator *emulator);

/* The visible picture as the viewer holds the module. */
uint16_t tarn_panel_emulator_width(const tarn_panel_emulator *emulator);
uint16_t tarn_panel_emulator_height(const tarn_panel_emulator *emulator);

/* The picture, width * height RGB565 words, rows top to bottom. Black while the
 * controller sleeps or the display is off. */
void tarn_panel_emulator_image(const tarn_panel_emulator *emulator, uint16_t *rgb565);

/* The same picture as RGB888 (3 bytes per pixel, for PNGs), each channel widened by
 * repeating its top bits, so 0 stays 0 and full scale becomes 255. */
void tarn_panel_emulator_image_rgb888(const tarn_panel_emulator *emulator, uint8_t *rgb);

void tarn_rgb565_to_rgb888(uint16_t pixel, uint8_t rgb[3]);

#endif
