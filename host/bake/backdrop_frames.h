/* backdrop_frames.h: what the makers of both backdrops share (backdrop.c and
 * still_backdrop.c; private to them), in backdrop_frames.c, which calls neither:
 * whole frames drawn by the core on the host, the scene split into its water and
 * its other objects, and the picture and depth spans kept from a frame. */
#ifndef TARN_HOST_BACKDROP_FRAMES_H
#define TARN_HOST_BACKDROP_FRAMES_H

#include "backdrop.h"

/* A whole frame as the core draws it. */
typedef struct {
    uint32_t *rgb;      /* width * height colours, with a still backdrop's marks */
    uint8_t *depth;     /* depth_bytes a pixel */
    size_t depth_bytes;
    int width;
} tarn_drawn_frame;

/* `scene`'s frame into `f`, whose buffers it allocates (tarn_drawn_free releases
 * them, whatever the outcome): 0, or -1 with `err` naming `what` it was for. */
int tarn_backdrop_draw(const tarn_scene *scene, const tarn_frame_config *config, tarn_drawn_frame *f,
                       const char *what, tarn_error *err);
/* The same of the scene's objects whose water-ness is `water` alone, without its
 * underwater view. */
int tarn_backdrop_draw_part(const tarn_scene *scene, int water, const tarn_frame_config *config,
                            tarn_drawn_frame *f, const char *what, tarn_error *err);
void tarn_drawn_free(tarn_drawn_frame *f);
/* Whether pixel k's depth differs between two frames of one quality. */
int tarn_drawn_depth_differs(const tarn_drawn_frame *a, const tarn_drawn_frame *b, size_t k);

int tarn_object_is_water(const tarn_object *o);
/* The scene with only the objects whose water-ness is `water`, into `objects`. */
tarn_scene tarn_scene_part(const tarn_scene *scene, int water, tarn_object *objects);

/* The backdrop's quality fields, for the opaque objects or with still water. */
void tarn_backdrop_set_quality(tarn_backdrop *b, const tarn_quality *q, int still_water);
/* The frame's colours as an ascending palette and packed indices; and the values
 * of a frame's depth (depth_bytes each) where `kept` is 1, in spans: 0, or -1
 * with `err` set. */
int tarn_backdrop_index_colours(const uint32_t *rgb, size_t pixels, tarn_backdrop_image *b, tarn_error *err);
int tarn_backdrop_keep_depth(const tarn_drawn_frame *f, const uint8_t *kept, uint32_t height, tarn_backdrop_image *b,
                             tarn_error *err);

#endif
