/* compare.h: how far one RGB888 image is from another (the core's render from the
 * float reference's), as the numbers every accuracy figure of tarn is quoted in. */
#ifndef TARN_HOST_COMPARE_H
#define TARN_HOST_COMPARE_H

#include <stdint.h>
#include <stdio.h>

/* PSNR of identical images is infinite; it is reported as this value, and any
 * larger PSNR is capped to it, so more accurate never reads as a smaller number. */
#define TARN_COMPARE_PSNR_MAX 99.99

typedef struct {
    double psnr_db;           /* over all channels of RGB888, capped at TARN_COMPARE_PSNR_MAX */
    int max_channel_error;    /* largest |a - b| over every channel of every pixel, 0..255 */
    double share_over2;       /* fraction (0..1) of pixels with some channel off by more than 2 */
    double share_over8;       /* ... off by more than 8 */
    long coverage_mismatches; /* pixels covered in one image and not in the other */
    long pixels;              /* width * height */
} tarn_compare_metrics;

/* a, b: width*height*3 bytes (R G B). cov_a, cov_b: width*height bytes, non-zero where
 * a triangle drew; if either is NULL, coverage_mismatches is 0. */
void tarn_compare_images(const uint8_t *a, const uint8_t *b, const uint8_t *cov_a,
                         const uint8_t *cov_b, int w, int h, tarn_compare_metrics *m);

/* Writes a width*height*3 RGB heat-map of |a - b| into rgb_out: black where equal,
 * then with the pixel's largest channel error a ramp (log scale) dark blue (1),
 * blue (2), red (8), yellow (32), white (128 and up). Pixels where `marked` (width*
 * height bytes, or NULL) is non-zero are magenta: tarn compare marks those whose
 * surface differs. */
void tarn_compare_heatmap(const uint8_t *a, const uint8_t *b, const uint8_t *marked, int w, int h,
                          uint8_t *rgb_out);

#endif
