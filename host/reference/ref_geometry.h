/* ref_geometry.h: the float reference's geometry, in doubles: vectors, the camera
 * as tarn_scene.h defines it, and an object's vertices in world space. The
 * reference renders with it (reference.c), and still water finds its planes with
 * it (still_planes.c), so both see the same camera. */
#ifndef TARN_HOST_REF_GEOMETRY_H
#define TARN_HOST_REF_GEOMETRY_H

#include "tarn/tarn_scene.h"

typedef struct {
    double x, y, z;
} tarn_dvec3;

tarn_dvec3 tarn_dvec_from_q16(tarn_vec3 v);
tarn_dvec3 tarn_dvec_sub(tarn_dvec3 a, tarn_dvec3 b);
double tarn_dvec_dot(tarn_dvec3 a, tarn_dvec3 b);
tarn_dvec3 tarn_dvec_cross(tarn_dvec3 a, tarn_dvec3 b);
tarn_dvec3 tarn_dvec_normalize(tarn_dvec3 v);
/* rot (Q16.16 rows) times p. */
tarn_dvec3 tarn_dvec_rotate(const tarn_q16 rot[3][3], tarn_dvec3 p);

/* The camera's position and unit axes, its near and far distances (world units),
 * and its focal length in pixels for a frame `height` pixels high: a point at view
 * (x, y, d) lands at (width/2 + x * focal / d, height/2 - y * focal / d). */
typedef struct {
    tarn_dvec3 position, right, up, forward;
    double near, far, focal;
} tarn_ref_camera;

tarn_ref_camera tarn_ref_camera_make(const tarn_camera *camera, int height);

/* Object-space point p in world space: position + scale * rotation p. */
tarn_dvec3 tarn_ref_world_position(const tarn_object *object, tarn_vec3 p);

/* The texture coordinates of a flat mesh (its tarn_uv_plane) where the ray through
 * the screen point (x, y) (pixels, of a frame width x height) meets its plane, into
 * uv (1.0 = one repeat): 1, or 0 when the ray runs along the plane. */
int tarn_ref_plane_uv(const tarn_ref_camera *cam, const tarn_object *object, double x, double y, int width,
                      int height, double uv[2]);

#endif
