/* checksum.c: the tile-order-free frame checksum of tarn_checksum.h. */
#include "tarn/tarn_checksum.h"

#define CHECKSUM_X_FACTOR 0x9E3779B1u
#define CHECKSUM_Y_FACTOR 0x85EBCA77u

/* MurmurHash3's 32-bit finalizer: every input bit reaches every output bit, and it
 * is invertible (xor-shifts and odd multipliers), so distinct inputs stay distinct. */
static uint32_t fmix32(uint32_t h)
{
    h ^= h >> 16;
    h *= 0x85EBCA6Bu;
    h ^= h >> 13;
    h *= 0xC2B2AE35u;
    h ^= h >> 16;
    return h;
}

uint32_t tarn_checksum_pixel(uint32_t x, uint32_t y, uint32_t rgb)
{
    return fmix32((x * CHECKSUM_X_FACTOR) ^ (y * CHECKSUM_Y_FACTOR) ^ (rgb & 0xFFFFFFu));
}

uint32_t tarn_checksum_tile(uint32_t sum, const tarn_tile *tile)
{
    for (uint32_t row = 0; row < tile->height; row++) {
        const uint32_t *rgb = tile->rgb + (uint32_t)tile->stride * row;
        const uint32_t y_term = ((uint32_t)tile->y + row) * CHECKSUM_Y_FACTOR;
        for (uint32_t i = 0; i < tile->width; i++)
            sum += fmix32((((uint32_t)tile->x + i) * CHECKSUM_X_FACTOR) ^ y_term ^ (rgb[i] & 0xFFFFFFu));
    }
    return sum;
}
