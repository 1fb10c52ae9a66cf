/* ref_motion.c: a moving scene posed in doubles (tarn_motion.h's formulas, libm's
 * sines), each pose then rounded to the scene's Q16.16 as the loader rounds every
 * number of a still scene. The core poses the same scene in integers
 * (core/scene/motion.c); tests/test_motion.c holds the two together. */
#include "ref_motion.h"

#include <math.h>

#include "tarn/tarn_render.h"

#define Q16 65536.0
#define TURN (2.0 * acos(-1.0))

static double phase(uint32_t time_ms, uint32_t period_ms)
{
    return (double)(time_ms % period_ms) / period_ms;
}

static tarn_q16 q16_of(double v)
{
    const double r = floor(v * Q16 + 0.5);
    return (tarn_q16)(r > 2147483647.0 ? 2147483647.0 : (r < -2147483648.0 ? -2147483648.0 : r));
}

static tarn_vec3 vec3_of(const double v[3])
{
    const tarn_vec3 q = { q16_of(v[0]), q16_of(v[1]), q16_of(v[2]) };
    return q;
}

/* ---- keys ------------------------------------------------------------------- */

static double key_time(const tarn_key_curve *c, int i)
{
    const int n = c->key_count;
    if (c->loop_ms == 0u) return c->times_ms[i < 0 ? 0 : (i >= n ? n - 1 : i)];
    if (i < 0) return (double)c->times_ms[i + n] - c->loop_ms;
    if (i >= n) return (double)c->times_ms[i - n] + c->loop_ms;
    return c->times_ms[i];
}

static double key_value(const tarn_key_curve *c, int i, int channel)
{
    const int n = c->key_count;
    const int k = c->loop_ms == 0u ? (i < 0 ? 0 : (i >= n ? n - 1 : i)) : (i + n) % n;
    return c->values[k * c->channels + channel] / Q16;
}

static double velocity(const tarn_key_curve *c, int i, int channel)
{
    int before = i - 1, after = i + 1;
    if (c->loop_ms == 0u) {
        before = before < 0 ? 0 : before;
        after = after >= c->key_count ? c->key_count - 1 : after;
    }
    return (key_value(c, after, channel) - key_value(c, before, channel)) / (key_time(c, after) - key_time(c, before));
}

void tarn_ref_key_curve_at(const tarn_key_curve *c, uint32_t time_ms, double *out)
{
    const int n = c->key_count;
    double t = c->loop_ms != 0u ? (double)(time_ms % c->loop_ms) : (double)time_ms;
    int k;
    if (t < c->times_ms[0]) {
        k = c->loop_ms == 0u ? -1 : n - 1;
        t += c->loop_ms;
    } else {
        for (k = 0; k + 1 < n && c->times_ms[k + 1] <= t; k++) continue;
    }
    for (int ch = 0; ch < c->channels; ch++) {
        if (n == 1 || k < 0 || (k == n - 1 && c->loop_ms == 0u)) {
            out[ch] = key_value(c, k, ch);
            continue;
        }
        const double h = key_time(c, k + 1) - key_time(c, k), s = (t - key_time(c, k)) / h;
        const double s2 = s * s, s3 = s2 * s;
        out[ch] = (2 * s3 - 3 * s2 + 1) * key_value(c, k, ch) + (s3 - 2 * s2 + s) * h * velocity(c, k, ch) +
                  (-2 * s3 + 3 * s2) * key_value(c, k + 1, ch) + (s3 - s2) * h * velocity(c, k + 1, ch);
    }
}

/* ---- rotations -------------------------------------------------------------- */

/* Rodrigues' rotation by `turns` about the axis (Q16.16). */
static void axis_rotation(const tarn_vec3 *axis, double turns, double r[3][3])
{
    const double k[3] = { axis->x / Q16, axis->y / Q16, axis->z / Q16 };
    const double s = sin(TURN * turns), c = cos(TURN * turns);
    const double cross[3][3] = { { 0, -k[2], k[1] }, { k[2], 0, -k[0] }, { -k[1], k[0], 0 } };
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r[i][j] = (i == j ? c : 0.0) + s * cross[i][j] + (1 - c) * k[i] * k[j];
}

