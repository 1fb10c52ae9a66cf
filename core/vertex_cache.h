/* vertex_cache.h: a small cache of transformed and projected vertices for one
 * object's walk (private to core/).
 *
 * Most vertices are shared by several triangles (six, inside a grid), and
 * neighbouring clusters share their borders. Keyed by the vertex index, the cache
 * keeps each vertex's view position, clip outcode and, once needed, its screen
 * position and its shading, so a walk transforms, projects and lights a vertex
 * about once instead of once per triangle. Direct-mapped: a colliding vertex simply replaces the older one.
 * It lives on the stack of the walk that uses it. */
#ifndef TARN_VERTEX_CACHE_H
#define TARN_VERTEX_CACHE_H

#include "pipeline.h"

#define TARN_VERTEX_CACHE_SLOTS 16u /* a power of two, 36 bytes each */

#define TARN_CACHED_FILLED 1u    /* the slot holds vertex `index` */
#define TARN_CACHED_PROJECTED 2u /* screen_x, screen_y and inv_depth are set */
#define TARN_CACHED_SHADED 4u    /* lit and fresnel are set */

typedef struct {
    uint16_t index;
    uint8_t state;     /* TARN_CACHED_* bits */
    uint8_t outcode;   /* tarn_clip_outcode */
    tarn_q16 x, y, d;  /* view space */
    int32_t screen_x, screen_y;
    uint32_t inv_depth;
    uint16_t lit[3];   /* tarn_vertex_shade's, Q8.8: always within 0..65280 */
    uint16_t fresnel;  /* Q1.15, 0..32768 */
} tarn_cached_vertex;

typedef struct {
    const tarn_view *view;
    const tarn_object_xform *xform;
    const tarn_mesh *mesh;
    tarn_cached_vertex slot[TARN_VERTEX_CACHE_SLOTS];
} tarn_vertex_cache;

/* An empty cache for one object's vertices. */
void tarn_vertex_cache_init(tarn_vertex_cache *cache, const tarn_view *view,
                            const tarn_object_xform *xform, const tarn_mesh *mesh);

/* The three vertices of a triangle (`index` its three indices) into c[]; returns the
 * clip planes all three are outside of, and those any is outside of in *outside_any. */
unsigned tarn_cached_triangle(tarn_vertex_cache *cache, const uint16_t index[3], tarn_cached_vertex c[3],
                              unsigned *outside_any);

/* The screen position and inverse depth of a vertex inside every clip plane, into
 * `screen` (its attributes untouched); computed once and kept in `vertex` and, while
 * it still holds the vertex, its slot. */
void tarn_cached_projection(tarn_vertex_cache *cache, tarn_cached_vertex *vertex,
                            tarn_screen_vertex *screen);

/* The vertex as a view vertex: its position and its shading (lit colour, fresnel,
 * texture coordinates), the shading computed once and kept as
 * tarn_cached_projection keeps the screen position. */
void tarn_cached_shading(tarn_vertex_cache *cache, tarn_cached_vertex *vertex, tarn_view_vertex *v);

#endif
