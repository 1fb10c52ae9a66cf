/* mesh_gen.h: heap-owned tarn meshes, built vertex by vertex, and the primitives.
 *
 * Every primitive is in object space, right-handed, +y up, with counter-clockwise
 * front faces seen from outside (or from above), unit normals and texture
 * coordinates. A builder takes doubles and rounds them to Q16.16 once, at the end.
 *
 * `what` in the generators names the object in error messages, e.g.
 * "scenes/pond.json: objects[3]", so a size error points at its source. */
#ifndef TARN_HOST_MESH_GEN_H
#define TARN_HOST_MESH_GEN_H

#include <stdint.h>
#include "error.h"
#include "png_io.h"
#include "tarn/tarn_scene.h"

/* A mesh plus the arrays it views, which it owns. */
typedef struct {
    tarn_mesh mesh; /* what the renderer reads; counts grow as vertices are added */
    tarn_vec3 *positions;
    tarn_vec3 *normals;
    tarn_uv *uvs; /* NULL when the mesh has no texture coordinates */
    uint32_t *colours; /* 0xRRGGBB per vertex; NULL when the mesh has none (white) */
    uint16_t *indices;
    tarn_cluster *clusters; /* NULL until tarn_mesh_build_clusters (host/scene/mesh_clusters.h) */
    tarn_uv_plane *plane;   /* NULL unless tarn_mesh_find_plane (host/scene/uv_plane.h) found one */
    uint32_t vertex_capacity, triangle_capacity;
} tarn_mesh_buffer;

/* Q16.16 from a double: rounded to nearest (ties away from zero), saturated. */
tarn_q16 tarn_q16_from_double(double v);

/* Allocates room for exactly `vertices` and `triangles`, failing with a message
 * about `what` when either exceeds the tarn_mesh limits. */
int tarn_mesh_reserve(tarn_mesh_buffer *m, uint32_t vertices, uint32_t triangles, int with_uvs,
                      const char *what, tarn_error *err);

/* Gives a reserved mesh per-vertex colours, all white until the caller sets
 * colours[index] for the vertices it adds. On failure the mesh is freed, as when
 * tarn_mesh_reserve fails. */
int tarn_mesh_reserve_colours(tarn_mesh_buffer *m, const char *what, tarn_error *err);

/* Appends a vertex and returns its index. The normal is normalised here (a zero
 * normal becomes +y); `uv` may be NULL for meshes without texture coordinates.
 * The caller stays within the reserved count. */
uint16_t tarn_mesh_add_vertex(tarn_mesh_buffer *m, const double position[3],
                              const double normal[3], const double uv[2]);

/* Appends a triangle; a, b, c counter-clockwise seen from its front. */
void tarn_mesh_add_triangle(tarn_mesh_buffer *m, uint32_t a, uint32_t b, uint32_t c);

/* Removes the vertices no triangle uses, keeping the others' order. */
int tarn_mesh_drop_unused_vertices(tarn_mesh_buffer *m, const char *what, tarn_error *err);

void tarn_mesh_buffer_free(tarn_mesh_buffer *m);

/* The vertices and triangles a generator makes room for, known from its arguments
 * before it builds anything, so that a scene can be weighed first (scene_budget.h). */
typedef struct {
    uint32_t vertices, triangles;
} tarn_mesh_size;

tarn_mesh_size tarn_mesh_plane_size(uint32_t segments_x, uint32_t segments_z);
tarn_mesh_size tarn_mesh_box_size(void);
tarn_mesh_size tarn_mesh_sphere_size(uint32_t segments, uint32_t rings);
/* The grid before its level squares merge, which can only drop some of both. */
tarn_mesh_size tarn_mesh_heightfield_size(uint32_t image_width, uint32_t image_height);

/* A flat grid in XZ, centred, facing +y: `segments_x` by `segments_z` quads,
 * texture coordinates from 0 to u_scale (along +x) and v_scale (along +z). */
int tarn_mesh_plane(tarn_mesh_buffer *out, double width, double depth, uint32_t segments_x,
                    uint32_t segments_z, double u_scale, double v_scale, const char *what,
                    tarn_error *err);

/* A box centred on the origin; each face has its own four vertices so that its
 * normals are flat, and texture coordinates 0..1 upright as seen from outside. */
int tarn_mesh_box(tarn_mesh_buffer *out, double width, double height, double depth,
                  const char *what, tarn_error *err);

/* A UV sphere centred on the origin: `segments` around the y axis (>= 3), `rings`
 * from pole to pole (>= 2). u runs around (0 at +x), v from the top pole (0) down. */
int tarn_mesh_sphere(tarn_mesh_buffer *out, double radius, uint32_t segments, uint32_t rings,
                     const char *what, tarn_error *err);

/* One vertex per pixel of a gray image, at height gray/255 * height, spread over
 * width x depth in XZ and centred; the image's top row lies toward -z. Normals are
 * smooth (from neighbouring heights); uvs run 0..u_scale, 0..v_scale. With
 * `merge_level`, level squares are drawn with fewer triangles (grid_merge.h) and
 * the vertices inside them are dropped: for a material lit per vertex alone,
 * not for water, whose vertices also carry a view-dependent fresnel term. */
int tarn_mesh_heightfield(tarn_mesh_buffer *out, const tarn_image *gray, double width,
                          double depth, double height, double u_scale, double v_scale,
                          int merge_level, const char *what, tarn_error *err);

#endif
