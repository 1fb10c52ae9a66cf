/* ref_geometry.c: see ref_geometry.h. */
#include "ref_geometry.h"

#include <math.h>

#define Q16_SCALE 65536.0

tarn_dvec3 tarn_dvec_from_q16(tarn_vec3 v)
{
    tarn_dvec3 r = { v.x / Q16_SCALE, v.y / Q16_SCALE, v.z / Q16_SCALE };
    return r;
}

tarn_dvec3 tarn_dvec_sub(tarn_dvec3 a, tarn_dvec3 b)
{
    tarn_dvec3 r = { a.x - b.x, a.y - b.y, a.z - b.z };
    return r;
}

double tarn_dvec_dot(tarn_dvec3 a, tarn_dvec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

tarn_dvec3 tarn_dvec_cross(tarn_dvec3 a, tarn_dvec3 b)
{
    tarn_dvec3 r = { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
    return r;
}

tarn_dvec3 tarn_dvec_normalize(tarn_dvec3 v)
{
    double len = sqrt(tarn_dvec_dot(v, v));
    tarn_dvec3 r = { v.x / len, v.y / len, v.z / len };
    return r;
}

tarn_dvec3 tarn_dvec_rotate(const tarn_q16 rot[3][3], tarn_dvec3 p)
{
    tarn_dvec3 r;
    double *out[3] = { &r.x, &r.y, &r.z };
    for (int row = 0; row < 3; row++) {
        tarn_dvec3 axis = { rot[row][0] / Q16_SCALE, rot[row][1] / Q16_SCALE, rot[row][2] / Q16_SCALE };
        *out[row] = tarn_dvec_dot(axis, p);
    }
    return r;
}

tarn_ref_camera tarn_ref_camera_make(const tarn_camera *cam, int height)
{
    tarn_ref_camera c;
    c.position = tarn_dvec_from_q16(cam->position);
    c.forward = tarn_dvec_normalize(tarn_dvec_sub(tarn_dvec_from_q16(cam->target), c.position));
    /* f is (anti)parallel to +y exactly when the Q16.16 offset has no x or z */
    int looks_vertically = cam->target.x == cam->position.x && cam->target.z == cam->position.z;
    tarn_dvec3 world_up = { 0, looks_vertically ? 0 : 1, looks_vertically ? -1 : 0 };
    c.right = tarn_dvec_normalize(tarn_dvec_cross(c.forward, world_up));
    c.up = tarn_dvec_cross(c.right, c.forward);
    c.near = cam->near / Q16_SCALE;
    c.far = cam->far / Q16_SCALE;
    double fov = cam->fov_y_degrees / Q16_SCALE * (acos(-1.0) / 180.0);
    c.focal = (height / 2.0) / tan(fov / 2.0);
    return c;
}

tarn_dvec3 tarn_ref_world_position(const tarn_object *object, tarn_vec3 p)
{
    const tarn_dvec3 rotated = tarn_dvec_rotate(object->rotation, tarn_dvec_from_q16(p));
    const double scale = object->scale / Q16_SCALE;
    const tarn_dvec3 pos = tarn_dvec_from_q16(object->position);
    tarn_dvec3 world = { pos.x + scale * rotated.x, pos.y + scale * rotated.y, pos.z + scale * rotated.z };
    return world;
}

static tarn_dvec3 scaled_sum(tarn_dvec3 a, tarn_dvec3 b, double scale) /* a + b * scale */
{
    tarn_dvec3 r = { a.x + b.x * scale, a.y + b.y * scale, a.z + b.z * scale };
    return r;
}

/* A point p lies on the plane when n . (p - position) = scale * offset (n the
 * rotated normal), and takes uv = uv_origin + (rotation g / scale) . (p - position). */
int tarn_ref_plane_uv(const tarn_ref_camera *cam, const tarn_object *object, double x, double y, int width,
                      int height, double uv[2])
{
    const tarn_uv_plane *p = object->mesh->plane;
    const double scale = object->scale / Q16_SCALE;
    const tarn_dvec3 normal = { p->normal[0] / 1073741824.0, p->normal[1] / 1073741824.0, p->normal[2] / 1073741824.0 };
    const tarn_dvec3 n = tarn_dvec_rotate(object->rotation, normal);
    const tarn_dvec3 dir = scaled_sum(scaled_sum(cam->forward, cam->right, (x - width / 2.0) / cam->focal), cam->up,
                                      (height / 2.0 - y) / cam->focal);
    const double along = tarn_dvec_dot(n, dir);
    if (along == 0) return 0;
    const tarn_dvec3 from_origin = tarn_dvec_sub(cam->position, tarn_dvec_from_q16(object->position));
    const double t = (scale * p->offset / Q16_SCALE - tarn_dvec_dot(n, from_origin)) / along;
    const tarn_dvec3 at = scaled_sum(from_origin, dir, t); /* the point, from the object's origin */
    const double origin[2] = { p->uv_origin.u / Q16_SCALE, p->uv_origin.v / Q16_SCALE };
    for (int axis = 0; axis < 2; axis++) {
        const double per = ldexp(1.0, -(int)p->uv_gradient_bits) / scale;
        const tarn_dvec3 g = { p->uv_gradient[axis][0] * per, p->uv_gradient[axis][1] * per,
                               p->uv_gradient[axis][2] * per };
        uv[axis] = origin[axis] + tarn_dvec_dot(tarn_dvec_rotate(object->rotation, g), at);
    }
    return 1;
}
