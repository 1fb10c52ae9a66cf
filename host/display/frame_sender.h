/* frame_sender.h: a frame to the panel by one of the three send paths.
 *
 *   bands    full-width bands inside one RAMWR (tarn_panel_band): the fast path
 *   tiles    a window per tile (tarn_panel_send_tile), each tile in one data call
 *   changed  a window per tile, only for tiles whose RGB565 differs from what the
 *            panel already shows: for slow links such as the MCP2210
 * Tiles come left to right, top to bottom, from tarn_render_frame directly (the
 * sender is a tile sink) or from a stored frame. */
#ifndef TARN_HOST_FRAME_SENDER_H
#define TARN_HOST_FRAME_SENDER_H

#include <stdint.h>
#include "error.h"
#include "show_options.h"
#include "tarn/tarn_panel.h"

typedef struct {
    const tarn_panel *panel;
    const tarn_panel_transport *transport;
    tarn_send_mode mode;
    int dither;
    unsigned tile_size;
    uint8_t *scratch;          /* RGB565: a band, or a whole tile */
    size_t scratch_bytes;
    tarn_panel_band band;
    uint16_t *shown;           /* changed: what the panel shows, RGB565, panel-sized */
    int shown_valid;           /* the panel shows `shown` (a frame went out whole) */
    uint64_t tiles_sent, tiles_skipped;
    tarn_status status;        /* why the last frame stopped; TARN_OK */
} tarn_frame_sender;

/* 0, or -1 with `err` set (out of memory). */
int tarn_frame_sender_init(tarn_frame_sender *sender, const tarn_panel *panel,
                           const tarn_panel_transport *transport, tarn_send_mode mode, int dither,
                           unsigned tile_size, tarn_error *err);

/* A tarn_tile_sink; `user` is the sender. */
int tarn_frame_sender_tile(void *user, const tarn_tile *tile);

/* A stored frame (panel width x height pixels 0x00RRGGBB), tile by tile. */
tarn_status tarn_frame_sender_send(tarn_frame_sender *sender, const uint32_t *frame);

/* The panel may no longer show what the sender thinks (a failed frame): the next
 * `changed` frame goes out whole. */
void tarn_frame_sender_forget(tarn_frame_sender *sender);

void tarn_frame_sender_free(tarn_frame_sender *sender);

#endif
