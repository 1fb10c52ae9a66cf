/* motion.c: a moving scene posed for a frame's time (tarn_motion.h): the camera on
 * its path, the light turned, each object's position and rotation. Once a frame,
 * a few sines and one curve per moving part; 64-bit products throughout. */
#include "scene/scene_internal.h"

#define ONE_Q30 ((int64_t)1 << 30)

/* (t mod period) / period in Q0.32 turns, to the floor. */
static uint32_t phase_q32(uint32_t time_ms, uint32_t period_ms)
{
    const tarn_divisor divisor = tarn_divisor_of(period_ms);
    uint32_t within;
    (void)tarn_divide_u64(time_ms, &divisor, &within);
    return (uint32_t)tarn_divide_u64((uint64_t)within << 32, &divisor, 0);
}

/* q16 * x_q30, in Q16.16, rounded and held in 32 bits. */
static int32_t scale_q16(int32_t q16, int32_t x_q30)
{
    return tarn_sat_i64_to_i32(tarn_round_shift_i64((int64_t)q16 * x_q30, 30));
}

static tarn_vec3 vec3_of(const int32_t v[3])
{
    const tarn_vec3 out = {v[0], v[1], v[2]};
    return out;
}

/* The rotation by `turns` about the unit axis k (Q16.16), Q2.30 rows:
 * R = cos I + sin [k]x + (1 - cos) k k^T (Rodrigues). */
static void axis_rotation_q30(const tarn_vec3 *axis, uint32_t turns_q32, int32_t r[3][3])
{
    int32_t s, c;
    tarn_sin_cos_turns_q30(turns_q32, &s, &c);
    const int32_t k[3] = {axis->x, axis->y, axis->z};
    /* [k]x: row i, column j holds -e_ijm k_m */
    const int32_t cross[3][3] = {{0, -k[2], k[1]}, {k[2], 0, -k[0]}, {-k[1], k[0], 0}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const int64_t kk_q30 = tarn_round_shift_i64((int64_t)k[i] * k[j], 2);
            int64_t e = tarn_round_shift_i64(kk_q30 * (ONE_Q30 - c), 30) + tarn_round_shift_i64((int64_t)s * cross[i][j], 16);
            if (i == j) e += c;
            r[i][j] = tarn_sat_i64_to_i32(e);
        }
}

/* v turned by r (Q2.30 rows), Q16.16. */
static tarn_vec3 rotate_vec3(int32_t r[3][3], const tarn_vec3 *v)
{
    const int32_t in[3] = {v->x, v->y, v->z};
    int32_t out[3];
    for (int i = 0; i < 3; i++) {
        int64_t sum = 0;
        for (int j = 0; j < 3; j++) sum += (int64_t)r[i][j] * in[j];
        out[i] = tarn_sat_i64_to_i32(tarn_round_shift_i64(sum, 30));
    }
    return vec3_of(out);
}

/* A Q1.30 unit vector from v (Q16.16), as Q16.16; `fallback` for the zero vector. */
static tarn_vec3 unit_q16(const int32_t v[3], const tarn_vec3 *fallback)
{
    const int64_t wide[3] = {v[0], v[1], v[2]};
    int32_t unit[3];
    if (!tarn_normalise_q30(wide, unit)) return *fallback;
    for (int i = 0; i < 3; i++) unit[i] = (int32_t)tarn_round_shift_i64(unit[i], 14);
    return vec3_of(unit);
}

static void orbit_camera(const tarn_camera_path *p, uint32_t time_ms, tarn_camera *camera)
{
    const uint32_t phase = phase_q32(time_ms, p->period_ms);
    int32_t s, c;
    tarn_sin_cos_turns_q30(p->start_turns_q32 + (p->clockwise ? 0u - phase : phase), &s, &c);
    camera->position.x = tarn_sat_i64_to_i32((int64_t)p->centre.x + scale_q16(p->radius, s));
    camera->position.y = tarn_sat_i64_to_i32((int64_t)p->centre.y + p->height);
    camera->position.z = tarn_sat_i64_to_i32((int64_t)p->centre.z + scale_q16(p->radius, c));
    camera->target = p->target;
}

static void keyed_camera(const tarn_camera_path *p, uint32_t time_ms, tarn_camera *camera)
{
    int32_t v[TARN_KEY_CHANNELS_MAX];
    tarn__key_curve_at(&p->keys, time_ms, v);
    camera->position = vec3_of(v);
    camera->target = vec3_of(v + 3);
    if (p->keys.channels == 7u) camera->fov_y_degrees = tarn_clamp_i32(v[6], TARN_Q16_ONE, 179 * TARN_Q16_ONE);
}

static void pose_light(const tarn_light_motion *m, uint32_t time_ms, tarn_light *light)
{
    if (m->direction.key_count > 0u) {
        int32_t v[3];
        tarn__key_curve_at(&m->direction, time_ms, v);
        light->direction = unit_q16(v, &light->direction);
    }
    if (m->spin_period_ms > 0u) {
        int32_t r[3][3];
        axis_rotation_q30(&m->spin_axis, phase_q32(time_ms, m->spin_period_ms), r);
        light->direction = rotate_vec3(r, &light->direction);
    }
}

