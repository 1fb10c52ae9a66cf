/* tile_internal.h: the third stage of a frame (core/tile/), internal to core/: a
 * tile's buffers, and which triangles reach them.
 *
 *   walk.c          every object's clusters, in scene order: those whose bin (or
 *                   bounding sphere) misses the tile are skipped whole, the
 *                   triangles of the rest go through core/geometry/ and, if they
 *                   reach the tile, on to a tarn_triangle_sink (the rasterizer)
 *   cluster_bins.c  where on screen each cluster draws, found once a frame
 *   backdrop_read.c a tile's opaque pixels read from a baked backdrop instead
 *
 * It takes the frame's view (core/geometry/) and a pixel rectangle, and hands on
 * screen triangles. Per tile it costs a test per cluster and, for the clusters
 * that meet the tile, the vertex cache's work; nothing per pixel but the backdrop's
 * copy. */
#ifndef TARN_TILE_INTERNAL_H
#define TARN_TILE_INTERNAL_H

#include "geometry/geometry_internal.h"

typedef struct {
    int32_t x0, y0, x1, y1; /* pixel rectangle [x0, x1) x [y0, y1) */
} tarn_pixel_rect;

/* What a pass draws into: the pixels it may draw, and buffers whose index 0 holds
 * frame pixel (origin_x, origin_y). */
typedef struct {
    tarn_pixel_rect rect;
    int32_t origin_x, origin_y;
    uint32_t *colour;   /* 0x00RRGGBB, `stride` pixels per row */
    void *depth;        /* uint16_t or uint32_t per pixel by depth_bits, near/d */
    int32_t stride;
    const tarn_quality *quality;
    uint8_t log2_span;  /* log2 of the quality's perspective_span, taken once a frame */
} tarn_tile_target;

/* ---- the walk (walk.c) ------------------------------------------------------- */

typedef enum {
    TARN_WALK_OPAQUE, /* objects whose material has no water block */
    TARN_WALK_WATER   /* water objects only */
} tarn_walk_pass;

/* Walks the triangles of the pass's objects in scene order; triangles whose screen
 * bounds miss `only_rect` (when not NULL) are skipped as early as possible, whole
 * clusters first: by their bins when `bins` (this frame's, tarn__bin_clusters) is
 * not NULL, else by their bounding spheres. */
void tarn__walk_triangles(const tarn_scene *scene, const tarn_view *view, tarn_walk_pass pass,
                         const tarn_cluster_bin *bins, const tarn_pixel_rect *only_rect,
                         tarn_triangle_sink sink, void *ctx);

/* ---- triangles from static vertices ---------------------------------------------
 *
 * For a frame whose view has static screen positions (tarn_view's static_screen: a
 * baked still view, or the frame's own vertex pass), the walk and the cluster bins
 * read most triangles straight from the static vertices, past the vertex cache,
 * which then transforms only the vertices of the triangles the frame clips. Inline:
 * they run at every visit of a triangle, where a call's overhead shows. */

/* The screen positions of a triangle whose three static vertices were projected
 * for this frame: a projected vertex lies inside every clip plane, so neither
 * outcodes nor the cache are needed. 0 when one was not projected (`screen` then
 * partly written): the cached walk then clips the triangle. */
static inline int tarn__static_screen_positions(const tarn_static_vertex *baked, const uint16_t index[3],
                                                tarn_screen_vertex screen[3])
{
    for (int k = 0; k < 3; k++) {
        const tarn_static_vertex *v = &baked[index[k]];
        if (v->inv_depth == 0u) return 0;
        screen[k].x = v->screen_x;
        screen[k].y = v->screen_y;
        screen[k].inv_depth = v->inv_depth;
    }
    return 1;
}

/* Whether the three static vertices lie outside one clip plane, by the planes each
 * one not projected keeps (tarn_static_vertex): such a triangle draws nothing. Most
 * of those a frame meets lie beyond the guard band at its sides, where the cache
 * would transform or look up their vertices again only to learn that. Only a build with
 * the vertex pass reads them (TARN_LINK_VERTEX_PASS: its frames clip the most, and
 * a 16 KB board's flash has no bytes to spare for it); others find 0. */
