/* static_view.c: see static_view.h. */
#include "static_view.h"

#include <stdlib.h>

#include "cluster_bins.h"
#include "pipeline.h"

/* Vertex `index` as a frame computes it: tarn_vertex_cache's position, outcode,
 * projection (inside every clip plane only) and shading. */
static tarn_static_vertex static_vertex(const tarn_view *view, const tarn_object_xform *xform,
                                        const tarn_mesh *mesh, uint16_t index)
{
    tarn_static_vertex out = {0, 0, 0, 0, 0, 0, {0, 0, 0}, 0};
    tarn_view_vertex v;
    tarn_vertex_position(xform, &mesh->positions[index], &v);
    out.x = v.x;
    out.y = v.y;
    out.d = v.d;
    if (tarn_clip_outcode(view, &v) == 0u) {
        tarn_screen_vertex screen;
        tarn_project_position(view, &v, &screen);
        out.screen_x = (int16_t)screen.x;
        out.screen_y = (int16_t)screen.y;
        out.inv_depth = screen.inv_depth;
    }
    tarn_vertex_shade(view, xform, mesh, index, &v);
    for (int c = 0; c < 3; c++) out.lit[c] = (uint16_t)v.lit[c];
    out.fresnel = (uint16_t)v.fresnel;
    return out;
}

static tarn_static_vertex *object_vertices(const tarn_view *view, const tarn_object *object)
{
    const tarn_mesh *mesh = object->mesh;
    tarn_static_vertex *vertices = malloc((mesh->vertex_count > 0 ? mesh->vertex_count : 1u) * sizeof *vertices);
    if (vertices == NULL) return NULL;
    tarn_object_xform xform;
    tarn_object_xform_setup(view, object, &xform);
    for (uint32_t i = 0; i < mesh->vertex_count; i++) vertices[i] = static_vertex(view, &xform, mesh, (uint16_t)i);
    return vertices;
}

/* The bins a frame of the scene with these static vertices finds: the same function
 * on the same vertices, so the same boxes. */
static int static_bins(const tarn_scene *scene, const tarn_frame_config *config, tarn_static_vertices *s)
{
    tarn_object *objects = calloc(scene->object_count > 0 ? scene->object_count : 1u, sizeof *objects);
    s->bin_count = tarn_cluster_bin_count(scene);
    s->bins = malloc((s->bin_count > 0 ? s->bin_count : 1u) * sizeof *s->bins);
    if (objects == NULL || s->bins == NULL) {
        free(objects);
        return -1;
    }
    for (uint32_t i = 0; i < scene->object_count; i++) {
        objects[i] = scene->objects[i];
        objects[i].static_vertices = s->vertices[i];
    }
    tarn_scene with_static = *scene;
    with_static.objects = objects;
    with_static.static_view = &s->view;
    tarn_view view;
    tarn_view_setup(&with_static, config, &view);
    tarn_bin_clusters(&with_static, &view, s->bins);
    free(objects);
    s->view.bins = s->bins;
    return 0;
}

int tarn_static_vertices_build(const tarn_scene *scene, const tarn_frame_config *config,
                               tarn_static_vertices *out, tarn_error *err)
{
    tarn_scene plain = *scene; /* a view of its own, whatever static view it had */
    plain.static_view = NULL;
    tarn_view view;
    tarn_view_setup(&plain, config, &view);
    out->view.camera = scene->camera;
    out->view.light = scene->light;
    out->view.width = config->width;
    out->view.height = config->height;
    out->view.subpixel_bits = config->quality.subpixel_bits;
    out->view.bins = NULL;
    out->bins = NULL;
    out->object_count = scene->object_count;
    out->vertices = calloc(scene->object_count > 0 ? scene->object_count : 1u, sizeof *out->vertices);
    if (out->vertices == NULL) return tarn_fail(err, "out of memory computing static vertices");
    for (uint32_t i = 0; i < scene->object_count; i++) {
        out->vertices[i] = object_vertices(&view, &scene->objects[i]);
        if (out->vertices[i] == NULL) {
            tarn_static_vertices_free(out);
            return tarn_fail(err, "out of memory computing static vertices");
        }
    }
    if (static_bins(scene, config, out) != 0) {
        tarn_static_vertices_free(out);
        return tarn_fail(err, "out of memory computing static vertices");
    }
    return 0;
}

size_t tarn_static_memory_bytes(const tarn_frame_config *config, const tarn_scene *scene,
                                const tarn_frame_config *made_for)
{
    tarn_frame_config without_found_bins = *config;
    if (config->width == made_for->width && config->height == made_for->height &&
        config->quality.subpixel_bits == made_for->quality.subpixel_bits)
        without_found_bins.quality.cluster_bins = 0;
    return tarn_frame_memory_bytes(&without_found_bins, scene);
}

void tarn_static_vertices_free(tarn_static_vertices *s)
{
    for (uint32_t i = 0; s->vertices != NULL && i < s->object_count; i++) free(s->vertices[i]);
    free(s->vertices);
    free(s->bins);
    s->vertices = NULL;
    s->bins = NULL;
    s->object_count = 0;
    s->bin_count = 0;
}
