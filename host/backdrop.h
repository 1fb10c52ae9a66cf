/* backdrop.h: a scene's backdrop (tarn_scene.h), made on the host.
 *
 * The scene's opaque objects are drawn once by the core, for one frame and
 * quality, and kept as a palette index per pixel and, where water may draw or
 * sample (its triangles' boxes grown by the frame's apron; every pixel under the
 * underwater view), the depth buffer's values. The scene then keeps only its water
 * objects, with a static view that holds the backdrop: a frame it applies to is the
 * same, byte for byte, as the whole scene drawn (tests/test_backdrop.c). `tarn bake
 * --backdrop on` writes it; `tarn render --backdrop on` draws through it. */
#ifndef TARN_HOST_BACKDROP_H
#define TARN_HOST_BACKDROP_H

#include "error.h"
#include "static_view.h"
#include "water_cull.h"
#include "tarn_render.h"

typedef struct {
    tarn_backdrop backdrop; /* points into the arrays below */
    uint32_t colours;       /* the distinct ones the opaque objects draw; the palette
                               pads them to 2^index_bits */
    uint32_t *palette;
    uint16_t *colour;
    size_t colour_words; /* uint16_t entries of colour */
    tarn_backdrop_row *rows;
    void *depth;
} tarn_backdrop_image;

/* The scene's water objects over the backdrop of its other objects, without the
 * triangles that draw no pixel of the frame (water_cull.h). */
typedef struct {
    tarn_backdrop_image image;
    tarn_water_cull cull;
    tarn_object *water_objects;
    tarn_static_scene water; /* water.scene is what a frame draws; its static view
                                holds the backdrop */
} tarn_backdrop_scene;

/* The backdrop of `scene` (without a static view of its own) for `config`'s frame
 * and quality, and its water objects with static vertices over it (static_view.h;
 * `keep_positions` as there). 0, or -1 with `err` set and `out` empty: out of
 * memory, a config the core refuses, or more than TARN_BACKDROP_COLOURS_MAX colours. */
int tarn_backdrop_scene_make(const tarn_scene *scene, const tarn_frame_config *config, int keep_positions,
                             tarn_backdrop_scene *out, tarn_error *err);
void tarn_backdrop_scene_free(tarn_backdrop_scene *s);

#endif
