/* frame_internal.h: the last stage of a frame (core/frame/), internal to core/:
 * the frame's memory, found once, and the tile loop that runs every other stage.
 *
 *   layout.c  which buffers a frame of this scene and quality needs, their bytes
 *             (tarn_frame_memory_bytes) and where each lies in the caller's memory
 *   frame.c   tarn_render_frame: checks, the scene it draws (posed, its vertices
 *             found once), view, bins, then each tile: the opaque pass (drawn or
 *             read from a backdrop), the water pass (in place, from a copy, or over
 *             still water), the underwater view, and the sink; or in strips of the
 *             whole width (TARN_FRAME_STRIPS), each strip's opaque pass drawn once
 *             into a ring, ahead of its water; tarn_render_frame_part draws one
 *             part's share of the tiles or strips; tarn_strip_pipeline_* let two
 *             workers share one ring, each taking a strip's opaque pass or water
 *   status.c  tarn_status_text and tarn_version
 *
 * It takes the scene, the config and the caller's memory, and hands each finished
 * tile to the caller's sink. Its own work is per tile: clears, copies and marks. */
#ifndef TARN_FRAME_INTERNAL_H
#define TARN_FRAME_INTERNAL_H

#include "water/underwater_internal.h"

/* Rows of the strips an in-place water pass falls back to when a water pixel
 * lands on another (frame.c's draw_water_in_strips). */
#define TARN_WATER_STRIP_ROWS 2

/* The buffers of one frame: the opaque pass's colour and depth over the tile and
 * its apron, or over the ring of strips; with water or the underwater view, the
 * water pass's colour and depth over the tile and the underwater apron (over the
 * strip, with strips), or only over two rows of the piece when the water pass
 * draws in place; with the underwater view, the tile's final colour; the water
 * blocks' slots; the cluster bins this frame finds. */
typedef struct {
    int32_t tile;
    int32_t under_apron;  /* pixels the underwater displacement reaches */
    int32_t refraction_apron; /* pixels refraction reaches */
    int32_t apron;        /* the opaque pass's: refraction plus underwater */
    int32_t region_width; /* the opaque buffers: tile + 2 * apron square, or the
                             frame's width, ring_strips strips tall */
    int32_t water_region; /* tile + 2 * under_apron */
    int water;            /* a water pass runs */
    int underwater;
    int in_place;         /* the water pass draws over the opaque buffers */
    size_t depth_bytes;
    uint32_t blocks;      /* water block slots, 0 without: tarn_water_block, or over
                             still water tarn_still_block */
    size_t block_bytes;   /* one slot's */
    uint32_t bins;        /* cluster bins found in the frame's memory, 0 without */
    const tarn_cluster_bin *static_bins; /* the static view's instead, or NULL */
    const tarn_backdrop *backdrop; /* the opaque pass's pixels, or NULL: drawn */
    int still;            /* the backdrop holds the water's still terms (tarn_scene.h) */
    int32_t piece_width;  /* pixels across a tile or strip */
    int32_t ring_strips;  /* strips whose opaque pass the ring keeps; 0: the frame is
                             drawn in tiles (the fields stay few: the layout lives on
                             the 16 KB boards' stack) */
} tarn_frame_layout;

/* Where each buffer of a layout lies in the caller's memory. */
typedef struct {
    uint32_t *opaque_colour;
    void *opaque_depth;
    uint32_t *water_colour;       /* the water pass's own buffers */
    void *water_depth;
    uint32_t *final;              /* the underwater pass's tile */
    tarn_water_block *blocks;     /* water blocks' slots, or NULL */
    tarn_still_block *still_blocks; /* or over still water these, or NULL */
    tarn_cluster_bin *found_bins; /* bins this frame finds, or NULL */
} tarn_frame_buffers;

/* The layout of a frame of a config that tarn__config_check accepts. */
tarn_frame_layout tarn__frame_layout_of(const tarn_frame_config *config, const tarn_scene *scene);
/* The scene the frame draws, at the start of *memory, which moves past it: a moving
 * scene posed for the frame's time; with the vertex pass (tarn_vertex_pass), a copy
 * whose static view holds every vertex as the frame's camera sees it. Otherwise the
 * scene as it is. tarn_frame_memory_bytes counts its bytes. */
const tarn_scene *tarn__frame_scene(const tarn_scene *scene, const tarn_frame_config *config, void **memory);
/* The layout with the underwater view off: a frame in strips, which a strip
 * pipeline draws (a frame under water is drawn in tiles). */
tarn_frame_layout tarn__frame_strips_layout(const tarn_frame_config *config, const tarn_scene *scene);
/* Pixels of the water pass's own colour and depth buffers. */
size_t tarn__frame_water_pixels(const tarn_frame_layout *l);
/* The buffers carved from `memory` (4-byte aligned, at least
 * tarn_frame_memory_bytes long), the blocks' slots cleared. */
tarn_frame_buffers tarn__frame_carve(const tarn_frame_layout *layout, void *memory);

#endif
