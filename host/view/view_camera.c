/* view_camera.c: the view's camera, turned by the mouse (view_camera.h). */
#include "view_camera.h"

#include <math.h>
#include <stdlib.h>

#include "mesh_gen.h"
#include "tarn/tarn_motion.h"

#define PI 3.14159265358979323846
#define PITCH_LIMIT (85.0 * PI / 180.0)
/* The world's range (scene_load.h): every coordinate below 32768 in magnitude. */
#define WORLD_LIMIT 32767.0

/* The scene's camera as its path puts it at `time_ms`. */
static int posed_camera(const tarn_scene *scene, uint32_t time_ms, tarn_camera *out, tarn_error *err)
{
    if (scene->camera_path == NULL) {
        *out = scene->camera;
        return 0;
    }
    tarn_object *objects = malloc((scene->object_count ? scene->object_count : 1u) * sizeof *objects);
    tarn_scene posed;
    const int failed = objects == NULL || tarn_scene_pose(scene, time_ms, &posed, objects) != TARN_OK;
    if (!failed) *out = posed.camera;
    free(objects);
    return failed ? tarn_fail(err, "the scene's camera cannot be posed at %lu ms", (unsigned long)time_ms) : 0;
}

static double clamp(double v, double low, double high)
{
    return v < low ? low : v > high ? high : v;
}

int tarn_view_camera(const tarn_scene *scene, uint32_t time_ms, double yaw_degrees, double pitch_degrees,
                     double zoom, tarn_camera *out, tarn_error *err)
{
    if (posed_camera(scene, time_ms, out, err) != 0) return -1;
    const double target[3] = {out->target.x / 65536.0, out->target.y / 65536.0, out->target.z / 65536.0};
    const double from[3] = {out->position.x / 65536.0 - target[0], out->position.y / 65536.0 - target[1],
                            out->position.z / 65536.0 - target[2]};
    const double distance = sqrt(from[0] * from[0] + from[1] * from[1] + from[2] * from[2]);
    const double yaw = atan2(from[0], from[2]) + yaw_degrees * PI / 180.0;
    const double pitch = clamp(asin(from[1] / distance) + pitch_degrees * PI / 180.0, -PITCH_LIMIT, PITCH_LIMIT);
    const double to[3] = {cos(pitch) * sin(yaw), sin(pitch), cos(pitch) * cos(yaw)};
    double position[3];
    for (int k = 0; k < 3; k++) {
        position[k] = target[k] + distance * zoom * to[k];
        if (!(fabs(position[k]) < WORLD_LIMIT))
            return tarn_fail(err, "the camera would leave the world (|coordinate| < 32768); zoom in");
    }
    const tarn_vec3 turned = {tarn_q16_from_double(position[0]), tarn_q16_from_double(position[1]),
                              tarn_q16_from_double(position[2])};
    if (turned.x == out->target.x && turned.y == out->target.y && turned.z == out->target.z)
        return tarn_fail(err, "the camera would stand on its target; zoom out");
    out->position = turned;
    return 0;
}
