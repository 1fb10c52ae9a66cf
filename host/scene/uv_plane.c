/* uv_plane.c: see uv_plane.h. */
#include "uv_plane.h"

#include <math.h>
#include <stdlib.h>

#define Q16 65536.0
#define Q30 1073741824.0
/* How far a vertex may lie off the plane, or a texture coordinate off the affine
 * map, for its extent: Q16.16 positions and coordinates round by 2^-17. */
#define FLAT_TOLERANCE 1e-4
#define GRADIENT_LIMIT 16777216.0 /* tarn_uv_plane's gradients stay below 2^24 */

typedef tarn_dvec3 vec;

static vec add(vec a, vec b, double scale) /* a + b * scale */
{
    const vec r = {a.x + b.x * scale, a.y + b.y * scale, a.z + b.z * scale};
    return r;
}

static vec times(vec v, double scale)
{
    const vec r = {v.x * scale, v.y * scale, v.z * scale};
    return r;
}

static vec vertex(const tarn_mesh *m, uint32_t k)
{
    return tarn_dvec_from_q16(m->positions[k]);
}

static double coordinate(const tarn_mesh *m, uint32_t k, int axis)
{
    if (m->uvs == NULL) return 0.0;
    return (axis == 0 ? m->uvs[k].u : m->uvs[k].v) / Q16;
}

/* The vertex farthest from vertex 0, then the one farthest from the line through
 * both: 0 when every vertex lies on one line. */
static int spanning_vertices(const tarn_mesh *m, uint32_t *a, uint32_t *b)
{
    const vec origin = vertex(m, 0);
    double best = 0;
    *a = *b = 0;
    for (uint32_t k = 1; k < m->vertex_count; k++) {
        const vec d = add(vertex(m, k), origin, -1);
        if (tarn_dvec_dot(d, d) > best) best = tarn_dvec_dot(d, d), *a = k;
    }
    const vec along = add(vertex(m, *a), origin, -1);
    double area = 0;
    for (uint32_t k = 1; k < m->vertex_count; k++) {
        const vec c = tarn_dvec_cross(along, add(vertex(m, k), origin, -1));
        if (tarn_dvec_dot(c, c) > area) area = tarn_dvec_dot(c, c), *b = k;
    }
    return area > 1e-12 * best * best;
}

/* The gradient of a coordinate that is `da` at e1 and `db` at e2 from the origin,
 * over the plane they span. */
static vec gradient(vec e1, vec e2, double da, double db)
{
    const double a = tarn_dvec_dot(e1, e1), b = tarn_dvec_dot(e1, e2), c = tarn_dvec_dot(e2, e2), det = a * c - b * b;
    return add(times(add(times(e1, c), e2, -b), da / det), add(times(e2, a), e1, -b), db / det);
}

/* Whether every vertex lies on the plane and takes the coordinates it gives. */
static int fits_plane(const tarn_mesh *m, const tarn_uv_plane_fit *p, double extent, const char **why)
{
    for (uint32_t k = 0; k < m->vertex_count; k++)
        if (fabs(tarn_dvec_dot(add(vertex(m, k), p->origin, -1), p->normal)) > FLAT_TOLERANCE * extent) {
            *why = "is not flat";
            return 0;
        }
    for (uint32_t k = 0; k < m->vertex_count; k++) {
        const vec d = add(vertex(m, k), p->origin, -1);
        for (int axis = 0; axis < 2; axis++)
            if (fabs(p->uv0[axis] + tarn_dvec_dot(p->gradient[axis], d) - coordinate(m, k, axis)) >
                FLAT_TOLERANCE * (1 + extent)) {
                *why = "has texture coordinates that are not an affine map of its plane";
                return 0;
            }
    }
    return 1;
}

int tarn_uv_plane_find(const tarn_mesh *m, tarn_uv_plane_fit *p, const char **why)
{
    uint32_t a, b;
    if (m->positions == NULL || m->vertex_count < 3 || !spanning_vertices(m, &a, &b)) {
        *why = "spans no plane";
        return 0;
    }
    p->origin = vertex(m, 0);
    const vec e1 = add(vertex(m, a), p->origin, -1), e2 = add(vertex(m, b), p->origin, -1);
    p->normal = tarn_dvec_normalize(tarn_dvec_cross(e1, e2));
    for (int axis = 0; axis < 2; axis++) {
        p->uv0[axis] = coordinate(m, 0, axis);
        p->gradient[axis] = gradient(e1, e2, coordinate(m, a, axis) - p->uv0[axis], coordinate(m, b, axis) - p->uv0[axis]);
    }
    return fits_plane(m, p, sqrt(tarn_dvec_dot(e1, e1)), why);
}

