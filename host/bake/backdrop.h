/* backdrop.h: a scene's backdrop (tarn_scene.h), made on the host.
 *
 * The scene's opaque objects are drawn once by the core, for one frame and
 * quality, and kept as a palette index per pixel and, where water may draw or
 * sample (its triangles' boxes grown by the frame's apron; every pixel under the
 * underwater view), the depth buffer's values. The scene then keeps only its water
 * objects, with a static view that holds the backdrop: a frame it applies to is the
 * same, byte for byte, as the whole scene drawn (tests/test_backdrop.c). `tarn bake
 * --backdrop on` writes it; `tarn render --backdrop on` draws through it.
 *
 * A still-water backdrop (`--backdrop still`, still_backdrop.c) holds the water's
 * still terms drawn too, each water pixel marked with its object and where foam
 * can show, the place in the foam band there, and each water object's plane
 * (still_planes.h); a frame then finds only the water's moving terms
 * (TARN_WATER_MOVING). */
#ifndef TARN_HOST_BACKDROP_H
#define TARN_HOST_BACKDROP_H

#include "error.h"
#include "static_view.h"
#include "still_planes.h"
#include "water_cull.h"
#include "tarn/tarn_render.h"

typedef struct {
    tarn_backdrop backdrop; /* points into the arrays below */
    uint32_t *palette;
    uint16_t *colour;
    size_t colour_words; /* uint16_t entries of colour */
    tarn_still_plane *planes; /* still water: each water object's */
    uint16_t *row_spans;
    tarn_backdrop_span *spans;
    void *depth;
} tarn_backdrop_image;

typedef enum {
    TARN_BACKDROP_NONE,   /* the whole scene drawn each frame */
    TARN_BACKDROP_OPAQUE, /* the opaque objects drawn once: --backdrop on */
    TARN_BACKDROP_STILL   /* and the water's still terms: --backdrop still */
} tarn_backdrop_kind;

/* The deepest water a still backdrop keeps under a pixel where a refracted sample
 * may land (--landing-depth): Q16.16 world units. */
#define TARN_LANDING_DEPTH_MIN_Q16 (1u << 16)
#define TARN_LANDING_DEPTH_MAX_Q16 (4u << 16)

/* What is drawn once: the kind, and for still water how deep it keeps the water
 * under a pixel where a refracted sample may land within the foam band of the
 * water it moved from (tarn_scene.h's tarn_backdrop depth: under one unit it
 * keeps it wherever the frame refracts; deeper only there, at 2 bytes a pixel). */
typedef struct {
    tarn_backdrop_kind kind;
    uint32_t landing_depth_q16; /* TARN_LANDING_DEPTH_MIN_Q16..MAX_Q16 */
} tarn_backdrop_request;

/* A request of `kind` with the deepest landing depth. */
tarn_backdrop_request tarn_backdrop_of(tarn_backdrop_kind kind);

/* The scene's water objects over the backdrop of its other objects, without the
 * triangles that draw no pixel of the frame (water_cull.h). */
typedef struct {
    tarn_backdrop_image image;
    tarn_water_cull cull;
    tarn_object *water_objects;
    tarn_static_scene water; /* water.scene is what a frame draws; its static view
                                holds the backdrop */
} tarn_backdrop_scene;

/* The backdrop `request` asks for (OPAQUE or STILL) of `scene` (without a static view of its
 * own) for `config`'s frame and quality, and its water objects with static vertices
 * over it (static_view.h; `keep_positions` as there). 0, or -1 with `err` set and
 * `out` empty: out of memory, a config the core refuses, more than
 * TARN_BACKDROP_COLOURS_MAX colours, or still water where it would not apply (an
 * underwater view, refraction with an apron, more water objects than
 * TARN_BACKDROP_STILL_OBJECTS_MAX). */
int tarn_backdrop_scene_make(const tarn_scene *scene, const tarn_frame_config *config, tarn_backdrop_request request,
                             int keep_positions, tarn_backdrop_scene *out, tarn_error *err);
void tarn_backdrop_scene_free(tarn_backdrop_scene *s);

#endif
