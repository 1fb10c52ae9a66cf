/* motion_load.h: a scene file's motion into tarn_motion.h's structs.
 *
 * The format (docs/scene-format.md, "Motion"; every field checked, times and periods
 * whole milliseconds, angles in degrees):
 *   camera "path": {"orbit": {"centre": [x,y,z], "radius": r, "height": h,
 *                             "period": ms, "start": deg, "direction":
 *                             "counterclockwise"|"clockwise", "target": [x,y,z]}}
 *               or {"keys": [{"time": ms, "position": [..], "target": [..],
 *                             "fov": deg}, ...], "loop": ms}
 *   light "motion": {"spin": {"axis": [..], "period": ms},
 *                    "path": {"keys": [{"time": ms, "direction": [..]}], "loop": ms}}
 *   object "motion": {"bob": {"axis": [..], "amplitude": a, "period": ms, "phase": deg},
 *                     "spin": {"axis": [..], "period": ms},
 *                     "path": {"keys": [{"time": ms, "position": [..]}], "loop": ms}}
 * Each reader fills its struct and allocates the keys' arrays, which
 * tarn_key_curve_free releases. */
#ifndef TARN_HOST_MOTION_LOAD_H
#define TARN_HOST_MOTION_LOAD_H

#include <jansson.h>
#include "scene_fields.h"
#include "tarn/tarn_motion.h"

/* `camera` is the scene's "camera" object, `fov` its field of view (Q16.16): 0 with
 * *present 0 when it has no "path". */
int tarn_camera_path_load(tarn_loader *l, const json_t *camera, tarn_camera_path *out, int *present);
int tarn_light_motion_load(tarn_loader *l, const json_t *light, tarn_light_motion *out, int *present);
/* `field` is the object's path ("objects[3]"). */
int tarn_object_motion_load(tarn_loader *l, const json_t *object, const char *field,
                            tarn_object_motion *out, int *present);

void tarn_key_curve_free(tarn_key_curve *curve);

#endif
