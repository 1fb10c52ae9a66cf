/* compare.c: image metrics and the difference heat-map (see compare.h). */
#include "compare.h"

#include <math.h>
#include <stdlib.h>

static int channel_error(uint8_t x, uint8_t y)
{
    return abs((int)x - (int)y);
}

/* Largest channel error of pixel p. */
static int pixel_error(const uint8_t *a, const uint8_t *b, size_t p)
{
    int worst = 0;
    for (int c = 0; c < 3; c++) {
        int e = channel_error(a[3 * p + c], b[3 * p + c]);
        if (e > worst) worst = e;
    }
    return worst;
}

static int coverage_differs(const uint8_t *cov_a, const uint8_t *cov_b, size_t p)
{
    return cov_a != NULL && cov_b != NULL && (cov_a[p] != 0) != (cov_b[p] != 0);
}

static double psnr_from_squared_error(double sum_sq, double samples)
{
    if (sum_sq == 0) return TARN_COMPARE_PSNR_MAX;
    double psnr = 10.0 * log10(255.0 * 255.0 * samples / sum_sq);
    return psnr < TARN_COMPARE_PSNR_MAX ? psnr : TARN_COMPARE_PSNR_MAX;
}

void tarn_compare_images(const uint8_t *a, const uint8_t *b, const uint8_t *cov_a,
                         const uint8_t *cov_b, int w, int h, tarn_compare_metrics *m)
{
    size_t pixels = (size_t)w * h;
    double sum_sq = 0;
    long over2 = 0, over8 = 0, coverage = 0;
    int worst = 0;
    for (size_t p = 0; p < pixels; p++) {
        for (int c = 0; c < 3; c++) {
            int e = channel_error(a[3 * p + c], b[3 * p + c]);
            sum_sq += (double)e * e;
        }
        int e = pixel_error(a, b, p);
        if (e > worst) worst = e;
        over2 += e > 2;
        over8 += e > 8;
        coverage += coverage_differs(cov_a, cov_b, p);
    }
    m->pixels = (long)pixels;
    m->psnr_db = psnr_from_squared_error(sum_sq, 3.0 * (double)pixels);
    m->max_channel_error = worst;
    m->share_over2 = pixels ? (double)over2 / (double)pixels : 0;
    m->share_over8 = pixels ? (double)over8 / (double)pixels : 0;
    m->coverage_mismatches = coverage;
}

typedef struct {
    double log2_error;
    uint8_t rgb[3];
} ramp_stop;

/* Stops at the errors the metrics single out: 2 (over2) is blue, 8 (over8) is red. */
static const ramp_stop heat_ramp[] = {
    { 0.0, { 0, 0, 96 } },      /* 1 */
    { 1.0, { 0, 0, 255 } },     /* 2 */
    { 3.0, { 255, 0, 0 } },     /* 8 */
    { 5.0, { 255, 255, 0 } },   /* 32 */
    { 7.0, { 255, 255, 255 } }, /* 128 */
};
#define HEAT_STOPS (sizeof heat_ramp / sizeof heat_ramp[0])

static void heat_colour(int error, uint8_t out[3])
{
    if (error == 0) {
        out[0] = out[1] = out[2] = 0;
        return;
    }
    double x = log2((double)error);
    size_t i = 0;
    while (i + 2 < HEAT_STOPS && x > heat_ramp[i + 1].log2_error) i++;
    const ramp_stop *lo = &heat_ramp[i], *hi = &heat_ramp[i + 1];
    double s = (x - lo->log2_error) / (hi->log2_error - lo->log2_error);
    if (s > 1) s = 1;
    for (int c = 0; c < 3; c++)
        out[c] = (uint8_t)lround(lo->rgb[c] + (hi->rgb[c] - lo->rgb[c]) * s);
}

void tarn_compare_heatmap(const uint8_t *a, const uint8_t *b, const uint8_t *marked, int w, int h,
                          uint8_t *rgb_out)
{
    static const uint8_t magenta[3] = { 255, 0, 255 };
    size_t pixels = (size_t)w * h;
    for (size_t p = 0; p < pixels; p++) {
        uint8_t *out = rgb_out + 3 * p;
        if (marked != NULL && marked[p] != 0) {
            for (int c = 0; c < 3; c++) out[c] = magenta[c];
        } else {
            heat_colour(pixel_error(a, b, p), out);
        }
    }
}
