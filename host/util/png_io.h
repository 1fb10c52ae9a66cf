/* png_io.h: reading PNG images (textures, heightfields) and writing frames.
 *
 * Readers accept any PNG colour type and bit depth: libpng's transforms expand
 * palettes and low bit depths, strip alpha and 16-bit precision, and convert
 * between gray and RGB as asked. Each reader checks the image size from the header
 * before decoding anything, so an oversized image costs no memory.
 *
 * Errors name the file ("pond/sand.png: not a PNG file") and leave `out` empty. A
 * file read must be a regular one of at most TARN_PNG_FILE_BYTES_MAX (input_file.h). */
#ifndef TARN_HOST_PNG_IO_H
#define TARN_HOST_PNG_IO_H

#include <stdint.h>
#include "error.h"

/* Heightfields become one vertex per pixel and two triangles per square of four,
 * in one tarn mesh (TARN_MESH_TRIANGLES_MAX): a side may reach 256 as long as the
 * grid's 2 * (w - 1) * (h - 1) triangles fit, so a square image up to 182x182. */
#define TARN_HEIGHTFIELD_SIZE_MAX 256u

/* The largest PNG file read, checked before its first byte. The biggest image a
 * reader accepts (a TARN_TEXTURE_SIZE_MAX square texture) is 8 MB even stored raw at
 * 16 bits per channel with alpha, and scenes/ holds PNGs of 10 KB; the rest is room
 * for ancillary chunks. */
#define TARN_PNG_FILE_BYTES_MAX (64u * 1024u * 1024u)

typedef struct {
    uint16_t width, height;
    uint8_t channels; /* 3: RGB8, 1: gray 8-bit */
    uint8_t *pixels;  /* width*height*channels bytes, rows top to bottom; owned */
} tarn_image;

/* A texture: RGB8, each side a power of two up to TARN_TEXTURE_SIZE_MAX. */
int tarn_png_read_texture(const char *path, tarn_image *out, tarn_error *err);

/* A heightfield: gray 8-bit (colour images are converted to luminance), each side
 * 2..TARN_HEIGHTFIELD_SIZE_MAX. */
int tarn_png_read_heightfield(const char *path, tarn_image *out, tarn_error *err);

/* Writes `rgb` (width*height*3 bytes, rows top to bottom) as an RGB8 PNG. The
 * image goes to a temporary file beside `path` that is renamed over `path` only
 * once complete, so a failure never leaves a partial or truncated file behind. */
int tarn_png_write_rgb(const char *path, const uint8_t *rgb, uint32_t width, uint32_t height,
                       tarn_error *err);

void tarn_image_free(tarn_image *image);

#endif
