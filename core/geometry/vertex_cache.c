/* vertex_cache.c: see vertex_cache.h. */
#include "geometry/vertex_cache_internal.h"

int32_t tarn__tile_edge_slope(const tarn_view *view, int32_t offset_half)
{
    /* focal in half pixels, rounded down: 1024 * offset / focal is bounded from
     * below by dividing by one more for a positive offset, and by this (at least
     * 1) with the quotient rounded away from 0 for a negative one */
    const uint32_t focal_half = (uint32_t)view->focal_q12 >> 11;
    const uint32_t magnitude = (uint32_t)(offset_half >= 0 ? offset_half : -offset_half) << 10; /* below 2^27 */
    if (offset_half >= 0) {
        const uint32_t slope = magnitude / (focal_half + 1u);
        return (int32_t)(slope > 1023u ? 1023u : slope); /* smaller is still a bound */
    }
    const uint32_t divisor = focal_half > 0u ? focal_half : 1u;
    const uint32_t slope = (magnitude + divisor - 1u) / divisor;
    return slope > 1023u ? TARN_TILE_EDGE_UNTESTED : -(int32_t)slope; /* no bound that small */
}

/* The bound on a vertex's signed offset beyond a tile edge (tarn_tile_edges): at
 * most 2^21 * 1023 in magnitude, so its negation is safe too. */
static inline int32_t edge_bound(int32_t depth_q6, int32_t slope)
{
    return (slope >= 0 ? depth_q6 : depth_q6 + 1) * slope;
}

/* The tile edges (bits 0..3) the vertex lies beyond; none for a vertex not in
 * front of the near plane, or without a tile. Edges without a slope are not
 * tested at all (their bits would be masked off). */
static unsigned beyond_tile_edges(const tarn_tile_edges *tile, const tarn_view *view, const tarn_view_vertex *v)
{
    if (tile == NULL || v->d < view->near) return 0;
    const int32_t depth_q6 = v->d >> 10; /* d >= near > 0: below 2^21 */
    const unsigned tested = tile->tested;
    unsigned beyond = 0;
    /* x <= bound for the left edge, -x <= bound for the right; y likewise, bottom and top */
    if ((tested & 1u) && v->x <= edge_bound(depth_q6, tile->slope_q10[0])) beyond |= 1u;
    if ((tested & 2u) && v->x >= -edge_bound(depth_q6, tile->slope_q10[1])) beyond |= 2u;
    if ((tested & 4u) && v->y >= -edge_bound(depth_q6, tile->slope_q10[2])) beyond |= 4u;
    if ((tested & 8u) && v->y <= edge_bound(depth_q6, tile->slope_q10[3])) beyond |= 8u;
    return beyond;
}

void tarn__vertex_cache_init(tarn_vertex_cache *cache, const tarn_view *view,
                            const tarn_object_xform *xform, const tarn_object *object,
                            const tarn_vec3 *static_positions, const tarn_tile_edges *tile)
{
    cache->view = view;
    cache->xform = xform;
    cache->mesh = object->mesh;
    cache->static_vertices = TARN_LINK_STATIC_VERTICES && view->static_vertices ? object->static_vertices : NULL;
    cache->static_positions = cache->static_vertices != NULL ? static_positions : NULL;
    cache->tile = tile;
    for (uint32_t i = 0; i < TARN_VERTEX_CACHE_SLOTS; i++) cache->slot[i].state = 0;
}

static tarn_cached_vertex *cache_slot(tarn_vertex_cache *cache, uint16_t index)
{
    /* Fibonacci hashing spreads a grid's rows, whose indices differ by the row length */
    return &cache->slot[((uint32_t)index * 40503u >> 11) & (TARN_VERTEX_CACHE_SLOTS - 1u)];
}

/* A vertex's screen position and inverse depth, kept. */
static inline void keep_projection(tarn_cached_vertex *to, int16_t screen_x, int16_t screen_y, uint32_t inv_depth)
{
    to->screen_x = screen_x;
    to->screen_y = screen_y;
    to->inv_depth = inv_depth;
    to->state |= TARN_CACHED_PROJECTED;
}

/* A vertex's shading, kept. */
static inline void keep_shading(tarn_cached_vertex *to, const uint16_t lit[3], uint16_t fresnel)
{
    for (int c = 0; c < 3; c++) to->lit[c] = lit[c];
    to->fresnel = fresnel;
    to->state |= TARN_CACHED_SHADED;
}

/* A static vertex's shading, and its projection where it was projected for this
 * frame, into the slot that holds its position and outcode. */
static void take_static_vertex(const tarn_view *view, const tarn_static_vertex *vertex, tarn_cached_vertex *slot)
{
    keep_shading(slot, vertex->lit, vertex->fresnel);
    if (view->static_screen && vertex->inv_depth != 0u && slot->outcode == 0u)
        keep_projection(slot, vertex->screen_x, vertex->screen_y, vertex->inv_depth);
}

/* The vertex's view position and outcode, from the cache or computed into it, copied
 * into *out (one copy: the triangle keeps its vertices even if they evict each other). */
