#include "mesh_gen.h"

#include "grid_merge.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

tarn_q16 tarn_q16_from_double(double v)
{
    double scaled = round(v * 65536.0); /* round() ties away from zero, like the core */
    if (!(scaled > (double)INT32_MIN)) return INT32_MIN; /* also catches NaN */
    if (scaled > (double)INT32_MAX) return INT32_MAX;
    return (tarn_q16)scaled;
}

static tarn_vec3 vec3_from_doubles(const double v[3])
{
    tarn_vec3 q = { tarn_q16_from_double(v[0]), tarn_q16_from_double(v[1]),
                    tarn_q16_from_double(v[2]) };
    return q;
}

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

int tarn_mesh_reserve(tarn_mesh_buffer *m, uint32_t vertices, uint32_t triangles, int with_uvs,
                      const char *what, tarn_error *err)
{
    memset(m, 0, sizeof *m);
    if (vertices > TARN_MESH_VERTICES_MAX) {
        return tarn_fail(err, "%s: needs %u vertices; a tarn mesh holds at most %u", what,
                         vertices, TARN_MESH_VERTICES_MAX);
    }
    if (triangles > TARN_MESH_TRIANGLES_MAX) {
        return tarn_fail(err, "%s: needs %u triangles; a tarn mesh holds at most %u", what,
                         triangles, TARN_MESH_TRIANGLES_MAX);
    }
    /* +1 so that an empty mesh still gets non-NULL arrays */
    m->positions = calloc(vertices + 1u, sizeof *m->positions);
    m->normals = calloc(vertices + 1u, sizeof *m->normals);
    m->uvs = with_uvs ? calloc(vertices + 1u, sizeof *m->uvs) : NULL;
    m->indices = calloc(3u * triangles + 1u, sizeof *m->indices);
    if (!m->positions || !m->normals || (with_uvs && !m->uvs) || !m->indices) {
        tarn_mesh_buffer_free(m);
        return tarn_fail(err, "%s: out of memory for %u vertices", what, vertices);
    }
    m->vertex_capacity = vertices;
    m->triangle_capacity = triangles;
    m->mesh.positions = m->positions;
    m->mesh.normals = m->normals;
    m->mesh.uvs = m->uvs;
    m->mesh.colours = NULL;
    m->mesh.indices = m->indices;
    return 0;
}

int tarn_mesh_reserve_colours(tarn_mesh_buffer *m, const char *what, tarn_error *err)
{
    m->colours = malloc((m->vertex_capacity + 1u) * sizeof *m->colours);
    if (!m->colours) {
        uint32_t vertices = m->vertex_capacity;
        tarn_mesh_buffer_free(m);
        return tarn_fail(err, "%s: out of memory for %u vertex colours", what, vertices);
    }
    for (uint32_t k = 0; k < m->vertex_capacity; k++) m->colours[k] = 0xFFFFFFu;
    m->mesh.colours = m->colours;
    return 0;
}

uint16_t tarn_mesh_add_vertex(tarn_mesh_buffer *m, const double position[3],
                              const double normal[3], const double uv[2])
{
    uint16_t index = m->mesh.vertex_count++;
    double length = sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    double unit[3] = { 0.0, 1.0, 0.0 };
    if (length > 0.0 && isfinite(length)) {
        for (int k = 0; k < 3; k++) unit[k] = normal[k] / length;
    }
    m->positions[index] = vec3_from_doubles(position);
    m->normals[index] = vec3_from_doubles(unit);
    if (m->uvs && uv) {
        m->uvs[index].u = tarn_q16_from_double(uv[0]);
        m->uvs[index].v = tarn_q16_from_double(uv[1]);
    }
    return index;
}

void tarn_mesh_add_triangle(tarn_mesh_buffer *m, uint32_t a, uint32_t b, uint32_t c)
{
    uint16_t *tri = m->indices + 3u * m->mesh.triangle_count++;
    tri[0] = (uint16_t)a;
    tri[1] = (uint16_t)b;
    tri[2] = (uint16_t)c;
}

int tarn_mesh_drop_unused_vertices(tarn_mesh_buffer *m, const char *what, tarn_error *err)
{
    const uint32_t vertices = m->mesh.vertex_count, indices = 3u * m->mesh.triangle_count;
    uint32_t *renumber = calloc(vertices + 1u, sizeof *renumber); /* new index + 1, 0 unused */
    if (!renumber) return tarn_fail(err, "%s: out of memory for %u vertices", what, vertices);
    for (uint32_t k = 0; k < indices; k++) renumber[m->indices[k]] = 1;
    uint32_t kept = 0;
    for (uint32_t v = 0; v < vertices; v++) {
        if (!renumber[v]) continue;
        m->positions[kept] = m->positions[v];
        m->normals[kept] = m->normals[v];
        if (m->uvs) m->uvs[kept] = m->uvs[v];
        if (m->colours) m->colours[kept] = m->colours[v];
        renumber[v] = ++kept;
    }
    for (uint32_t k = 0; k < indices; k++) m->indices[k] = (uint16_t)(renumber[m->indices[k]] - 1u);
    m->mesh.vertex_count = (uint16_t)kept;
    free(renumber);
    return 0;
}

