/* cluster_bins.c: see cluster_bins.h. The box of a cluster is exact for its
 * unclipped triangles (the walk projects the same vertices to the same positions)
 * and one pixel wider where a triangle is cut by the far plane or the guard band:
 * the cut polygon lies inside the triangle, and its new vertices round at most
 * that far. */
#include "tile/tile_internal.h"
#include "geometry/vertex_cache_internal.h"

#define NEAR_PLANE_BIT 1u /* tarn__clip_outcode's bit 0 */

static const tarn_cluster_bin bin_whole = {0, 0, 255, 255};
static const tarn_cluster_bin bin_empty = {255, 255, 0, 0};

uint32_t tarn__cluster_bins_of(const tarn_mesh *mesh)
{
    return mesh->clusters != NULL ? mesh->cluster_count : 1u;
}

uint32_t tarn__cluster_bin_count(const tarn_scene *scene)
{
    uint32_t count = 0;
    for (uint32_t i = 0; i < scene->object_count; i++) count += tarn__cluster_bins_of(scene->objects[i].mesh);
    return count;
}

int tarn__cluster_bin_touches(const tarn_cluster_bin *bin, const tarn_pixel_rect *rect)
{
    if (bin->x0 > bin->x1) return 0;
    return ((int32_t)bin->x0 << TARN_BIN_CELL_SHIFT) < rect->x1 &&
           ((int32_t)(bin->x1 + 1) << TARN_BIN_CELL_SHIFT) > rect->x0 &&
           ((int32_t)bin->y0 << TARN_BIN_CELL_SHIFT) < rect->y1 &&
           ((int32_t)(bin->y1 + 1) << TARN_BIN_CELL_SHIFT) > rect->y0;
}

int tarn__cluster_bin_is_whole(const tarn_cluster_bin *bin)
{
    return bin->x0 == 0 && bin->y0 == 0 && bin->x1 == 255 && bin->y1 == 255;
}

/* Pixels whose centres the bounds may cover, widened by `margin` pixels, in frame
 * cells. */
static tarn_cluster_bin to_cells(const tarn_subpixel_bounds *bounds, int32_t margin, const tarn_view *view)
{
    if (bounds->x0 > bounds->x1) return bin_empty;
    const tarn_pixel_box box = tarn__bounds_pixels(bounds, view->subpixel_bits);
    const int32_t x0 = tarn_clamp_i32(box.x0 - margin, 0, view->width - 1);
    const int32_t y0 = tarn_clamp_i32(box.y0 - margin, 0, view->height - 1);
    const int32_t x1 = tarn_clamp_i32(box.x1 + margin, 0, view->width - 1);
    const int32_t y1 = tarn_clamp_i32(box.y1 + margin, 0, view->height - 1);
    if (x0 > x1 || y0 > y1) return bin_empty;
    const tarn_cluster_bin bin = {(uint8_t)(x0 >> TARN_BIN_CELL_SHIFT), (uint8_t)(y0 >> TARN_BIN_CELL_SHIFT),
                                  (uint8_t)(x1 >> TARN_BIN_CELL_SHIFT), (uint8_t)(y1 >> TARN_BIN_CELL_SHIFT)};
    return bin;
}

/* The bin of triangles [first, end) of the cache's mesh: what the walk would hand
 * the rasterizer, less the triangles it would cull. A frame with static screen
 * positions reads them as the walk does: the cache then transforms the vertices
 * of the triangles the frame clips, not those of every triangle. */
static tarn_cluster_bin bin_run(tarn_vertex_cache *cache, const tarn_object *object, uint32_t first,
                                uint32_t end)
{
    const tarn_mesh *mesh = object->mesh;
    const tarn_static_vertex *projected =
        TARN_LINK_STATIC_VERTICES && cache->view->static_screen ? cache->static_vertices : NULL;
    tarn_subpixel_bounds bounds = tarn__bounds_empty();
    int32_t margin = 0; /* 1 once a triangle was clipped */
    for (uint32_t t = first; t < end; t++) {
        const uint16_t *index = &mesh->indices[3 * t];
        tarn_screen_vertex screen[3];
        unsigned outside_any = 0u;
        if (projected == NULL || !tarn__static_screen_positions(projected, index, screen)) {
            if (projected != NULL && tarn__static_outside_a_plane(projected, index)) continue;
            tarn_cached_vertex c[3];
            if (tarn__cached_triangle(cache, index, c, &outside_any)) continue;
            if (outside_any & NEAR_PLANE_BIT) return bin_whole;
            for (int k = 0; k < 3; k++) tarn__cached_projection(cache, &c[k], &screen[k]);
        }
        if (outside_any == 0 && tarn__drawn_area2(screen, object->material->cull) == 0) continue;
        if (outside_any) margin = 1;
        for (int k = 0; k < 3; k++) tarn__bounds_add(&bounds, &screen[k]);
    }
    return to_cells(&bounds, margin, cache->view);
}

/* One object's bins into `bins`, from its vertices (`static_positions` those of its
 * static vertices, or NULL); returns the bins after them. */
static tarn_cluster_bin *bin_object(const tarn_view *view, const tarn_object *object,
                                    const tarn_vec3 *static_positions, tarn_cluster_bin *bins)
{
    const tarn_mesh *mesh = object->mesh;
    tarn_object_xform xform;
    tarn__object_xform_setup(view, object, &xform);
    tarn_vertex_cache cache;
    tarn__vertex_cache_init(&cache, view, &xform, object, static_positions, NULL);
    if (mesh->clusters == NULL) {
        *bins++ = bin_run(&cache, object, 0, mesh->triangle_count);
        return bins;
    }
    for (uint32_t c = 0; c < mesh->cluster_count; c++) {
        const tarn_cluster *cluster = &mesh->clusters[c];
        *bins++ = bin_run(&cache, object, cluster->first_triangle,
                          (uint32_t)cluster->first_triangle + cluster->triangle_count);
    }
    return bins;
}

void tarn__bin_clusters(const tarn_scene *scene, const tarn_view *view, tarn_cluster_bin *bins)
{
    const tarn_vec3 *positions = tarn__static_positions(scene, view);
    for (uint32_t i = 0; i < scene->object_count; i++) {
        bins = bin_object(view, &scene->objects[i], positions, bins);
        if (positions != NULL) positions += scene->objects[i].mesh->vertex_count;
    }
}
