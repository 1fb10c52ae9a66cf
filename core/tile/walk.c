/* triangles.c: walks a scene's triangles through transform, clipping, projection
 * and culling-free emission; the rasterizer culls, since culling needs the
 * snapped screen winding. For a tile, whole clusters whose bin or bounding sphere
 * misses the tile are skipped before any of their vertices is touched, and
 * triangles beyond an edge of the tile before they are projected. */
#include "tile/tile_internal.h"
#include "geometry/vertex_cache_internal.h"

/* The four planes through the eye bounding a pixel rectangle, as
 * side * (x*focal - offset*d) >= 0 with x the view x (or -y) and offset the
 * rectangle edge's distance from the frame centre; norm = |(focal, offset)|. */
typedef struct {
    int32_t offset_q12[4]; /* pixels from the frame centre, Q20.12: left, right, top, bottom */
    int64_t norm_q12[4];   /* sqrt(focal^2 + offset^2), Q.12 */
    int use_x[4];         /* 1: the plane bounds x; 0: it bounds -y (screen y runs down) */
    int side[4];          /* +1: inside where x*focal >= offset*d; -1: where <= */
    tarn_tile_edges edges; /* the same edges for single vertices (vertex_cache.h) */
    int active;           /* 0: no rectangle, every cluster is walked */
} tile_frustum;

static tile_frustum make_tile_frustum(const tarn_view *view, const tarn_pixel_rect *rect)
{
    tile_frustum f;
    f.active = rect != NULL;
    if (!f.active) return f;
    const int32_t edges[4] = {rect->x0, rect->x1, rect->y0, rect->y1};
    f.edges.tested = 0;
    for (int k = 0; k < 4; k++) {
        const int horizontal = k < 2;
        const int32_t centre = horizontal ? view->width : view->height; /* in half pixels: the extent in pixels */
        f.offset_q12[k] = edges[k] * 4096 - centre * 2048;
        f.use_x[k] = horizontal;
        f.side[k] = (k % 2 == 0) ? 1 : -1;
        /* a pixel beyond the first pixel centre of the left and top edges, half a
         * pixel beyond the last of the right and bottom ones; an edge outside the
         * frame is not tested, as the guard band may clamp a vertex short of it */
        const int inside_frame = f.side[k] > 0 ? edges[k] >= 0 : edges[k] <= centre;
        const int32_t offset_half = f.side[k] > 0 ? 2 * edges[k] - centre - 2 : centre - 2 * edges[k];
        const int32_t slope = inside_frame ? tarn__tile_edge_slope(view, offset_half) : TARN_TILE_EDGE_UNTESTED;
        f.edges.slope_q10[k] = (int16_t)(slope != TARN_TILE_EDGE_UNTESTED ? slope : 0);
        if (slope != TARN_TILE_EDGE_UNTESTED) f.edges.tested |= (uint8_t)(1u << k);
        uint64_t sum = (uint64_t)((int64_t)view->focal_q12 * view->focal_q12) +
                       (uint64_t)((int64_t)f.offset_q12[k] * f.offset_q12[k]);
        f.norm_q12[k] = (int64_t)tarn_isqrt_u64(sum) + 1; /* rounded up: conservative */
    }
    return f;
}

/* 1 when the sphere (view space centre, radius) cannot touch the tile's slice of
 * the view between near and far. */
static int sphere_misses_tile(const tarn_view *view, const tile_frustum *f,
                              const tarn_view_vertex *centre, int64_t radius_q16)
{
    if ((int64_t)centre->d + radius_q16 < view->near) return 1;
    if ((int64_t)centre->d - radius_q16 > view->far) return 1;
    if (!f->active) return 0;
    for (int k = 0; k < 4; k++) {
        const int64_t along = f->use_x[k] ? centre->x : -(int64_t)centre->y;
        const int64_t signed_q28 = f->side[k] * (along * view->focal_q12 - (int64_t)f->offset_q12[k] * centre->d);
        if (signed_q28 < -radius_q16 * f->norm_q12[k]) return 1;
    }
    return 0;
}

/* The subpixel positions of the centres of a rectangle's first and last pixels,
 * taken once a run: a triangle whose bounds end before the first or begin after
 * the last cannot cover a pixel centre of the rectangle (tarn__bounds_pixels' pixel
 * box, without its divisions). */
