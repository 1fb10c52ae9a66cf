/* panel_sink.c: tiles to the panel through core/panel/panel.c, one or two RGB565 buffers
 * (panel_sink.h says why two). */
#include "panel_sink.h"

void panel_sink_init(panel_sink *sink, tarn_panel panel, const tarn_panel_transport *transport,
                     uint8_t *first, uint8_t *second, size_t buffer_bytes, int dither)
{
    sink->panel = panel;
    sink->transport = transport;
    sink->buffer[0] = first;
    sink->buffer[1] = second != NULL ? second : first;
    sink->buffer_bytes = buffer_bytes;
    sink->next = 0;
    sink->dither = dither;
    sink->status = TARN_OK;
}

int panel_sink_send_tile(void *user, const tarn_tile *tile)
{
    panel_sink *sink = user;
    uint8_t *buffer = sink->buffer[sink->next];
    const int alternating = sink->buffer[0] != sink->buffer[1];
    if (alternating && 2u * (size_t)tile->width * tile->height > sink->buffer_bytes) {
        /* in pieces, the second piece would be converted over the first one in flight */
        sink->status = TARN_ERR_CONFIG;
        return 1;
    }
    sink->status = tarn_panel_send_tile(&sink->panel, sink->transport, tile, sink->dither,
                                        buffer, sink->buffer_bytes);
    sink->next ^= (unsigned)alternating;
    return sink->status != TARN_OK;
}

tarn_status panel_sink_frame_status(const panel_sink *sink, tarn_status status)
{
    return status == TARN_ERR_SINK && sink->status != TARN_OK ? sink->status : status;
}
