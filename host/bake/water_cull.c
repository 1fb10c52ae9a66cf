/* water_cull.c: see water_cull.h. */
#include "water_cull.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tarn_internal.h"

#define BOX_SPARE_PIXELS 2

typedef struct {
    double x, y, d; /* view space, world units */
} view_point;

/* The part of triangle v with d >= near: at most four corners. */
static int clip_to_near(const view_point v[3], double near, view_point out[4])
{
    int n = 0;
    for (int k = 0; k < 3; k++) {
        const view_point *a = &v[k], *b = &v[(k + 1) % 3];
        if (a->d >= near) out[n++] = *a;
        if ((a->d >= near) != (b->d >= near)) {
            const double t = (near - a->d) / (b->d - a->d);
            out[n++] = (view_point){a->x + t * (b->x - a->x), a->y + t * (b->y - a->y), near};
        }
    }
    return n;
}

typedef struct {
    const uint8_t *water;
    int width, height;
    double focal, near;
} frame_water;

/* Whether a water pixel lies in the screen box of the clipped triangle. */
static int may_draw(const frame_water *f, const view_point v[3])
{
    view_point corner[4];
    const int n = clip_to_near(v, f->near, corner);
    if (n == 0) return 0;
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int k = 0; k < n; k++) {
        const double sx = f->width / 2.0 + corner[k].x * f->focal / corner[k].d;
        const double sy = f->height / 2.0 - corner[k].y * f->focal / corner[k].d;
        x0 = fmin(x0, sx), x1 = fmax(x1, sx), y0 = fmin(y0, sy), y1 = fmax(y1, sy);
    }
    const int i0 = (int)fmax(0.0, floor(x0) - BOX_SPARE_PIXELS);
    const int i1 = (int)fmin(f->width - 1.0, ceil(x1) + BOX_SPARE_PIXELS);
    const int j0 = (int)fmax(0.0, floor(y0) - BOX_SPARE_PIXELS);
    const int j1 = (int)fmin(f->height - 1.0, ceil(y1) + BOX_SPARE_PIXELS);
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++)
            if (f->water[(size_t)j * (size_t)f->width + (size_t)i]) return 1;
    return 0;
}

static view_point view_position(const tarn_object_xform *xform, const tarn_vec3 *p)
{
    tarn_view_vertex v;
    tarn__vertex_position(xform, p, &v);
    return (view_point){v.x / 65536.0, v.y / 65536.0, v.d / 65536.0};
}

/* The triangles of [first, end) that may draw, appended to `indices` after the
 * `kept` there: the new count. */
static uint16_t keep_drawing_run(const frame_water *f, const tarn_object_xform *xform, const tarn_mesh *m,
                                 uint32_t first, uint32_t end, uint16_t *indices, uint16_t kept)
{
    for (uint32_t t = first; t < end; t++) {
        const uint16_t *corner = &m->indices[3u * t];
        const view_point v[3] = {view_position(xform, &m->positions[corner[0]]),
                                 view_position(xform, &m->positions[corner[1]]),
                                 view_position(xform, &m->positions[corner[2]])};
        if (!may_draw(f, v)) continue;
        memcpy(&indices[3u * kept], corner, 3u * sizeof *corner);
        kept++;
    }
    return kept;
}

/* The mesh's kept triangles into `indices`, in order, and each cluster's run over
 * them into `clusters`: a cluster keeps its sphere, which still holds every vertex
 * it runs over. Returns the kept triangle count. */
static uint16_t keep_drawing_triangles(const frame_water *f, const tarn_object_xform *xform, const tarn_mesh *m,
                                       uint16_t *indices, tarn_cluster *clusters)
{
    if (m->clusters == NULL) return keep_drawing_run(f, xform, m, 0, m->triangle_count, indices, 0);
    uint16_t kept = 0;
    for (uint32_t k = 0; k < m->cluster_count; k++) {
        const tarn_cluster *run = &m->clusters[k];
        clusters[k] = *run;
        clusters[k].first_triangle = kept;
        kept = keep_drawing_run(f, xform, m, run->first_triangle, (uint32_t)run->first_triangle + run->triangle_count,
                                indices, kept);
        clusters[k].triangle_count = (uint16_t)(kept - clusters[k].first_triangle);
    }
    return kept;
}

static int cull_object(const frame_water *f, const tarn_view *view, tarn_object *object, tarn_water_cull *c,
                       uint32_t i)
{
    const tarn_mesh *m = object->mesh;
    c->indices[i] = malloc((3u * m->triangle_count + 1u) * sizeof *c->indices[i]);
    c->clusters[i] = malloc((m->cluster_count + 1u) * sizeof *c->clusters[i]);
    if (c->indices[i] == NULL || c->clusters[i] == NULL) return -1;
    tarn_object_xform xform;
    tarn__object_xform_setup(view, object, &xform);
    c->meshes[i] = *m;
    c->meshes[i].indices = c->indices[i];
    c->meshes[i].clusters = m->clusters != NULL ? c->clusters[i] : NULL;
    c->meshes[i].triangle_count = keep_drawing_triangles(f, &xform, m, c->indices[i], c->clusters[i]);
    c->triangles_before += m->triangle_count;
    c->triangles_after += c->meshes[i].triangle_count;
    object->mesh = &c->meshes[i];
    return 0;
}

int tarn_water_cull_make(tarn_scene *scene, tarn_object *objects, const tarn_frame_config *config,
                         const uint8_t *water, tarn_water_cull *out, tarn_error *err)
{
    memset(out, 0, sizeof *out);
    const size_t count = scene->object_count > 0 ? scene->object_count : 1u;
    out->object_count = scene->object_count;
    out->meshes = calloc(count, sizeof *out->meshes);
    out->indices = calloc(count, sizeof *out->indices);
    out->clusters = calloc(count, sizeof *out->clusters);
    int failed = out->meshes == NULL || out->indices == NULL || out->clusters == NULL;
    tarn_scene plain = *scene;
    plain.static_view = NULL;
    tarn_view view;
    tarn__view_setup(&plain, config, &view);
    const frame_water f = {water, config->width, config->height, view.focal_q12 / 4096.0, view.near / 65536.0};
    for (uint32_t i = 0; !failed && i < scene->object_count; i++)
        if (objects[i].material->water != NULL && objects[i].mesh->positions != NULL)
            failed = cull_object(&f, &view, &objects[i], out, i) != 0;
    scene->objects = objects;
    if (failed) {
        tarn_water_cull_free(out);
        return tarn_fail(err, "out of memory leaving out hidden water triangles");
    }
    return 0;
}

void tarn_water_cull_free(tarn_water_cull *c)
{
    for (uint32_t i = 0; i < c->object_count; i++) {
        if (c->indices != NULL) free(c->indices[i]);
        if (c->clusters != NULL) free(c->clusters[i]);
    }
    free(c->meshes);
    free(c->indices);
    free(c->clusters);
    memset(c, 0, sizeof *c);
}
