/* static_view.c: see static_view.h. */
#include "static_view.h"

#include <stdlib.h>
#include <string.h>

#include "tarn_internal.h"

/* An object's static vertices, and their view positions into `positions`; NULL out
 * of memory. */
static tarn_static_vertex *object_vertices(const tarn_view *view, const tarn_object *object, tarn_vec3 *positions)
{
    const tarn_mesh *mesh = object->mesh;
    tarn_static_vertex *vertices = malloc((mesh->vertex_count > 0 ? mesh->vertex_count : 1u) * sizeof *vertices);
    if (vertices == NULL) return NULL;
    tarn_object_xform xform;
    tarn__object_xform_setup(view, object, &xform);
    for (uint32_t i = 0; i < mesh->vertex_count; i++)
        vertices[i] = tarn__static_vertex_of(view, &xform, mesh, (uint16_t)i, &positions[i]);
    return vertices;
}

static void static_vertices_free(tarn_static_vertices *s)
{
    for (uint32_t i = 0; s->vertices != NULL && i < s->object_count; i++) free(s->vertices[i]);
    free(s->vertices);
    free(s->positions);
    free(s->bins);
}

/* Every object's static vertices, and the static view they are for (its bins not
 * yet found). 0, or -1 out of memory. */
static int static_vertices_build(const tarn_scene *scene, const tarn_frame_config *config,
                                 tarn_static_vertices *out)
{
    tarn_scene plain = *scene; /* a view of its own, whatever static view it had */
    plain.static_view = NULL;
    tarn_view view;
    tarn__view_setup(&plain, config, &view);
    out->view.camera = scene->camera;
    out->view.light = scene->light;
    out->view.width = config->width;
    out->view.height = config->height;
    out->view.subpixel_bits = config->quality.subpixel_bits;
    out->view.bins = NULL;
    out->object_count = scene->object_count;
    const uint32_t vertex_count = tarn__scene_vertex_count(scene);
    out->vertices = calloc(scene->object_count > 0 ? scene->object_count : 1u, sizeof *out->vertices);
    out->positions = malloc((vertex_count > 0 ? vertex_count : 1u) * sizeof *out->positions);
    if (out->vertices == NULL || out->positions == NULL) return -1;
    out->view.positions = out->positions;
    tarn_vec3 *positions = out->positions;
    for (uint32_t i = 0; i < scene->object_count; i++) {
        if ((out->vertices[i] = object_vertices(&view, &scene->objects[i], positions)) == NULL) return -1;
        positions += scene->objects[i].mesh->vertex_count;
    }
    return 0;
}

/* The bins a frame of the scene with its static vertices finds: the same function
 * on the same vertices, so the same boxes. 0, or -1 out of memory. */
static int static_bins(tarn_static_scene *s, const tarn_frame_config *config)
{
    tarn_static_vertices *v = &s->vertices;
    v->bin_count = tarn__cluster_bin_count(&s->scene);
    v->bins = malloc((v->bin_count > 0 ? v->bin_count : 1u) * sizeof *v->bins);
    if (v->bins == NULL) return -1;
    tarn_view view;
    tarn__view_setup(&s->scene, config, &view);
    tarn__bin_clusters(&s->scene, &view, v->bins);
    v->view.bins = v->bins;
    return 0;
}

/* Object i's copy, drawing from its static vertices and a copy of its mesh. */
static void copy_object(tarn_static_scene *s, const tarn_object *object, uint32_t i, int keep_positions)
{
    s->meshes[i] = *object->mesh;
    if (!keep_positions) {
        s->meshes[i].positions = NULL;
        s->meshes[i].normals = NULL;
        s->meshes[i].colours = NULL;
    }
    s->objects[i] = *object;
    s->objects[i].mesh = &s->meshes[i];
    s->objects[i].static_vertices = s->vertices.vertices[i];
}

int tarn_static_scene_make(const tarn_scene *scene, const tarn_frame_config *config, int keep_positions,
                           tarn_static_scene *out, tarn_error *err)
{
    memset(out, 0, sizeof *out);
    const size_t count = scene->object_count > 0 ? scene->object_count : 1u;
    out->objects = calloc(count, sizeof *out->objects);
    out->meshes = calloc(count, sizeof *out->meshes);
    int failed = out->objects == NULL || out->meshes == NULL || static_vertices_build(scene, config, &out->vertices);
    if (!failed) {
        for (uint32_t i = 0; i < scene->object_count; i++) copy_object(out, &scene->objects[i], i, keep_positions);
        out->scene = *scene;
        out->scene.objects = out->objects;
        out->scene.static_view = &out->vertices.view;
        failed = static_bins(out, config);
    }
    if (failed) {
        tarn_static_scene_free(out);
        return tarn_fail(err, "out of memory computing static vertices");
    }
    return 0;
}

void tarn_static_scene_free(tarn_static_scene *s)
{
    static_vertices_free(&s->vertices);
    free(s->objects);
    free(s->meshes);
    memset(s, 0, sizeof *s);
}

size_t tarn_static_memory_bytes(const tarn_frame_config *config, const tarn_scene *scene,
                                const tarn_frame_config *made_for)
{
    tarn_frame_config without_found_bins = *config;
    if (!tarn_scene_moves(scene) && config->width == made_for->width && config->height == made_for->height &&
        config->quality.subpixel_bits == made_for->quality.subpixel_bits)
        without_found_bins.quality.cluster_bins = 0;
    return tarn_frame_memory_bytes(&without_found_bins, scene);
}
