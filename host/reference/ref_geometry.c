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
