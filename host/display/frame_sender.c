/* frame_sender.c: the three send paths (frame_sender.h). */
#include "frame_sender.h"

#include <stdlib.h>
#include <string.h>

int tarn_frame_sender_init(tarn_frame_sender *s, const tarn_panel *panel, const tarn_panel_transport *transport,
                           tarn_send_mode mode, int dither, unsigned tile_size, tarn_error *err)
{
    memset(s, 0, sizeof *s);
    s->panel = panel;
    s->transport = transport;
    s->mode = mode;
    s->dither = dither;
    s->tile_size = tile_size;
    size_t pixels = (size_t)panel->width * panel->height;
    s->scratch_bytes = mode == TARN_SEND_BANDS ? tarn_panel_band_bytes(panel, tile_size) : 2u * tile_size * tile_size;
    s->scratch = malloc(s->scratch_bytes);
    if (mode == TARN_SEND_CHANGED) s->shown = malloc(pixels * sizeof *s->shown);
    if (s->scratch == NULL || (mode == TARN_SEND_CHANGED && s->shown == NULL)) {
        tarn_frame_sender_free(s);
        return tarn_fail(err, "out of memory for the panel's send buffers");
    }
    if (mode == TARN_SEND_BANDS &&
        tarn_panel_band_init(&s->band, panel, transport, dither, s->scratch, s->scratch_bytes) != TARN_OK) {
        tarn_frame_sender_free(s);
        return tarn_fail(err, "the panel's band buffer cannot be set up");
    }
    return 0;
}

/* 1 if the tile's RGB565 differs from what the panel shows, which then takes it. */
static int tile_changed(tarn_frame_sender *s, const tarn_tile *tile)
{
    int changed = !s->shown_valid;
    for (uint16_t row = 0; row < tile->height; row++) {
        uint16_t *shown = s->shown + (size_t)(tile->y + row) * s->panel->width + tile->x;
        for (uint16_t i = 0; i < tile->width; i++) {
            uint16_t pixel = tarn_rgb565(tile->rgb[(size_t)row * tile->stride + i], (uint16_t)(tile->x + i),
                                         (uint16_t)(tile->y + row), s->dither);
            changed |= shown[i] != pixel;
            shown[i] = pixel;
        }
    }
    return changed;
}

int tarn_frame_sender_tile(void *user, const tarn_tile *tile)
{
    tarn_frame_sender *s = user;
    if (s->mode == TARN_SEND_BANDS) {
        s->status = tarn_panel_band_add_tile(&s->band, tile);
    } else if (s->mode == TARN_SEND_CHANGED && !tile_changed(s, tile)) {
        s->tiles_skipped++;
        return 0;
    } else {
        s->status = tarn_panel_send_tile(s->panel, s->transport, tile, s->dither, s->scratch, s->scratch_bytes);
    }
    if (s->status != TARN_OK) {
        tarn_frame_sender_forget(s);
        return 1;
    }
    s->tiles_sent++;
    return 0;
}

tarn_status tarn_frame_sender_send(tarn_frame_sender *s, const uint32_t *frame)
{
    const uint16_t width = s->panel->width, height = s->panel->height, size = (uint16_t)s->tile_size;
    s->status = TARN_OK;
    for (uint16_t y = 0; y < height; y = (uint16_t)(y + size)) {
        for (uint16_t x = 0; x < width; x = (uint16_t)(x + size)) {
            tarn_tile tile = {x, y, (uint16_t)(width - x < size ? width - x : size),
                              (uint16_t)(height - y < size ? height - y : size),
                              frame + (size_t)y * width + x, NULL, width, 0};
            if (tarn_frame_sender_tile(s, &tile) != 0) return s->status;
        }
    }
    if (s->mode == TARN_SEND_CHANGED) s->shown_valid = 1;
    return TARN_OK;
}

void tarn_frame_sender_forget(tarn_frame_sender *s)
{
    s->shown_valid = 0;
}

void tarn_frame_sender_free(tarn_frame_sender *s)
{
    free(s->scratch);
    free(s->shown);
    s->scratch = NULL;
    s->shown = NULL;
}