void tarn_mesh_buffer_free(tarn_mesh_buffer *m)
{
    if (!m) return;
    free(m->positions);
    free(m->normals);
    free(m->uvs);
    free(m->colours);
    free(m->indices);
    free(m->clusters);
    free(m->plane);
    memset(m, 0, sizeof *m);
}

/* ---- grids: planes and heightfields ------------------------------------------ */

typedef struct {
    uint32_t columns, rows; /* vertices along x and along z, each >= 2 */
    double width, depth;
    double u_scale, v_scale;
    const uint8_t *gray; /* columns*rows heights, or NULL for a flat grid */
    double height;       /* world height of gray 255 */
    int merge_level;     /* merge level squares into fewer triangles (grid_merge.h) */
} grid_spec;

static double grid_height(const grid_spec *g, uint32_t i, uint32_t j)
{
    return g->gray ? g->gray[(size_t)j * g->columns + i] / 255.0 * g->height : 0.0;
}

/* Slope of the surface between the neighbours of (i, j) along x (dx = 1) or z
 * (dz = 1): central where both neighbours exist, one-sided at the border. */
static double grid_slope(const grid_spec *g, uint32_t i, uint32_t j, int along_x)
{
    uint32_t n = along_x ? g->columns : g->rows;
    uint32_t at = along_x ? i : j;
    uint32_t lo = at > 0 ? at - 1 : at, hi = at + 1 < n ? at + 1 : at;
    double spacing = (along_x ? g->width : g->depth) / (n - 1);
    double h_lo = along_x ? grid_height(g, lo, j) : grid_height(g, i, lo);
    double h_hi = along_x ? grid_height(g, hi, j) : grid_height(g, i, hi);
    return (h_hi - h_lo) / ((hi - lo) * spacing);
}

/* Per vertex, the key grid_merge.h merges by: 1 + its height code where its
 * normal points straight up, so that vertices with equal keys draw alike; 0
 * elsewhere, and everywhere when the grid does not merge. */
static uint32_t *level_keys(const grid_spec *g)
{
    uint32_t *keys = calloc((size_t)g->columns * g->rows, sizeof *keys);
    for (uint32_t j = 0; keys && g->merge_level && j < g->rows; j++) {
        for (uint32_t i = 0; i < g->columns; i++) {
            const int level = grid_slope(g, i, j, 1) == 0.0 && grid_slope(g, i, j, 0) == 0.0;
            const uint32_t code = g->gray ? g->gray[(size_t)j * g->columns + i] : 0u;
            keys[(size_t)j * g->columns + i] = level ? code + 1u : 0u;
        }
    }
    return keys;
}

/* The grid's triangles: two per cell, or fewer where level squares merge. */
static int add_grid_triangles(tarn_mesh_buffer *out, const grid_spec *g, const char *what,
                              tarn_error *err)
{
    uint32_t *keys = level_keys(g);
    if (!keys) return tarn_fail(err, "%s: out of memory for %u x %u vertices", what, g->columns, g->rows);
    tarn_grid_blocks blocks;
    const int found = tarn_grid_blocks_find(&blocks, g->columns, g->rows, keys, what, err);
    free(keys);
    if (found) return -1;
    out->mesh.triangle_count = (uint16_t)tarn_grid_blocks_triangles(&blocks, out->indices);
    tarn_grid_blocks_free(&blocks);
    return tarn_mesh_drop_unused_vertices(out, what, err);
}

/* `columns` x `rows` vertices, two triangles a cell. */
static tarn_mesh_size grid_size(uint32_t columns, uint32_t rows)
{
    tarn_mesh_size size = { columns * rows, 2 * (columns - 1) * (rows - 1) };
    return size;
}

tarn_mesh_size tarn_mesh_plane_size(uint32_t segments_x, uint32_t segments_z)
{
    return grid_size(segments_x + 1, segments_z + 1);
}

tarn_mesh_size tarn_mesh_heightfield_size(uint32_t image_width, uint32_t image_height)
{
    return grid_size(image_width, image_height);
}

static int build_grid(tarn_mesh_buffer *out, const grid_spec *g, const char *what,
                      tarn_error *err)
{
    const tarn_mesh_size size = grid_size(g->columns, g->rows);
    if (tarn_mesh_reserve(out, size.vertices, size.triangles, 1, what, err)) return -1;
    for (uint32_t j = 0; j < g->rows; j++) {
        double fz = (double)j / (g->rows - 1);
        for (uint32_t i = 0; i < g->columns; i++) {
            double fx = (double)i / (g->columns - 1);
            double position[3] = { (fx - 0.5) * g->width, grid_height(g, i, j),
                                   (fz - 0.5) * g->depth };
            /* the surface y = h(x, z) has normal (-dh/dx, 1, -dh/dz) */
            double normal[3] = { -grid_slope(g, i, j, 1), 1.0, -grid_slope(g, i, j, 0) };
            double uv[2] = { fx * g->u_scale, fz * g->v_scale };
            tarn_mesh_add_vertex(out, position, normal, uv);
        }
    }
    if (add_grid_triangles(out, g, what, err)) {
        tarn_mesh_buffer_free(out);
        return -1;
    }
    return 0;
}

