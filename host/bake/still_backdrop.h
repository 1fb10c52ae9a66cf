/* still_backdrop.h: the still-water backdrop's image (backdrop.h, tarn_scene.h
 * "Still water"), which backdrop.c makes its scene over for --backdrop still. */
#ifndef TARN_HOST_STILL_BACKDROP_H
#define TARN_HOST_STILL_BACKDROP_H

#include <stdint.h>
#include "backdrop.h"

/* The still-water backdrop of `scene` for `config`'s frame and quality, keeping
 * the water under a landing refracted sample `landing_depth_q16` deep
 * (tarn_backdrop_request), and where the frame's water draws (`*water`, width *
 * height flags). 0, or -1 with `err` set; the caller frees what was made either
 * way. */
int tarn_still_image_make(const tarn_scene *scene, const tarn_frame_config *config, uint32_t landing_depth_q16,
                          tarn_backdrop_image *b, uint8_t **water, tarn_error *err);

#endif
