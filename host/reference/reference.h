/* reference.h: the float reference renderer, the truth the integer core is measured
 * against.
 *
 * It follows the pixel rules written at the top of core/include/tarn/tarn_render.h, in double
 * precision with libm, and shares no arithmetic with core/ (only the struct
 * definitions, and in snapped mode the core's own screen triangles).
 *
 * Two modes:
 *  - default: the whole pipeline in doubles (transform, camera, near/far clipping,
 *    projection), then screen positions rounded to the 1/2^subpixel_bits grid and
 *    rasterized. Measures everything the core approximates.
 *  - snapped: rasterizes exactly the triangles the core produces
 *    (tarn_visit_screen_triangles), so only rasterization and shading differ; the
 *    coverage must then match the core's pixel for pixel.
 *
 * A frame is drawn as core/include/tarn/tarn_water.h describes: opaque materials first, then
 * water materials over them (depth-tested against both, reading only the opaque
 * colour and depth), then the underwater view when the camera is below its level.
 * The reference has no tiles: refraction reads the whole frame. */
#ifndef TARN_HOST_REFERENCE_H
#define TARN_HOST_REFERENCE_H

#include <stdint.h>
#include "tarn/tarn_scene.h"

typedef struct {
    int snapped;       /* 1: rasterize the core's snapped triangles */
    int subpixel_bits; /* TARN_SUBPIXEL_BITS_MIN..MAX, as in the core's quality */
    uint32_t time_ms;  /* the frame's clock, as tarn_frame_config.time_ms (water panning) */
} tarn_reference_options;

/* Renders `scene` into `rgb` (width*height*3 bytes, rows top to bottom, R G B) and,
 * unless NULL, `covered` (width*height bytes: 1 where a triangle drew, else 0).
 * Returns TARN_OK (0), TARN_ERR_CONFIG for a size or option out of range, or
 * TARN_ERR_SCENE for a malformed scene; the outputs are then left unspecified. */
int tarn_reference_render(const tarn_scene *scene, int width, int height,
                          const tarn_reference_options *opt, uint8_t *rgb,
                          uint8_t *covered);

#endif
