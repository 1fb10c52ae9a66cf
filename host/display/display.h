/* display.h: the panel link `tarn show` drives, opened from its options.
 *
 * A real link (spidev + GPIO lines, GPIO bit-bang, MCP2210 over hidapi) or the
 * panel emulator, reached directly or through one of those backends' own code
 * (`--via`): the spidev backend with its ioctl answered by the emulated module, the
 * bit-bang backend on emulated lines, the MCP2210 protocol talking to the MCP2210
 * emulator. Opening either succeeds whole or leaves nothing behind: lines released,
 * devices closed. */
#ifndef TARN_HOST_DISPLAY_H
#define TARN_HOST_DISPLAY_H

#include "display_gpio_spi.h"
#include "display_spidev.h"
#include "error.h"
#include "gpio_lines.h"
#include "link_counts.h"
#include "mcp2210.h"
#include "mcp2210_emulator.h"
#include "mcp2210_hidapi.h"
#include "panel_emulator.h"
#include "panel_link.h"
#include "panel_wiring.h"
#include "show_options.h"

enum { LINE_DC, LINE_RESET, LINE_BACKLIGHT, LINE_SCK, LINE_MOSI, LINE_CS, LINE_COUNT };

typedef struct {
    tarn_display_kind link;          /* the backend whose code sends */
    int emulated;                    /* the panel is the emulator */
    tarn_panel_transport transport;
    const tarn_link_counts *counts;
    const tarn_error *link_error;    /* the backend's reason when a transport call failed */
    uint32_t spi_hz;                 /* the link's SPI clock; 0 for the bit-bang */

    tarn_gpio_line lines[LINE_COUNT];
    tarn_spidev spidev;
    tarn_gpio_spi gpio_spi;
    tarn_mcp2210 mcp2210;
    tarn_mcp2210_usb *usb;
    char name[160];

    tarn_panel_emulator *emulator;   /* when emulated */
    tarn_panel_wiring wiring;
    tarn_mcp2210_emulator mcp2210_emulator;
    tarn_counted_link direct;        /* emulator reached directly: bytes at spi_hz */
} tarn_display;

/* 0, or -1 with one line in `err` and nothing left open. */
int tarn_display_open(tarn_display *display, const tarn_show_options *options, tarn_error *err);

/* Why the last transport call failed, as one line. */
const char *tarn_display_failure(const tarn_display *display);

/* Releases lines, closes devices, frees the emulator; safe to call twice. */
void tarn_display_close(tarn_display *display);

#endif