static void pose_object(const tarn_object_motion *m, uint32_t time_ms, tarn_object *o)
{
    if (m->path.key_count > 0u) {
        int32_t v[3];
        tarn__key_curve_at(&m->path, time_ms, v);
        o->position = vec3_of(v);
    }
    if (m->bob_period_ms > 0u) {
        int32_t s, c;
        tarn_sin_cos_turns_q30(phase_q32(time_ms, m->bob_period_ms) + m->bob_phase_q32, &s, &c);
        o->position.x = tarn_sat_i64_to_i32((int64_t)o->position.x + scale_q16(m->bob.x, s));
        o->position.y = tarn_sat_i64_to_i32((int64_t)o->position.y + scale_q16(m->bob.y, s));
        o->position.z = tarn_sat_i64_to_i32((int64_t)o->position.z + scale_q16(m->bob.z, s));
    }
    if (m->spin_period_ms > 0u) {
        int32_t r[3][3];
        axis_rotation_q30(&m->spin_axis, phase_q32(time_ms, m->spin_period_ms), r);
        for (int column = 0; column < 3; column++) {
            const tarn_vec3 base = {o->rotation[0][column], o->rotation[1][column], o->rotation[2][column]};
            const tarn_vec3 turned = rotate_vec3(r, &base);
            o->rotation[0][column] = turned.x;
            o->rotation[1][column] = turned.y;
            o->rotation[2][column] = turned.z;
        }
    }
    o->motion = NULL;
}

static int unit_axis(const tarn_vec3 *a)
{
    const int64_t length2 = (int64_t)a->x * a->x + (int64_t)a->y * a->y + (int64_t)a->z * a->z;
    const int64_t one = (int64_t)1 << 32, slack = (int64_t)1 << 20; /* |a| within 2^-12 of 1 */
    return length2 > one - slack && length2 < one + slack;
}

static int camera_path_valid(const tarn_camera_path *p)
{
    if (p->kind == TARN_CAMERA_ORBIT) return p->radius > 0 && p->period_ms > 0u;
    return p->kind == TARN_CAMERA_KEYS &&
           (tarn__key_curve_valid(&p->keys, 6u) || tarn__key_curve_valid(&p->keys, 7u));
}

static int object_motion_valid(const tarn_object *o)
{
    const tarn_object_motion *m = o->motion;
    if (o->static_vertices != NULL) return 0; /* they hold the object where it stood */
    if (m->spin_period_ms > 0u && !unit_axis(&m->spin_axis)) return 0;
    return m->path.key_count == 0u || tarn__key_curve_valid(&m->path, 3u);
}

static int light_motion_valid(const tarn_light_motion *m)
{
    if (m->spin_period_ms > 0u && !unit_axis(&m->spin_axis)) return 0;
    return m->direction.key_count == 0u || tarn__key_curve_valid(&m->direction, 3u);
}

int tarn__motion_valid(const tarn_scene *scene)
{
    if (scene->camera_path != NULL && !camera_path_valid(scene->camera_path)) return 0;
    if (scene->light_motion != NULL && !light_motion_valid(scene->light_motion)) return 0;
    for (uint32_t i = 0; i < scene->object_count; i++)
        if (scene->objects[i].motion != NULL && !object_motion_valid(&scene->objects[i])) return 0;
    return 1;
}

int tarn__view_moves(const tarn_scene *scene)
{
    return scene->camera_path != NULL || scene->light_motion != NULL;
}

int tarn__objects_move(const tarn_scene *scene)
{
    for (uint32_t i = 0; i < scene->object_count; i++)
        if (scene->objects[i].motion != NULL) return 1;
    return 0;
}

int tarn_scene_moves(const tarn_scene *scene)
{
    return scene != NULL && (tarn__view_moves(scene) || tarn__objects_move(scene));
}

void tarn__scene_pose(const tarn_scene *scene, uint32_t time_ms, tarn_scene *posed, tarn_object *objects)
{
    *posed = *scene;
    posed->camera_path = NULL;
    posed->light_motion = NULL;
    if (tarn__view_moves(scene)) posed->static_view = NULL; /* made for one camera and light */
    if (scene->camera_path != NULL) {
        if (scene->camera_path->kind == TARN_CAMERA_ORBIT) orbit_camera(scene->camera_path, time_ms, &posed->camera);
        else keyed_camera(scene->camera_path, time_ms, &posed->camera);
    }
    if (scene->light_motion != NULL) pose_light(scene->light_motion, time_ms, &posed->light);
    if (objects == NULL) return; /* the objects stay the scene's: none moves */
    for (uint32_t i = 0; i < scene->object_count; i++) {
        objects[i] = scene->objects[i];
        if (objects[i].motion != NULL) pose_object(objects[i].motion, time_ms, &objects[i]);
    }
    posed->objects = objects;
}
