/* view_camera.h: the camera tarn view draws with: the scene's own (on its path,
 * where it has one), turned about its target by the mouse. */
#ifndef TARN_HOST_VIEW_CAMERA_H
#define TARN_HOST_VIEW_CAMERA_H

#include <stdint.h>
#include "error.h"
#include "tarn/tarn_scene.h"

/* The scene's camera at `time_ms`, its position turned about the target by
 * `yaw_degrees` (about the world's up) and `pitch_degrees` (up and over, stopping
 * 5 degrees short of straight above or below), its distance times `zoom`; near,
 * far and the field of view as the scene has them then. 0, or -1 with `err` set
 * when the scene cannot be posed or the camera leaves the world's Q16.16 range. */
int tarn_view_camera(const tarn_scene *scene, uint32_t time_ms, double yaw_degrees, double pitch_degrees,
                     double zoom, tarn_camera *out, tarn_error *err);

#endif
