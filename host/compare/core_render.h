/* core_render.h: the integer core rendering a whole frame into host memory. */
#ifndef TARN_HOST_CORE_RENDER_H
#define TARN_HOST_CORE_RENDER_H

#include <stdint.h>
#include "error.h"
#include "tarn/tarn_render.h"

/* Renders into `rgb` (width*height*3 bytes, R G B) and, unless NULL, `covered`
 * (width*height bytes, 1 where a triangle drew). 0, or -1 with `err` set. */
int tarn_core_render(const tarn_scene *scene, const tarn_frame_config *config, uint8_t *rgb,
                     uint8_t *covered, tarn_error *err);

#endif
