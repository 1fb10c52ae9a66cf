/* image_checksum.h: core/include/tarn/tarn_checksum.h's frame checksum of a whole RGB888 image,
 * the number a board's sweep reports for the same frame. */
#ifndef TARN_HOST_IMAGE_CHECKSUM_H
#define TARN_HOST_IMAGE_CHECKSUM_H

#include <stdint.h>

/* rgb: width*height*3 bytes, rows top to bottom, R G B. */
uint32_t tarn_image_checksum(const uint8_t *rgb, uint32_t width, uint32_t height);

#endif
