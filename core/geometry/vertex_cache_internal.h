/* vertex_cache.h: a small cache of transformed and projected vertices for one
 * object's walk (private to core/).
 *
 * Most vertices are shared by several triangles (six, inside a grid), and
 * neighbouring clusters share their borders. Keyed by the vertex index, the cache
 * keeps each vertex's view position, clip outcode, the tile edges it lies beyond
 * and, once needed, its screen position and its shading, so a walk transforms, projects and lights a vertex
 * about once instead of once per triangle. Direct-mapped: a colliding vertex simply replaces the older one.
 * It lives on the stack of the walk that uses it. */
#ifndef TARN_VERTEX_CACHE_H
#define TARN_VERTEX_CACHE_H

#include "geometry/geometry_internal.h"

/* TARN_VERTEX_CACHE_SLOTS (tarn_config.h) must be a power of two from 4 to 256 */
typedef char tarn_vertex_cache_slots_check[(TARN_VERTEX_CACHE_SLOTS >= 4u && TARN_VERTEX_CACHE_SLOTS <= 256u &&
                                            (TARN_VERTEX_CACHE_SLOTS & (TARN_VERTEX_CACHE_SLOTS - 1u)) == 0u) ? 1 : -1];

#define TARN_CACHED_FILLED 1u    /* the slot holds vertex `index` */
#define TARN_CACHED_PROJECTED 2u /* screen_x, screen_y and inv_depth are set */
#define TARN_CACHED_SHADED 4u    /* lit and fresnel are set */
#define TARN_CACHED_BEYOND_TILE_SHIFT 4u /* state bits 4..7: the tile edges the vertex lies beyond */

/* tarn__cached_triangle's outcodes: tarn__clip_outcode's bits, and above them, from
 * bit TARN_CACHED_TILE_OUTCODE_SHIFT, the tile edges. */
#define TARN_CACHED_CLIP_PLANES TARN_CLIP_PLANE_BITS
#define TARN_CACHED_TILE_OUTCODE_SHIFT 6u

/* A tile's four edges (left, right, top, bottom) as slopes in view space, for a
 * test without projecting: a vertex in front of the near plane whose signed
 * offset (x, -x, -y, y in that order) is at most (d >> 10) * slope, or
 * ((d >> 10) + 1) * slope for a negative slope, projects at least a pixel beyond
 * the edge, so the bounds of a triangle of three such vertices miss the tile.
 * Each slope is at most 1024 * (the edge's offset from the frame centre, with
 * that pixel) / focal, within +-1023. */
typedef struct {
    int16_t slope_q10[4];
    uint8_t tested; /* bit k: edge k has a slope (0 for an edge outside the frame) */
} tarn_tile_edges;

typedef struct {
    uint16_t index;
    uint8_t state;     /* TARN_CACHED_* bits */
    uint8_t outcode;   /* tarn__clip_outcode */
    tarn_q16 x, y, d;  /* view space */
    int16_t screen_x, screen_y; /* inside the guard box, which is below 2^15 subpixels */
    uint32_t inv_depth;
    uint16_t lit[3];   /* tarn__vertex_shade's, Q8.8: always within 0..65280 */
    uint16_t fresnel;  /* Q1.15, 0..32768 */
} tarn_cached_vertex;

typedef struct {
    const tarn_view *view;
    const tarn_object_xform *xform;
    const tarn_mesh *mesh;
    const tarn_static_vertex *static_vertices; /* the object's, when they apply; else NULL */
    const tarn_vec3 *static_positions;         /* with them, their view positions, or NULL */
    const tarn_tile_edges *tile; /* NULL: no tile edges in the outcodes */
    tarn_cached_vertex slot[TARN_VERTEX_CACHE_SLOTS];
} tarn_vertex_cache;

/* A tile edge's slope (tarn_tile_edges) from its offset from the frame centre in
 * half pixels, with the pixel beyond it, negated for the right and bottom edges;
 * TARN_TILE_EDGE_UNTESTED when no slope in range bounds it. */
int32_t tarn__tile_edge_slope(const tarn_view *view, int32_t offset_half);

#define TARN_TILE_EDGE_UNTESTED INT32_MIN

/* An empty cache for one object's vertices, for a walk of the tile whose `tile`
 * edges are given, or of the whole frame (NULL). Where the object's static vertices
 * apply (tarn_view's static_vertices), a vertex is read from them, already lit and,
 * in their own frame, projected. */
void tarn__vertex_cache_init(tarn_vertex_cache *cache, const tarn_view *view,
                            const tarn_object_xform *xform, const tarn_object *object,
                            const tarn_vec3 *static_positions, const tarn_tile_edges *tile);

/* The static view's view positions of the scene's first object, where its static
 * vertices apply and it has them (tarn_static_view's positions); else NULL. A walk
 * over the objects passes each its own (tarn__vertex_cache_init) and steps on past
 * its mesh's vertices. */
static inline const tarn_vec3 *tarn__static_positions(const tarn_scene *scene, const tarn_view *view)
{
    return TARN_LINK_STATIC_VERTICES && view->static_vertices && scene->static_view != NULL
               ? scene->static_view->positions
               : NULL;
}

/* The three vertices of a triangle (`index` its three indices) into c[]; returns the
 * outcode bits all three have, and in *outside_any those any of them has. */
unsigned tarn__cached_triangle(tarn_vertex_cache *cache, const uint16_t index[3], tarn_cached_vertex c[3],
                              unsigned *outside_any);

/* The screen position and inverse depth of a vertex inside every clip plane, into
 * `screen` (its attributes untouched); computed once and kept in `vertex` and, while
 * it still holds the vertex, its slot. */
void tarn__cached_projection(tarn_vertex_cache *cache, tarn_cached_vertex *vertex,
                            tarn_screen_vertex *screen);

/* The vertex as a view vertex: its position and its shading (lit colour, fresnel,
 * texture coordinates), the shading computed once and kept as
 * tarn__cached_projection keeps the screen position. */
void tarn__cached_shading(tarn_vertex_cache *cache, tarn_cached_vertex *vertex, tarn_view_vertex *v);

/* The same shading straight into a screen vertex's attributes, as
 * tarn__project_attributes would set them from the view vertex. */
void tarn__cached_attributes(tarn_vertex_cache *cache, tarn_cached_vertex *vertex, tarn_screen_vertex *screen);

#endif