static tarn_subpixel_bounds rect_centres(const tarn_pixel_rect *rect, unsigned subpixel_bits)
{
    const tarn_subpixel_bounds b = {tarn__pixel_centre(rect->x0, subpixel_bits), tarn__pixel_centre(rect->y0, subpixel_bits),
                               tarn__pixel_centre(rect->x1 - 1, subpixel_bits), tarn__pixel_centre(rect->y1 - 1, subpixel_bits)};
    return b;
}

/* 1 when the triangle's bounds miss the centres; across first, as most do. */
static int bounds_miss(const tarn_screen_vertex s[3], const tarn_subpixel_bounds *centres)
{
    if (tarn_max3_i32(s[0].x, s[1].x, s[2].x) < centres->x0 || tarn_min3_i32(s[0].x, s[1].x, s[2].x) > centres->x1)
        return 1;
    return tarn_max3_i32(s[0].y, s[1].y, s[2].y) < centres->y0 || tarn_min3_i32(s[0].y, s[1].y, s[2].y) > centres->y1;
}

/* Their shading, read once the triangle is known to reach the tile. */
static void static_screen_attributes(const tarn_static_vertex *baked, const tarn_mesh *mesh,
                                     const uint16_t index[3], tarn_screen_vertex screen[3])
{
    for (int k = 0; k < 3; k++) {
        const tarn_static_vertex *v = &baked[index[k]];
        for (int c = 0; c < 3; c++) screen[k].lit[c] = v->lit[c];
        screen[k].fresnel = v->fresnel;
        screen[k].uv = tarn__vertex_uv(mesh, index[k]);
        screen[k].uv_low[0] = screen[k].uv_low[1] = 0u;
    }
}

/* A triangle through the vertex cache: clipped where it crosses a clip plane,
 * dropped beyond one plane or beyond an edge of the tile. `screen` is room for its
 * screen vertices, the caller's, whose stack holds one such array for both walks. */
static void walk_cached_triangle(const tarn_object *object, const uint16_t index[3],
                                 const tarn_subpixel_bounds *centres, tarn_vertex_cache *cache,
                                 tarn_screen_vertex screen[3], tarn_triangle_sink sink, void *ctx)
{
    const tarn_view *view = cache->view;
    tarn_cached_vertex c[3];
    unsigned outside_any;
    const unsigned outside_all = tarn__cached_triangle(cache, index, c, &outside_any);
    /* wholly outside one clip plane, or beyond one edge of the tile: a vertex lies
     * beyond a tile edge only in front of the near plane, where the edge's plane
     * through the eye bounds what clipping keeps of the triangle too */
    if (outside_all) return;
    if (outside_any & TARN_CACHED_CLIP_PLANES) {
        tarn_view_vertex v[3];
        for (int k = 0; k < 3; k++) tarn__cached_shading(cache, &c[k], &v[k]);
        tarn__clip_and_emit(view, outside_any & TARN_CACHED_CLIP_PLANES, v, object, sink, ctx);
        return;
    }
    for (int k = 0; k < 3; k++) tarn__cached_projection(cache, &c[k], &screen[k]);
    if (centres && bounds_miss(screen, centres)) return;
    for (int k = 0; k < 3; k++) tarn__cached_attributes(cache, &c[k], &screen[k]);
    sink(ctx, screen, object);
}

static void walk_run(const tarn_object *object, uint32_t first, uint32_t end,
                     const tarn_pixel_rect *only_rect, tarn_vertex_cache *cache,
                     tarn_triangle_sink sink, void *ctx)
{
    const tarn_view *view = cache->view;
    const tarn_mesh *mesh = object->mesh;
    const tarn_static_vertex *projected =
        TARN_LINK_STATIC_VERTICES && view->static_screen ? cache->static_vertices : NULL;
    const tarn_subpixel_bounds tile_centres = only_rect ? rect_centres(only_rect, view->subpixel_bits) : tarn__bounds_empty();
    const tarn_subpixel_bounds *centres = only_rect ? &tile_centres : NULL;
    tarn_screen_vertex screen[3];
    for (uint32_t t = first; t < end; t++) {
        const uint16_t *index = &mesh->indices[3 * t];
        if (projected == NULL || !tarn__static_screen_positions(projected, index, screen)) {
            if (projected == NULL || !tarn__static_outside_a_plane(projected, index))
                walk_cached_triangle(object, index, centres, cache, screen, sink, ctx);
        } else if (!centres || !bounds_miss(screen, centres)) {
            static_screen_attributes(projected, mesh, index, screen);
            sink(ctx, screen, object);
        }
    }
}

