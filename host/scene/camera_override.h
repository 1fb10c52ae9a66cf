/* camera_override.h: the --camera option of render, compare and view, a camera in
 * place of the scene's own (and of its path):
 *   --camera X,Y,Z:TX,TY,TZ[:FOV]
 * the position and the target in world units, and the vertical field of view in
 * degrees (the scene's without it); near and far stay the scene's. Each number
 * becomes Q16.16 as the scene loader rounds it, so the text tarn_camera_override_text
 * writes reads back to the very same camera: tarn view prints its camera so. */
#ifndef TARN_HOST_CAMERA_OVERRIDE_H
#define TARN_HOST_CAMERA_OVERRIDE_H

#include <stddef.h>
#include "error.h"
#include "tarn/tarn_scene.h"

typedef struct {
    int given;               /* 0: the scene's camera stays */
    tarn_vec3 position;      /* Q16.16 world */
    tarn_vec3 target;        /* Q16.16 world, distinct from position */
    tarn_q16 fov_y_degrees;  /* Q16.16 degrees 1..179; 0: the scene's */
} tarn_camera_override;

/* The option's value: 0, or -1 with "--camera: expected ..." in `err`. */
int tarn_camera_override_parse(const char *text, tarn_camera_override *out, tarn_error *err);

/* The scene with this camera, standing still (no path). */
void tarn_camera_override_apply(const tarn_camera_override *camera, tarn_scene *scene);

/* Room for the text below: 7 numbers of at most 24 characters and their separators. */
#define TARN_CAMERA_TEXT_MAX 192

/* "X,Y,Z:TX,TY,TZ:FOV", each number the exact decimal of its Q16.16 value. */
void tarn_camera_override_text(const tarn_camera *camera, char *out, size_t size);

#endif
