/* triangles.c: walks a scene's triangles through transform, clipping, projection
 * and culling-free emission; the rasterizer culls, since culling needs the
 * snapped screen winding. */
#include "pipeline.h"

static int bounds_miss_rect(const tarn_screen_vertex s[3], unsigned subpixel_bits,
                            const tarn_pixel_rect *rect)
{
    int32_t min_x = s[0].x, max_x = s[0].x, min_y = s[0].y, max_y = s[0].y;
    for (int i = 1; i < 3; i++) {
        if (s[i].x < min_x) min_x = s[i].x;
        if (s[i].x > max_x) max_x = s[i].x;
        if (s[i].y < min_y) min_y = s[i].y;
        if (s[i].y > max_y) max_y = s[i].y;
    }
    /* Conservative in whole pixels: a centre at i + 0.5 lies in pixel column i. */
    const int32_t one = (int32_t)1 << subpixel_bits;
    return max_x < rect->x0 * one || min_x >= rect->x1 * one ||
           max_y < rect->y0 * one || min_y >= rect->y1 * one;
}

static void emit_clipped(const tarn_view *view, unsigned planes, const tarn_view_vertex v[3],
                         const tarn_object *object, tarn_triangle_sink sink, void *ctx)
{
    tarn_view_vertex polygon[TARN_CLIP_POLYGON_MAX] = {v[0], v[1], v[2]};
    int count = tarn_clip_polygon(view, planes, polygon, 3);
    tarn_screen_vertex screen[TARN_CLIP_POLYGON_MAX];
    for (int i = 0; i < count; i++) tarn_project(view, &polygon[i], &screen[i]);
    for (int i = 1; i + 1 < count; i++) {
        const tarn_screen_vertex fan[3] = {screen[0], screen[i], screen[i + 1]};
        sink(ctx, fan, object);
    }
}

static void walk_object(const tarn_view *view, const tarn_object *object,
                        const tarn_pixel_rect *only_rect, tarn_triangle_sink sink, void *ctx)
{
    const tarn_mesh *mesh = object->mesh;
    tarn_object_xform xform;
    tarn_object_xform_setup(view, object, &xform);
    for (uint32_t t = 0; t < mesh->triangle_count; t++) {
        const uint16_t *index = &mesh->indices[3 * t];
        tarn_view_vertex v[3] = {{0}};
        unsigned outside_all = ~0u, outside_any = 0;
        for (int k = 0; k < 3; k++) {
            tarn_vertex_position(&xform, &mesh->positions[index[k]], &v[k]);
            unsigned code = tarn_clip_outcode(view, &v[k]);
            outside_all &= code;
            outside_any |= code;
        }
        if (outside_all) continue; /* wholly outside one plane */
        if (outside_any) {
            for (int k = 0; k < 3; k++) tarn_vertex_shade(view, &xform, mesh, index[k], &v[k]);
            emit_clipped(view, outside_any, v, object, sink, ctx);
            continue;
        }
        tarn_screen_vertex screen[3];
        for (int k = 0; k < 3; k++) tarn_project(view, &v[k], &screen[k]);
        if (only_rect && bounds_miss_rect(screen, view->subpixel_bits, only_rect)) continue;
        for (int k = 0; k < 3; k++) {
            tarn_vertex_shade(view, &xform, mesh, index[k], &v[k]);
            tarn_project_attributes(&v[k], &screen[k]);
        }
        sink(ctx, screen, object);
    }
}

void tarn_walk_triangles(const tarn_scene *scene, const tarn_view *view,
                         const tarn_pixel_rect *only_rect, tarn_triangle_sink sink, void *ctx)
{
    for (uint32_t i = 0; i < scene->object_count; i++)
        walk_object(view, &scene->objects[i], only_rect, sink, ctx);
}
