/* still_planes.c: see still_planes.h. */
#include "still_planes.h"

#include <math.h>

#include "ref_geometry.h"
#include "uv_plane.h"

#define Q16 65536.0
#define Q30 1073741824.0

typedef tarn_dvec3 vec;

static vec add(vec a, vec b, double scale) /* a + b * scale */
{
    const vec r = {a.x + b.x * scale, a.y + b.y * scale, a.z + b.z * scale};
    return r;
}

/* The object's plane (uv_plane.h) in world space: position + scale * rotation p. */
static int object_plane_of(const tarn_object *o, tarn_uv_plane_fit *p, const char **what)
{
    if (!tarn_uv_plane_find(o->mesh, p, what)) return 0;
    const double scale = o->scale / Q16;
    p->origin = tarn_ref_world_position(o, o->mesh->positions[0]);
    p->normal = tarn_dvec_rotate(o->rotation, p->normal);
    for (int axis = 0; axis < 2; axis++) {
        const vec g = tarn_dvec_rotate(o->rotation, p->gradient[axis]);
        const vec per_world_unit = {g.x / scale, g.y / scale, g.z / scale};
        p->gradient[axis] = per_world_unit;
    }
    return 1;
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
static int frame_plane(const tarn_uv_plane_fit *p, const tarn_ref_camera *cam, const tarn_frame_config *config,
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
        tarn_uv_plane_fit p;
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
