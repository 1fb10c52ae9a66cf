/* panel_sink.h: the tile sink that sends every finished tile to the panel: RGB565
 * conversion, the tile's window and its pixels, through a panel transport.
 *
 * With one buffer the pixels go out as many rows at a time as it holds (one row is
 * enough). With two buffers, each holding a whole tile, the tiles alternate between
 * them and each tile's pixels leave in a single data call: a transport whose data()
 * only starts a DMA transfer then sends one tile while the core renders the next.
 * That works because the transport waits for the previous transfer before its next
 * command, and the next command (the next tile's window) comes only after the next
 * tile was converted into the other buffer. */
#ifndef TARN_FIRMWARE_PANEL_SINK_H
#define TARN_FIRMWARE_PANEL_SINK_H

#include <stddef.h>
#include <stdint.h>
#include "tarn/tarn_panel.h"

typedef struct {
    tarn_panel panel;
    const tarn_panel_transport *transport;
    uint8_t *buffer[2];    /* RGB565 scratch; the same one twice when not alternating */
    size_t buffer_bytes;   /* of each buffer */
    unsigned next;         /* the buffer the next tile is converted into */
    int dither;            /* ordered dither in the RGB565 conversion */
    tarn_status status;    /* why the sink stopped a frame; TARN_OK while it has not */
} panel_sink;

/* `second` may be NULL or equal to `first`: one buffer, no alternation. With two
 * distinct buffers, a tile that does not fit one of them whole stops the frame
 * with TARN_ERR_CONFIG instead of overwriting pixels still being sent. */
void panel_sink_init(panel_sink *sink, tarn_panel panel, const tarn_panel_transport *transport,
                     uint8_t *first, uint8_t *second, size_t buffer_bytes, int dither);

/* A tarn_tile_sink; `user` is the panel_sink. */
int panel_sink_send_tile(void *user, const tarn_tile *tile);

/* The frame's status once tarn_render_frame returned `status`: the sink's reason
 * when it was the sink that stopped the frame. */
tarn_status panel_sink_frame_status(const panel_sink *sink, tarn_status status);

#endif