int tarn_mesh_plane(tarn_mesh_buffer *out, double width, double depth, uint32_t segments_x,
                    uint32_t segments_z, double u_scale, double v_scale, const char *what,
                    tarn_error *err)
{
    grid_spec g = { .columns = segments_x + 1, .rows = segments_z + 1, .width = width,
                    .depth = depth, .u_scale = u_scale, .v_scale = v_scale };
    return build_grid(out, &g, what, err);
}

int tarn_mesh_heightfield(tarn_mesh_buffer *out, const tarn_image *gray, double width,
                          double depth, double height, double u_scale, double v_scale,
                          int merge_level, const char *what, tarn_error *err)
{
    grid_spec g = { .columns = gray->width, .rows = gray->height, .width = width,
                    .depth = depth, .u_scale = u_scale, .v_scale = v_scale,
                    .gray = gray->pixels, .height = height, .merge_level = merge_level };
    return build_grid(out, &g, what, err);
}

/* ---- box ---------------------------------------------------------------------- */

tarn_mesh_size tarn_mesh_box_size(void)
{
    const tarn_mesh_size size = { 24, 12 }; /* four vertices and two triangles a face */
    return size;
}

int tarn_mesh_box(tarn_mesh_buffer *out, double width, double height, double depth,
                  const char *what, tarn_error *err)
{
    /* Each face: its outward normal and the direction that is "right" when seen
     * from outside; up = normal x right, so right x up = normal (counter-clockwise). */
    static const double faces[6][2][3] = {
        { { 1, 0, 0 }, { 0, 0, -1 } }, { { -1, 0, 0 }, { 0, 0, 1 } },
        { { 0, 1, 0 }, { 1, 0, 0 } },  { { 0, -1, 0 }, { 1, 0, 0 } },
        { { 0, 0, 1 }, { 1, 0, 0 } },  { { 0, 0, -1 }, { -1, 0, 0 } },
    };
    static const double corners[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
    const double half[3] = { width / 2, height / 2, depth / 2 };
    const tarn_mesh_size size = tarn_mesh_box_size();
    if (tarn_mesh_reserve(out, size.vertices, size.triangles, 1, what, err)) return -1;
    for (int f = 0; f < 6; f++) {
        const double *normal = faces[f][0], *right = faces[f][1];
        double up[3];
        cross(normal, right, up);
        uint32_t first = out->mesh.vertex_count;
        for (int c = 0; c < 4; c++) {
            double position[3], uv[2] = { (corners[c][0] + 1) / 2, (1 - corners[c][1]) / 2 };
            for (int k = 0; k < 3; k++) {
                position[k] =
                    (normal[k] + corners[c][0] * right[k] + corners[c][1] * up[k]) * half[k];
            }
            tarn_mesh_add_vertex(out, position, normal, uv);
        }
        tarn_mesh_add_triangle(out, first, first + 1, first + 2);
        tarn_mesh_add_triangle(out, first, first + 2, first + 3);
    }
    return 0;
}

/* ---- sphere ------------------------------------------------------------------- */

/* The seam column is duplicated (u = 0 and u = 1) and each pole is one vertex per
 * segment, so every vertex has a single texture coordinate; the triangle touching a
 * pole through two of its corners has no area, so a pole's ring has one a segment. */
tarn_mesh_size tarn_mesh_sphere_size(uint32_t segments, uint32_t rings)
{
    const tarn_mesh_size size = { (rings + 1) * (segments + 1), 2 * segments * (rings - 1) };
    return size;
}

int tarn_mesh_sphere(tarn_mesh_buffer *out, double radius, uint32_t segments, uint32_t rings,
                     const char *what, tarn_error *err)
{
    uint32_t columns = segments + 1;
    const tarn_mesh_size size = tarn_mesh_sphere_size(segments, rings);
    if (tarn_mesh_reserve(out, size.vertices, size.triangles, 1, what, err)) return -1;
    for (uint32_t k = 0; k <= rings; k++) {
        double theta = PI * k / rings; /* 0 at the top pole */
        for (uint32_t s = 0; s <= segments; s++) {
            /* phi grows toward -z so that u increases to the right seen from outside */
            double phi = 2 * PI * s / segments;
            double normal[3] = { sin(theta) * cos(phi), cos(theta), -sin(theta) * sin(phi) };
            double position[3] = { radius * normal[0], radius * normal[1], radius * normal[2] };
            double uv[2] = { (double)s / segments, (double)k / rings };
            tarn_mesh_add_vertex(out, position, normal, uv);
        }
    }
    for (uint32_t k = 0; k < rings; k++) {
        for (uint32_t s = 0; s < segments; s++) {
            uint32_t a = k * columns + s, b = a + columns, c = a + 1, d = b + 1;
            /* the triangle touching a pole through two of its corners has no area */
            if (k != 0) tarn_mesh_add_triangle(out, a, b, c);
            if (k != rings - 1) tarn_mesh_add_triangle(out, c, b, d);
        }
    }
    return 0;
}
