/* tarn_checksum.h: a checksum of a rendered frame that does not depend on the tile
 * size or on the order the tiles arrive in, so that a board can sum its tiles as
 * they leave the renderer and the host can compute the same number from a whole
 * image.
 *
 * The checksum is the sum, modulo 2^32, over every pixel of the frame of
 *   tarn_checksum_pixel(x, y, rgb) = fmix32((x * 0x9E3779B1) ^ (y * 0x85EBCA77) ^ rgb)
 * where rgb is the pixel as 0x00RRGGBB (any top byte is ignored) and fmix32 is
 * MurmurHash3's finalizer (a bijection of 32-bit words, so changing any bit of one
 * pixel's colour always changes the sum). A sum of per-pixel terms is the same in
 * any order and however the frame is cut into tiles. Start a frame from 0.
 * 32-bit multiplies only. */
#ifndef TARN_CHECKSUM_H
#define TARN_CHECKSUM_H

#include <stdint.h>
#include "tarn_render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The term of one pixel at frame position (x, y). */
uint32_t tarn_checksum_pixel(uint32_t x, uint32_t y, uint32_t rgb);

/* `sum` plus the terms of every pixel of the tile, at their frame positions. */
uint32_t tarn_checksum_tile(uint32_t sum, const tarn_tile *tile);

#ifdef __cplusplus
}
#endif

#endif
