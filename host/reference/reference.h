/* reference.h: the float reference renderer, the truth the integer core is measured
 * against.
 *
 * It follows the pixel rules written at the top of core/include/tarn/tarn_render.h, in double
 * precision with libm, and shares no arithmetic with core/ (only the struct
 * definitions, and in snapped mode the core's own screen triangles).
 *
 * Two geometries (tarn_reference_geometry), the truth and the core's own:
 *  - continuous: the whole pipeline in doubles (transform, camera, near/far
 *    clipping, projection) and screen positions left where they fall, on no grid:
 *    edges are where the scene puts them. The same for every quality: the yardstick
 *    of the whole error a viewer sees.
 *  - core triangles: rasterizes exactly the triangles the core produces
 *    (tarn_visit_screen_triangles: its positions on its subpixel grid and its vertex
 *    attributes), so only per-pixel arithmetic differs and the coverage matches the
 *    core's pixel for pixel: the yardstick of the shading error.
 *
 * A frame is drawn as core/include/tarn/tarn_water.h describes: opaque materials first, then
 * water materials over them (depth-tested against both, reading only the opaque
 * colour and depth), then the underwater view when the camera is below its level.
 * The reference has no tiles: refraction reads the whole frame. */
#ifndef TARN_HOST_REFERENCE_H
#define TARN_HOST_REFERENCE_H

#include <stdint.h>
#include "tarn/tarn_render.h"
#include "tarn/tarn_scene.h"

typedef enum {
    TARN_REF_CONTINUOUS = 0,
    TARN_REF_CORE_TRIANGLES = 1
} tarn_reference_geometry;

typedef struct {
    tarn_reference_geometry geometry;
    int subpixel_bits; /* TARN_SUBPIXEL_BITS_MIN..MAX: the core triangles' grid; the
                          continuous geometry ignores it */
    uint32_t time_ms;  /* the frame's clock, as tarn_frame_config.time_ms (water panning) */
    const tarn_quality *quality; /* CORE_TRIANGLES: the core's quality (its subpixel_bits
                                    is replaced by the one above); NULL: the default */
} tarn_reference_options;

/* Renders `scene` into `rgb` (width*height*3 bytes, rows top to bottom, R G B) and,
 * unless NULL, `covered` (width*height bytes: 1 where a triangle drew, else 0).
 * Returns TARN_OK (0), TARN_ERR_CONFIG for a size or option out of range, or
 * TARN_ERR_SCENE for a malformed scene; the outputs are then left unspecified. */
int tarn_reference_render(const tarn_scene *scene, int width, int height,
                          const tarn_reference_options *opt, uint8_t *rgb,
                          uint8_t *covered);

/* The same, with `surface` (width*height entries, required) naming what each
 * pixel shows: 0 where nothing drew, else 1 + the index in scene->objects of the
 * nearest object drawn there (water included). Two renders whose surfaces differ
 * at a pixel disagree about what is there, not about its shade. */
int tarn_reference_render_surfaces(const tarn_scene *scene, int width, int height,
                                   const tarn_reference_options *opt, uint8_t *rgb,
                                   uint32_t *surface);

#endif
