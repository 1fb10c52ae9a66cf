/* gif_io.h: a frame sequence as one animated GIF (giflib), written all or nothing
 * like every output (atomic_file.h).
 *
 * The whole animation shares one palette of 255 colours, chosen by median cut over
 * every frame's pixels (giflib's GifQuantizeBuffer), so that a colour does not
 * flicker from frame to frame; the 256th index is transparent. The first frame is
 * stored whole; each later one stores only the rectangle of pixels whose index
 * changed, the unchanged ones inside it transparent, over the frame before (which
 * keeps LZW's runs long where water moves and the ground stands still). The
 * animation loops for ever. */
#ifndef TARN_HOST_GIF_IO_H
#define TARN_HOST_GIF_IO_H

#include <stddef.h>
#include <stdint.h>
#include "error.h"

/* GIF delays are whole hundredths of a second, and viewers slow anything shorter
 * than two to a tenth: frames at most 50 a second. */
#define TARN_GIF_FPS_MAX 50u

typedef struct {
    uint16_t width, height;
    unsigned frame_count;
    unsigned fps;       /* frame k shows from floor(100 k / fps) hundredths of a second */
    const uint8_t *rgb; /* frame_count frames of width * height RGB888, one after the other */
} tarn_gif_animation;

/* 0, or -1 with one line in `err` (the path and the reason). */
int tarn_gif_write(const char *path, const tarn_gif_animation *animation, tarn_error *err);

#endif
