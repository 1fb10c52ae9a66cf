/* still_planes.c: see still_planes.h. */
#include "still_planes.h"

#include <math.h>

#include "ref_geometry.h"

#define Q16 65536.0
#define Q30 1073741824.0
/* How far a vertex may lie off the plane, or a texture coordinate off the affine
 * map, for its extent: Q16.16 positions and coordinates round by 2^-17. */
#define FLAT_TOLERANCE 1e-4

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

/* Vertex k of the object in world space, as the reference draws it. */
static vec world_vertex(const tarn_object *o, uint32_t k)
{
    return tarn_ref_world_position(o, o->mesh->positions[k]);
}

static double coordinate(const tarn_object *o, uint32_t k, int axis)
{
    if (o->mesh->uvs == NULL) return 0.0;
    return (axis == 0 ? o->mesh->uvs[k].u : o->mesh->uvs[k].v) / Q16;
}

/* The object's plane through its vertex 0 with normal n, and the world gradients of
 * its two texture coordinates, from three vertices that span it. */
typedef struct {
    vec origin, normal;
    double uv0[2];
    vec gradient[2];
} object_plane;

/* The vertex farthest from vertex 0, then the one farthest from the line through
 * both: 0 when every vertex lies on one line. */
static int spanning_vertices(const tarn_object *o, uint32_t *a, uint32_t *b)
{
    const vec origin = world_vertex(o, 0);
    double best = 0;
    *a = *b = 0;
    for (uint32_t k = 1; k < o->mesh->vertex_count; k++) {
        const vec d = add(world_vertex(o, k), origin, -1);
        if (tarn_dvec_dot(d, d) > best) best = tarn_dvec_dot(d, d), *a = k;
    }
    const vec along = add(world_vertex(o, *a), origin, -1);
    double area = 0;
    for (uint32_t k = 1; k < o->mesh->vertex_count; k++) {
        const vec c = tarn_dvec_cross(along, add(world_vertex(o, k), origin, -1));
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
static int object_fits_plane(const tarn_object *o, const object_plane *p, double extent, const char **what)
{
    for (uint32_t k = 0; k < o->mesh->vertex_count; k++)
        if (fabs(tarn_dvec_dot(add(world_vertex(o, k), p->origin, -1), p->normal)) > FLAT_TOLERANCE * extent) {
            *what = "is not flat";
            return 0;
        }
    for (uint32_t k = 0; k < o->mesh->vertex_count; k++) {
        const vec d = add(world_vertex(o, k), p->origin, -1);
        for (int axis = 0; axis < 2; axis++)
            if (fabs(p->uv0[axis] + tarn_dvec_dot(p->gradient[axis], d) - coordinate(o, k, axis)) > FLAT_TOLERANCE * (1 + extent)) {
                *what = "has texture coordinates that are not an affine map of its plane";
                return 0;
            }
    }
    return 1;
}

static int object_plane_of(const tarn_object *o, object_plane *p, const char **what)
{
    uint32_t a, b;
    if (o->mesh->positions == NULL || o->mesh->vertex_count < 3 || !spanning_vertices(o, &a, &b)) {
        *what = "spans no plane";
        return 0;
    }
    p->origin = world_vertex(o, 0);
    const vec e1 = add(world_vertex(o, a), p->origin, -1), e2 = add(world_vertex(o, b), p->origin, -1);
    p->normal = tarn_dvec_normalize(tarn_dvec_cross(e1, e2));
    for (int axis = 0; axis < 2; axis++) {
        p->uv0[axis] = coordinate(o, 0, axis);
        p->gradient[axis] = gradient(e1, e2, coordinate(o, a, axis) - p->uv0[axis], coordinate(o, b, axis) - p->uv0[axis]);
    }
    return object_fits_plane(o, p, sqrt(tarn_dvec_dot(e1, e1)), what);
}

/* An affine function of the pixel centre (x, y): at + per_x * x + per_y * y. */
typedef struct {
    double at, per_x, per_y;
} affine;

static double affine_at(const affine *f, double x, double y)
{
    return f->at + f->per_x * x + f->per_y * y;
}

/* w . dir for the ray through pixel centre (x, y), dir = forward + (x - W/2) / f *
 * right + (H/2 - y) / f * up, whose forward part is 1: its points lie at view
 * depth t at eye + t * dir. */
static affine along_ray(const tarn_ref_camera *cam, const tarn_frame_config *config, vec w)
{
    const affine f = {tarn_dvec_dot(w, cam->forward) - config->width / 2.0 / cam->focal * tarn_dvec_dot(w, cam->right) +
                          config->height / 2.0 / cam->focal * tarn_dvec_dot(w, cam->up),
                      tarn_dvec_dot(w, cam->right) / cam->focal, -tarn_dvec_dot(w, cam->up) / cam->focal};
    return f;
}

static affine scaled(affine f, double by)
{
    const affine r = {f.at * by, f.per_x * by, f.per_y * by};
    return r;
}

static affine sum(affine a, affine b)
{
    const affine r = {a.at + b.at, a.per_x + b.per_x, a.per_y + b.per_y};
    return r;
}

/* The largest |f| over the frame's pixel centres, at a corner; not a number when
 * f is none somewhere. */
static double largest(const affine *f, const tarn_frame_config *config)
{
    double most = 0;
    for (int corner = 0; corner < 4; corner++) {
        const double x = (corner & 1) ? config->width - 0.5 : 0.5, y = (corner & 2) ? config->height - 0.5 : 0.5;
        const double v = fabs(affine_at(f, x, y));
        if (!(v <= most)) most = v; /* and not a number stays so */
    }
    return most;
}

/* f at pixel (i, j) = f at centre (i + 0.5, j + 0.5), rounded. */
static void store(const affine *f, int32_t out[3])
{
    out[0] = (int32_t)lround(affine_at(f, 0.5, 0.5));
    out[1] = (int32_t)lround(f->per_x);
    out[2] = (int32_t)lround(f->per_y);
}

/* The integers of plane p as the frame sees it; 0 when near/d, or a coordinate
 * times it, passes 2^31 in the frame. near/d = near * (n . dir) / (n . (origin - eye)); along the ray a point is
 * eye + t * dir with t = near / (near/d), so coordinate * near/d = (uv0 + g .
 * (eye - origin)) * near/d + near * (g . dir). */
static int frame_plane(const object_plane *p, const tarn_ref_camera *cam, const tarn_frame_config *config,
                       tarn_still_plane *out)
{
    const vec to_plane = add(p->origin, cam->position, -1);
    const affine depth = scaled(along_ray(cam, config, p->normal), Q30 * cam->near / tarn_dvec_dot(p->normal, to_plane));
    if (!(largest(&depth, config) < Q30 * 2 - 4096.0)) return 0; /* also when not a number */
    affine uv[2];
    double most = 0;
    for (int axis = 0; axis < 2; axis++) {
        const double at_eye = p->uv0[axis] - tarn_dvec_dot(p->gradient[axis], to_plane);
        uv[axis] = scaled(sum(scaled(depth, at_eye), scaled(along_ray(cam, config, p->gradient[axis]), Q30 * cam->near)),
                          Q16);
        const double v = largest(&uv[axis], config);
        if (!(v <= most)) most = v;
    }
    unsigned shift = 0;
    while (shift < 31u && most / ldexp(1.0, (int)shift) >= Q30) shift++;
    if (!(most / ldexp(1.0, (int)shift) < Q30)) return 0;
    const affine u = scaled(uv[0], ldexp(1.0, -(int)shift)), v = scaled(uv[1], ldexp(1.0, -(int)shift));
    store(&depth, out->depth);
    store(&u, out->u);
    store(&v, out->v);
    out->uv_shift = (uint8_t)shift;
    return 1;
}

int tarn_still_planes_make(const tarn_scene *scene, const tarn_frame_config *config, tarn_still_plane *planes,
                           tarn_error *err)
{
    const tarn_ref_camera cam = tarn_ref_camera_make(&scene->camera, config->height);
    uint32_t count = 0;
    for (uint32_t k = 0; k < scene->object_count; k++) {
        const tarn_object *o = &scene->objects[k];
        if (o->material == NULL || o->material->water == NULL) continue;
        object_plane p;
        const char *what = NULL;
        if (!object_plane_of(o, &p, &what))
            return tarn_fail(err, "--backdrop still: water object objects[%u] %s; still water draws flat water only",
                             k, what);
        if (!frame_plane(&p, &cam, config, &planes[count++]))
            return tarn_fail(err, "--backdrop still: water object objects[%u] comes so close to the camera that its "
                                  "depth leaves 32 bits in the frame", k);
    }
    return 0;
}