static inline int tarn__static_outside_a_plane(const tarn_static_vertex *baked, const uint16_t index[3])
{
    if (!TARN_LINK_VERTEX_PASS) return 0;
    unsigned all = TARN_CLIP_PLANE_BITS;
    for (int k = 0; k < 3; k++) {
        const tarn_static_vertex *v = &baked[index[k]];
        all &= v->inv_depth == 0u ? (uint16_t)v->screen_x : 0u; /* a projected one is inside every plane */
    }
    return all != 0u;
}

/* ---- cluster bins (cluster_bins.c) ---------------------------------------------
 *
 * Without bins, every tile tests every cluster's bounding sphere against its slice
 * of the view, and walks (transforms, clips, projects) every triangle of each
 * cluster whose sphere touches it: a sphere is loose, so a cluster is walked by
 * several tiles. With bins (the quality's `cluster_bins`), one pass a frame
 * projects every cluster and keeps the screen box its drawable triangles cover, in
 * cells of 4 pixels; a tile then walks only the clusters whose box meets it. That
 * costs 4 bytes of frame memory a cluster, or none where the scene's static view
 * holds the boxes for the frame (tarn bake). A cluster cut by the near plane has no
 * meaningful screen box: its bin is the whole screen and the sphere decides. */

#define TARN_BIN_CELL_SHIFT 2u /* a cell is 4 x 4 pixels */

/* tarn_cluster_bin (tarn_scene.h): cells [x0, x1] x [y0, y1], inclusive. */

/* Bins a mesh takes: one per cluster, or one for an unclustered mesh. */
uint32_t tarn__cluster_bins_of(const tarn_mesh *mesh);
/* Bins a scene takes, every object in scene order. */
uint32_t tarn__cluster_bin_count(const tarn_scene *scene);
/* Fills bins[tarn__cluster_bin_count(scene)] for this frame's view. */
void tarn__bin_clusters(const tarn_scene *scene, const tarn_view *view, tarn_cluster_bin *bins);

/* 1 when the bin's box meets the pixel rectangle. */
int tarn__cluster_bin_touches(const tarn_cluster_bin *bin, const tarn_pixel_rect *rect);
/* 1 when the bin is the whole screen (the sphere test must decide). */
int tarn__cluster_bin_is_whole(const tarn_cluster_bin *bin);

/* ---- a baked backdrop (backdrop_read.c) ------------------------------------------ */

/* The target's rect from the backdrop of a frame `frame_width` pixels wide, as the
 * opaque pass would draw it; the colours alone with depth_bytes 0. */
void tarn__backdrop_fill(const tarn_backdrop *backdrop, uint16_t frame_width, tarn_tile_target *target,
                        size_t depth_bytes);
/* What a still-water backdrop keeps at frame pixel (i, j) (tarn_scene.h: the depth
 * of water beneath, or the place in the foam band, Q0.16); 65536 where it keeps
 * nothing. */
uint32_t tarn__backdrop_kept(const tarn_backdrop *backdrop, int32_t i, int32_t j);
/* The opaque depth (near/d, Q1.30) an opaque backdrop keeps at frame pixel (i, j),
 * as tarn__backdrop_fill puts it in a tile's depth buffer: in front of every water
 * pixel where it keeps none. */
uint32_t tarn__backdrop_depth_q30(const tarn_backdrop *backdrop, int32_t i, int32_t j);
/* The backdrop's colour at frame pixel (i, j) of a frame `frame_width` pixels wide,
 * marks and all: a read anywhere in the picture, as a refracted sample over still
 * water makes. */
uint32_t tarn__backdrop_colour_at(const tarn_backdrop *backdrop, uint16_t frame_width, int32_t i, int32_t j);

#endif
