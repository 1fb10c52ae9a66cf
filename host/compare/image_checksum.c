#include "image_checksum.h"

#include "tarn/tarn_checksum.h"

uint32_t tarn_image_checksum(const uint8_t *rgb, uint32_t width, uint32_t height)
{
    uint32_t sum = 0;
    for (uint32_t y = 0; y < height; y++)
        for (uint32_t x = 0; x < width; x++) {
            const uint8_t *p = rgb + 3u * ((size_t)y * width + x);
            sum += tarn_checksum_pixel(x, y, ((uint32_t)p[0] << 16) | ((uint32_t)p[1] << 8) | p[2]);
        }
    return sum;
}