/* Whether a cluster may draw into the rectangle: its bin when the frame has them,
 * and its bounding sphere where the bin could not tell (a cluster cut by the near
 * plane) or there are no bins. */
static int cluster_may_touch(const tarn_view *view, const tarn_object_xform *xform,
                             const tarn_object *object, const tarn_cluster *cluster,
                             const tile_frustum *frustum, const tarn_cluster_bin *bin,
                             const tarn_pixel_rect *only_rect)
{
    if (bin != NULL && only_rect != NULL) {
        if (!tarn__cluster_bin_touches(bin, only_rect)) return 0;
        if (!tarn__cluster_bin_is_whole(bin)) return 1;
    }
    tarn_view_vertex centre;
    tarn__vertex_position(xform, &cluster->centre, &centre);
    /* at most Q16.16's range, so that radius * plane norm stays within 64 bits */
    int64_t radius = tarn_sat_i64_to_i32(tarn_round_shift_i64((int64_t)cluster->radius * object->scale, 16) + 1);
    return !sphere_misses_tile(view, frustum, &centre, radius);
}

static int any_bin_touches(const tarn_cluster_bin *bins, uint32_t count, const tarn_pixel_rect *rect)
{
    for (uint32_t i = 0; i < count; i++)
        if (tarn__cluster_bin_touches(&bins[i], rect)) return 1;
    return 0;
}

static void walk_object(const tarn_view *view, const tarn_object *object, const tarn_vec3 *static_positions,
                        const tile_frustum *frustum, const tarn_cluster_bin *bins,
                        const tarn_pixel_rect *only_rect, tarn_triangle_sink sink, void *ctx)
{
    const tarn_mesh *mesh = object->mesh;
    if (bins != NULL && only_rect != NULL && !any_bin_touches(bins, tarn__cluster_bins_of(mesh), only_rect))
        return; /* before the object's setup, which costs as much as a few vertices */
    tarn_object_xform xform;
    tarn__object_xform_setup(view, object, &xform);
    tarn_vertex_cache cache;
    tarn__vertex_cache_init(&cache, view, &xform, object, static_positions, frustum->active ? &frustum->edges : NULL);
    if (mesh->clusters == NULL) { /* its one bin, if any, was tested above */
        walk_run(object, 0, mesh->triangle_count, only_rect, &cache, sink, ctx);
        return;
    }
    for (uint32_t c = 0; c < mesh->cluster_count; c++) {
        const tarn_cluster *cluster = &mesh->clusters[c];
        if (!cluster_may_touch(view, &xform, object, cluster, frustum, bins ? &bins[c] : NULL, only_rect))
            continue;
        walk_run(object, cluster->first_triangle, (uint32_t)cluster->first_triangle + cluster->triangle_count,
                 only_rect, &cache, sink, ctx);
    }
}

void tarn__walk_triangles(const tarn_scene *scene, const tarn_view *view, tarn_walk_pass pass,
                         const tarn_cluster_bin *bins, const tarn_pixel_rect *only_rect,
                         tarn_triangle_sink sink, void *ctx)
{
    const tile_frustum frustum = make_tile_frustum(view, only_rect);
    const tarn_vec3 *positions = tarn__static_positions(scene, view);
    for (uint32_t i = 0; i < scene->object_count; i++) {
        const tarn_object *object = &scene->objects[i];
        if ((object->material->water != NULL) == (pass == TARN_WALK_WATER))
            walk_object(view, object, positions, &frustum, bins, only_rect, sink, ctx);
        if (bins != NULL) bins += tarn__cluster_bins_of(object->mesh);
        if (positions != NULL) positions += object->mesh->vertex_count;
    }
}