static void cached_position(tarn_vertex_cache *cache, uint16_t index, tarn_cached_vertex *out)
{
    tarn_cached_vertex *slot = cache_slot(cache, index);
    if ((slot->state & TARN_CACHED_FILLED) && slot->index == index) {
        *out = *slot;
        return;
    }
    const tarn_static_vertex *baked =
        TARN_LINK_STATIC_VERTICES && cache->static_vertices != NULL ? &cache->static_vertices[index] : NULL;
    tarn_view_vertex v;
    if (TARN_LINK_COMPUTED_VERTICES && cache->static_positions == NULL) { /* NULL too without static vertices */
        tarn__vertex_position(cache->xform, &cache->mesh->positions[index], &v);
    } else { /* the scene check saw to it that every object has them */
        const tarn_vec3 *p = &cache->static_positions[index];
        v.x = p->x;
        v.y = p->y;
        v.d = p->z;
    }
    slot->index = index;
    slot->state = (uint8_t)(TARN_CACHED_FILLED | beyond_tile_edges(cache->tile, cache->view, &v)
                                                   << TARN_CACHED_BEYOND_TILE_SHIFT);
    slot->outcode = (uint8_t)tarn__clip_outcode(cache->view, &v);
    slot->x = v.x;
    slot->y = v.y;
    slot->d = v.d;
    if (baked != NULL) take_static_vertex(cache->view, baked, slot);
    *out = *slot;
}

unsigned tarn__cached_triangle(tarn_vertex_cache *cache, const uint16_t index[3], tarn_cached_vertex c[3],
                              unsigned *outside_any)
{
    unsigned all = ~0u, any = 0;
    for (int k = 0; k < 3; k++) {
        cached_position(cache, index[k], &c[k]);
        const unsigned code = c[k].outcode | (unsigned)(c[k].state >> TARN_CACHED_BEYOND_TILE_SHIFT)
                                                 << TARN_CACHED_TILE_OUTCODE_SHIFT;
        all &= code;
        any |= code;
    }
    *outside_any = any;
    return all;
}

/* A cached vertex's view position into *v, and nothing else: the callers read the
 * position alone or write every other field (zeroing the rest cost a memset). */
static void set_view_position(tarn_view_vertex *v, const tarn_cached_vertex *vertex)
{
    v->x = vertex->x;
    v->y = vertex->y;
    v->d = vertex->d;
    v->x_low = v->y_low = v->d_low = 0u;
}

/* The slot that still holds the vertex, or NULL once another took it over. */
static tarn_cached_vertex *holding_slot(tarn_vertex_cache *cache, const tarn_cached_vertex *vertex)
{
    tarn_cached_vertex *slot = cache_slot(cache, vertex->index);
    return (slot->state & TARN_CACHED_FILLED) && slot->index == vertex->index ? slot : NULL;
}

void tarn__cached_projection(tarn_vertex_cache *cache, tarn_cached_vertex *vertex,
                            tarn_screen_vertex *screen)
{
    if (!(vertex->state & TARN_CACHED_PROJECTED)) {
        tarn_view_vertex v;
        set_view_position(&v, vertex);
        tarn__project_position(cache->view, &v, screen);
        keep_projection(vertex, (int16_t)screen->x, (int16_t)screen->y, screen->inv_depth);
        tarn_cached_vertex *slot = holding_slot(cache, vertex);
        if (slot != NULL) keep_projection(slot, vertex->screen_x, vertex->screen_y, vertex->inv_depth);
    }
    screen->x = vertex->screen_x;
    screen->y = vertex->screen_y;
    screen->inv_depth = vertex->inv_depth;
}

void tarn__cached_shading(tarn_vertex_cache *cache, tarn_cached_vertex *vertex, tarn_view_vertex *v)
{
    const tarn_mesh *mesh = cache->mesh;
    set_view_position(v, vertex);
    if (TARN_LINK_COMPUTED_VERTICES && !(vertex->state & TARN_CACHED_SHADED)) {
        tarn__vertex_shade(cache->view, cache->xform, mesh, vertex->index, v);
        const uint16_t lit[3] = {(uint16_t)v->lit[0], (uint16_t)v->lit[1], (uint16_t)v->lit[2]};
        keep_shading(vertex, lit, (uint16_t)v->fresnel);
        tarn_cached_vertex *slot = holding_slot(cache, vertex);
        if (slot != NULL) keep_shading(slot, vertex->lit, vertex->fresnel);
        return;
    }
    for (int c = 0; c < 3; c++) v->lit[c] = vertex->lit[c];
    v->fresnel = vertex->fresnel;
    v->uv = tarn__vertex_uv(mesh, vertex->index);
    v->uv_low[0] = v->uv_low[1] = 0u;
}

void tarn__cached_attributes(tarn_vertex_cache *cache, tarn_cached_vertex *vertex, tarn_screen_vertex *screen)
{
    if (!(vertex->state & TARN_CACHED_SHADED)) {
        tarn_view_vertex v;
        tarn__cached_shading(cache, vertex, &v);
    }
    /* in range already (vertex_cache.h), which tarn__project_attributes would clamp to */
    for (int c = 0; c < 3; c++) screen->lit[c] = vertex->lit[c];
    screen->fresnel = vertex->fresnel;
    screen->uv = tarn__vertex_uv(cache->mesh, vertex->index);
    screen->uv_low[0] = screen->uv_low[1] = 0u;
}
