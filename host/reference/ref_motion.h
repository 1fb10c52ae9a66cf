/* ref_motion.h: the float reference's pose of a moving scene (tarn_motion.h), in
 * doubles, rounded to the scene's Q16.16 at the end. */
#ifndef TARN_HOST_REF_MOTION_H
#define TARN_HOST_REF_MOTION_H

#include <stdint.h>
#include "tarn/tarn_motion.h"

/* The curve's channels at time_ms, in world units (or degrees). */
void tarn_ref_key_curve_at(const tarn_key_curve *curve, uint32_t time_ms, double *out);

/* tarn_scene_pose's result, found in doubles: `objects` holds object_count entries.
 * The scene has passed the core's check (tarn_scene_pose), which its motion must. */
void tarn_ref_scene_pose(const tarn_scene *scene, uint32_t time_ms, tarn_scene *posed, tarn_object *objects);

#endif