/* round(v) into *out when it lies within int32_t. */
static int rounded_i32(double v, int32_t *out)
{
    const double r = nearbyint(v);
    if (!(r >= -2147483648.0 && r <= 2147483647.0)) return 0; /* and not a number */
    *out = (int32_t)r;
    return 1;
}

int tarn_uv_plane_to_fixed(const tarn_uv_plane_fit *p, tarn_uv_plane *out)
{
    const double normal[3] = {p->normal.x, p->normal.y, p->normal.z};
    double most = 0;
    for (int axis = 0; axis < 2; axis++) {
        const double g[3] = {p->gradient[axis].x, p->gradient[axis].y, p->gradient[axis].z};
        for (int k = 0; k < 3; k++) most = fabs(g[k]) > most ? fabs(g[k]) : most;
    }
    /* the most fraction bits that keep every gradient below 2^24 */
    int bits = (int)TARN_UV_PLANE_GRADIENT_BITS_MAX;
    while (bits > 0 && most * ldexp(1.0, bits) >= GRADIENT_LIMIT - 1) bits--;
    if (!(most * ldexp(1.0, bits) < GRADIENT_LIMIT - 1)) return 0;
    out->uv_gradient_bits = (uint8_t)bits;
    int32_t origin_u, origin_v;
    if (!rounded_i32(tarn_dvec_dot(p->normal, p->origin) * Q16, &out->offset) ||
        !rounded_i32((p->uv0[0] - tarn_dvec_dot(p->gradient[0], p->origin)) * Q16, &origin_u) ||
        !rounded_i32((p->uv0[1] - tarn_dvec_dot(p->gradient[1], p->origin)) * Q16, &origin_v))
        return 0;
    out->uv_origin.u = origin_u;
    out->uv_origin.v = origin_v;
    for (int k = 0; k < 3; k++) {
        out->normal[k] = (int32_t)nearbyint(normal[k] * Q30);
        const double g[2] = {k == 0 ? p->gradient[0].x : k == 1 ? p->gradient[0].y : p->gradient[0].z,
                             k == 0 ? p->gradient[1].x : k == 1 ? p->gradient[1].y : p->gradient[1].z};
        for (int axis = 0; axis < 2; axis++) out->uv_gradient[axis][k] = (int32_t)nearbyint(ldexp(g[axis], bits));
    }
    return 1;
}

/* The largest scale of the water's maps, in repeats per coordinate unit. */
static double finest_map_scale(const tarn_water *w)
{
    const tarn_panning *pans[3] = {w->normal_a != NULL ? &w->pan_a : NULL, w->normal_b != NULL ? &w->pan_b : NULL,
                                   w->foam_texture != NULL ? &w->foam_pan : NULL};
    double most = 0;
    for (int k = 0; k < 3; k++)
        if (pans[k] != NULL && fabs(pans[k]->scale / Q16) > most) most = fabs(pans[k]->scale / Q16);
    return most;
}

/* The most repeats of the finest map the mesh's coordinates reach. */
static double map_repeats(const tarn_mesh *m, const tarn_water *water)
{
    double most = 0;
    for (uint32_t k = 0; k < m->vertex_count; k++)
        for (int axis = 0; axis < 2; axis++)
            if (fabs(coordinate(m, k, axis)) > most) most = fabs(coordinate(m, k, axis));
    return most * finest_map_scale(water);
}

int tarn_mesh_find_plane(tarn_mesh_buffer *m, const tarn_water *water)
{
    tarn_uv_plane_fit fit;
    tarn_uv_plane fixed;
    const char *why;
    free(m->plane);
    m->plane = NULL;
    m->mesh.plane = NULL;
    if (map_repeats(&m->mesh, water) > TARN_UV_PLANE_REPEATS_MAX) return 0;
    if (!tarn_uv_plane_find(&m->mesh, &fit, &why) || !tarn_uv_plane_to_fixed(&fit, &fixed)) return 0;
    m->plane = malloc(sizeof *m->plane);
    if (m->plane == NULL) return -1;
    *m->plane = fixed;
    m->mesh.plane = m->plane;
    return 0;
}
