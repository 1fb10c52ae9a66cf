/* still_planes.h: each water object's surface as a still-water backdrop's frame
 * sees it (tarn_still_plane, tarn_scene.h), found on the host in doubles.
 *
 * The object must be flat, its texture coordinates an affine map of its plane. Then
 * along the ray through a pixel's centre, near/d and (u, v) * near/d are affine
 * functions of the pixel: the plane keeps them as integers, which the core
 * evaluates the same way on every target. */
#ifndef TARN_HOST_STILL_PLANES_H
#define TARN_HOST_STILL_PLANES_H

#include "error.h"
#include "tarn/tarn_render.h"

/* The plane of each of `scene`'s water objects, in their order, into `planes`, for
 * `config`'s frame: 0, or -1 with `err` naming the object (by its index in the
 * scene's objects) that is not flat, whose texture coordinates are not an affine
 * map of its plane, or whose surface comes so close to the camera that its near/d
 * leaves 32 bits somewhere in the frame. */
int tarn_still_planes_make(const tarn_scene *scene, const tarn_frame_config *config, tarn_still_plane *planes,
                           tarn_error *err);

#endif