static void rotate(double r[3][3], const double v[3], double out[3])
{
    for (int i = 0; i < 3; i++) out[i] = r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2];
}

static void vec3_doubles(const tarn_vec3 *v, double out[3])
{
    out[0] = v->x / Q16;
    out[1] = v->y / Q16;
    out[2] = v->z / Q16;
}

/* ---- the parts ---------------------------------------------------------------- */

static void pose_camera(const tarn_camera_path *p, uint32_t time_ms, tarn_camera *camera)
{
    if (p->kind == TARN_CAMERA_ORBIT) {
        const double a = p->start_turns_q32 / 4294967296.0 + (p->clockwise ? -1 : 1) * phase(time_ms, p->period_ms);
        const double position[3] = { p->centre.x / Q16 + p->radius / Q16 * sin(TURN * a),
                                     (p->centre.y + (double)p->height) / Q16,
                                     p->centre.z / Q16 + p->radius / Q16 * cos(TURN * a) };
        camera->position = vec3_of(position);
        camera->target = p->target;
        return;
    }
    double v[TARN_KEY_CHANNELS_MAX];
    tarn_ref_key_curve_at(&p->keys, time_ms, v);
    camera->position = vec3_of(v);
    camera->target = vec3_of(v + 3);
    if (p->keys.channels == 7u) camera->fov_y_degrees = q16_of(fmin(179.0, fmax(1.0, v[6])));
}

static void pose_light(const tarn_light_motion *m, uint32_t time_ms, tarn_light *light)
{
    double d[3];
    vec3_doubles(&light->direction, d);
    if (m->direction.key_count > 0u) {
        double v[3];
        tarn_ref_key_curve_at(&m->direction, time_ms, v);
        const double length = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (length > 0)
            for (int i = 0; i < 3; i++) d[i] = v[i] / length;
    }
    if (m->spin_period_ms > 0u) {
        double r[3][3], turned[3];
        axis_rotation(&m->spin_axis, phase(time_ms, m->spin_period_ms), r);
        rotate(r, d, turned);
        for (int i = 0; i < 3; i++) d[i] = turned[i];
    }
    light->direction = vec3_of(d);
}

static void pose_object(const tarn_object_motion *m, uint32_t time_ms, tarn_object *o)
{
    double position[3];
    vec3_doubles(&o->position, position);
    if (m->path.key_count > 0u) tarn_ref_key_curve_at(&m->path, time_ms, position);
    if (m->bob_period_ms > 0u) {
        const double s = sin(TURN * (phase(time_ms, m->bob_period_ms) + m->bob_phase_q32 / 4294967296.0));
        double bob[3];
        vec3_doubles(&m->bob, bob);
        for (int i = 0; i < 3; i++) position[i] += bob[i] * s;
    }
    o->position = vec3_of(position);
    if (m->spin_period_ms > 0u) {
        double r[3][3];
        axis_rotation(&m->spin_axis, phase(time_ms, m->spin_period_ms), r);
        for (int column = 0; column < 3; column++) {
            const double base[3] = { o->rotation[0][column] / Q16, o->rotation[1][column] / Q16,
                                     o->rotation[2][column] / Q16 };
            double turned[3];
            rotate(r, base, turned);
            for (int row = 0; row < 3; row++) o->rotation[row][column] = q16_of(turned[row]);
        }
    }
    o->motion = NULL;
}

void tarn_ref_scene_pose(const tarn_scene *scene, uint32_t time_ms, tarn_scene *posed, tarn_object *objects)
{
    *posed = *scene;
    posed->camera_path = NULL;
    posed->light_motion = NULL;
    if (scene->camera_path != NULL || scene->light_motion != NULL) posed->static_view = NULL;
    if (scene->camera_path != NULL) pose_camera(scene->camera_path, time_ms, &posed->camera);
    if (scene->light_motion != NULL) pose_light(scene->light_motion, time_ms, &posed->light);
    for (uint32_t i = 0; i < scene->object_count; i++) {
        objects[i] = scene->objects[i];
        if (objects[i].motion != NULL) pose_object(objects[i].motion, time_ms, &objects[i]);
    }
    posed->objects = objects;
}
