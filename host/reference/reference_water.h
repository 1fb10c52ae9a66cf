/* reference_water.h: the float reference's water, private to host/reference/.
 *
 * reference_water.c shades one water pixel by the rules of core/include/tarn/tarn_water.h and
 * applies the underwater view, in doubles with libm; reference.c rasterizes, keeps
 * the buffers and calls it. Both sample textures and round through ref_texel.h,
 * so by one definition; reference_water.c calls nothing of reference.c. */
#ifndef TARN_HOST_REFERENCE_WATER_H
#define TARN_HOST_REFERENCE_WATER_H

#include <stdint.h>
#include "tarn/tarn_water.h"

/* Everything a water pixel reads besides its own surface: the frame, the opaque
 * pass's buffers (never the water pass's: water does not see water) and the
 * frame's time and light. */
typedef struct {
    int width, height;
    const uint8_t *rgb;   /* the opaque image, R G B per pixel, rows top to bottom */
    const double *depth;  /* the opaque linear depth per pixel, the far distance where
                             nothing opaque was drawn */
    uint32_t time_ms;
    const tarn_light *light;
    double backward[3];   /* the camera's backward axis, world, unit length */
} tarn_ref_water_view;

/* A water surface at a pixel, interpolated perspective-correctly. */
typedef struct {
    double depth;   /* linear depth ds, world units */
    double lit[3];  /* material colour times shade, 0..255 */
    double uv[2];   /* mesh texture coordinates */
    double fresnel; /* (1 - saturate(n.v))^2 */
} tarn_ref_water_surface;

/* Whether the water block is complete enough to shade: the textures its features
 * sample exist and are valid, and the distances it divides by are positive. */
int tarn_ref_water_is_valid(const tarn_water *water);
int tarn_ref_underwater_is_valid(const tarn_underwater *underwater);

/* Steps 1-11 of tarn_water.h for pixel (i, j) of `object` (whose material has a
 * water block): the final colour, rounded, into out[0..2]. */
void tarn_ref_shade_water(const tarn_ref_water_view *view, const tarn_object *object, int i,
                          int j, const tarn_ref_water_surface *surface, uint8_t out[3]);

/* The underwater view over the whole frame: reads `rgb` (the image after the water
 * pass) and `depth` (the linear depth of the nearest surface, water included; far
 * where nothing was drawn), writes `out` (not `rgb`: every pixel reads others). */
void tarn_ref_apply_underwater(const tarn_underwater *underwater, int width, int height,
                               uint32_t time_ms, const uint8_t *rgb, const double *depth,
                               uint8_t *out);

#endif
