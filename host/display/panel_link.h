/* panel_link.h: what the backends that drive a panel's own wires share (spidev
 * with GPIO lines, the GPIO bit-bang, the MCP2210 bridge), and the one panel
 * transport over it. A command is one byte sent with DC low, data are bytes sent
 * with DC high, reset drives the reset line where one is wired, and a delay
 * pauses the link: a sleep, or the emulated module's clock. A backend holds a
 * tarn_panel_link as its first member and gives it what differs: how bytes go
 * out, and how the reset line is driven. */
#ifndef TARN_HOST_PANEL_LINK_H
#define TARN_HOST_PANEL_LINK_H

#include <stddef.h>
#include <stdint.h>
#include "error.h"
#include "link_counts.h"
#include "tarn/tarn_panel.h"

typedef struct tarn_panel_link tarn_panel_link;

/* `count` bytes with DC at `dc` (0: command, 1: data): 0, or -1 with `error` set. */
typedef int (*tarn_link_send_fn)(tarn_panel_link *link, int dc, const uint8_t *bytes, size_t count);
/* The reset line, asserted (low) or released: 0, or -1 with `error` set. */
typedef int (*tarn_link_reset_fn)(tarn_panel_link *link, int asserted);

struct tarn_panel_link {
    tarn_link_send_fn send;
    tarn_link_reset_fn reset; /* NULL: no reset line */
    tarn_delay_fn delay;      /* tarn_sleep_ms unless replaced */
    void *delay_user;
    tarn_link_counts counts;
    tarn_error error;         /* why the last call failed */
};

/* A link sending with `send`, without a reset line yet, pausing with tarn_sleep_ms,
 * nothing counted. */
tarn_panel_link tarn_panel_link_make(tarn_link_send_fn send);

/* command() and data() through `send`, reset() when the link has a reset line,
 * delay_ms() through `delay`. */
tarn_panel_transport tarn_panel_link_transport(tarn_panel_link *link);

/* A link straight into a panel transport (the emulator's), counting its bytes and
 * transfers as an SPI link at `hz` would send them. */
typedef struct {
    tarn_panel_link link; /* first */
    tarn_panel_transport panel;
    uint32_t hz;
} tarn_counted_link;

void tarn_counted_link_init(tarn_counted_link *counted, tarn_panel_transport panel, uint32_t hz);

#endif
