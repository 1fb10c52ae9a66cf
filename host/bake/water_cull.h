/* water_cull.h: the water triangles that draw no pixel of a frame, left out.
 *
 * Over a backdrop (backdrop.h) the frame is fixed, and the pixels where water draws
 * are known; a water triangle whose screen box holds none of them draws nothing
 * (the box taken in floating point from the triangle clipped to the near plane,
 * two pixels wider on every side than the rounding could move it). Left out, it
 * costs a frame nothing: no transform, clip or set-up in each tile it reaches, and
 * no depth test at each pixel it covers under the opaque scene. The image is the
 * same, since it drew nothing and water triangles never overlap in a way the
 * order of the rest depends on: every triangle kept keeps its place. */
#ifndef TARN_HOST_WATER_CULL_H
#define TARN_HOST_WATER_CULL_H

#include "error.h"
#include "tarn/tarn_render.h"

typedef struct {
    tarn_mesh *meshes;        /* per object of the scene: the culled copy, or unused */
    uint16_t **indices;       /* per object: its kept triangles' indices */
    tarn_cluster **clusters;  /* per object: its clusters over the kept triangles */
    uint32_t object_count;
    uint32_t triangles_before, triangles_after; /* over every water object */
} tarn_water_cull;

/* Points each water object of `scene` (its objects array is rewritten) at a copy of
 * its mesh without the triangles that cannot draw a pixel where `water`
 * (width * height flags, 1 where the frame's water draws) is 0. 0, or -1 with
 * `err` set out of memory. */
int tarn_water_cull_make(tarn_scene *scene, tarn_object *objects, const tarn_frame_config *config,
                         const uint8_t *water, tarn_water_cull *out, tarn_error *err);
void tarn_water_cull_free(tarn_water_cull *c);

#endif
