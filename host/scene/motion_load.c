/* motion_load.c: camera paths, light and object motion from a scene file
 * (motion_load.h). Numbers become the core's: milliseconds as integers, angles as
 * Q0.32 turns, axes as Q16.16 unit vectors, keys as Q16.16 values. */
#include "motion_load.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_gen.h"

static const tarn_rule PERIOD = { "a whole number of milliseconds, 1..2147483647", 1, 2147483647.0, TARN_INTEGER };
static const tarn_rule KEY_TIME = { "a whole number of milliseconds, 0..4294967295", 0, 4294967295.0, TARN_INTEGER };
static const tarn_rule LOOP = { "a whole number of milliseconds, 0 (no loop)..4294967295", 0, 4294967295.0,
                                TARN_INTEGER };
static const tarn_rule DEGREES = { "a number of degrees, -360..360", -360, 360, 0 };

/* Degrees to Q0.32 turns, wrapped. */
static uint32_t turns_q32(double degrees)
{
    double turns = degrees / 360.0;
    turns -= floor(turns);
    return (uint32_t)(uint64_t)llround(turns * 4294967296.0);
}

/* A required non-zero vector `key` of `parent`, as a Q16.16 unit vector. */
static int get_axis(tarn_loader *l, const json_t *object, const char *parent, const char *key, tarn_vec3 *out)
{
    double v[3];
    if (tarn_get_vec3(l, object, parent, key, NULL, v)) return -1;
    const double length = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(length > 1e-9)) {
        char field[TARN_FIELD_PATH_MAX];
        tarn_join_path(field, parent, key);
        return tarn_fail_field(l, field, "expected a non-zero vector, got [%g, %g, %g]", v[0], v[1], v[2]);
    }
    const double unit[3] = { v[0] / length, v[1] / length, v[2] / length };
    *out = tarn_vec3_q16(unit);
    return 0;
}

static int get_period(tarn_loader *l, const json_t *object, const char *parent, uint32_t *out)
{
    double period;
    if (tarn_get_number(l, object, parent, "period", &PERIOD, NULL, &period)) return -1;
    *out = (uint32_t)period;
    return 0;
}

/* ---- keys ------------------------------------------------------------------- */

/* What a key holds: its time, then three channels for each vector field, then
 * perhaps a field of view. */
typedef struct {
    const char *const *fields;       /* allowed fields, NULL-terminated */
    const char *const *vectors;      /* the vector fields, in channel order, NULL-terminated */
    int with_fov;                    /* a "fov" channel after them, in every key or none */
} key_format;

static int load_key(tarn_loader *l, const json_t *key, const char *field, const key_format *f, int fov_expected,
                    uint32_t *time, tarn_q16 *values)
{
    double t;
    if (!json_is_object(key)) return tarn_fail_field(l, field, "expected an object {\"time\"...}, got %s", tarn_json_type(key));
    if (tarn_check_fields(l, key, field, f->fields, NULL, "") ||
        tarn_get_number(l, key, field, "time", &KEY_TIME, NULL, &t))
        return -1;
    *time = (uint32_t)t;
    size_t channel = 0;
    for (const char *const *name = f->vectors; *name != NULL; name++, channel += 3) {
        double v[3];
        if (tarn_get_vec3(l, key, field, *name, NULL, v)) return -1;
        const tarn_vec3 q = tarn_vec3_q16(v);
        values[channel] = q.x;
        values[channel + 1] = q.y;
        values[channel + 2] = q.z;
    }
    if (!f->with_fov) return 0;
    const int has_fov = json_object_get(key, "fov") != NULL;
    if (has_fov != fov_expected) {
        return tarn_fail_field(l, field, "%s \"fov\": give it in every key or in none",
                               has_fov ? "has" : "lacks");
    }
    double fov;
    if (has_fov && tarn_get_number(l, key, field, "fov", &TARN_FOV, NULL, &fov)) return -1;
    if (has_fov) values[channel] = tarn_q16_from_double(fov);
    return 0;
}

static int check_key_times(tarn_loader *l, const char *field, const tarn_key_curve *c)
{
    char key_field[TARN_FIELD_PATH_MAX + 32];
    for (uint32_t i = 1; i < c->key_count; i++) {
        if (c->times_ms[i] <= c->times_ms[i - 1]) {
            snprintf(key_field, sizeof key_field, "%s.keys[%u].time", field, i);
            return tarn_fail_field(l, key_field, "expected a time after the key before's (%u ms), got %u",
                                   c->times_ms[i - 1], c->times_ms[i]);
        }
    }
    if (c->loop_ms != 0u && c->times_ms[c->key_count - 1] >= c->loop_ms) {
        snprintf(key_field, sizeof key_field, "%s.loop", field);
        return tarn_fail_field(l, key_field, "expected a period after the last key's time (%u ms), got %u",
                               c->times_ms[c->key_count - 1], c->loop_ms);
    }
    return 0;
}

/* `path` = {"keys": [...], "loop": ms} at `field` into a curve of the format's keys. */
static int load_keys(tarn_loader *l, const json_t *path, const char *field, const key_format *f, tarn_key_curve *out)
{
    static const char *const fields[] = { "keys", "loop", NULL };
    const json_t *keys = json_object_get(path, "keys");
    double loop;
    if (tarn_check_fields(l, path, field, fields, NULL, "") ||
        tarn_get_number(l, path, field, "loop", &LOOP, &(double){0}, &loop))
        return -1;
    const size_t n = json_array_size(keys);
    if (!json_is_array(keys) || n < 1 || n > TARN_KEYS_MAX) {
        char keys_field[TARN_FIELD_PATH_MAX + 8];
        snprintf(keys_field, sizeof keys_field, "%s.keys", field);
        return tarn_fail_field(l, keys_field, "expected an array of 1..%u keys, got %s", TARN_KEYS_MAX,
                               json_is_array(keys) ? "none" : (keys ? tarn_json_type(keys) : "nothing"));
    }
    size_t channels = 0;
    for (const char *const *name = f->vectors; *name != NULL; name++) channels += 3;
    const int with_fov = f->with_fov && json_object_get(json_array_get(keys, 0), "fov") != NULL;
    channels += (size_t)with_fov;
    uint32_t *times = calloc(n, sizeof *times);
    tarn_q16 *values = calloc(n * channels, sizeof *values);
    out->times_ms = times;
    out->values = values;
    if (!times || !values) return tarn_fail(l->err, "%s: out of memory", l->file);
    out->key_count = (uint16_t)n;
    out->channels = (uint8_t)channels;
    out->loop_ms = (uint32_t)loop;
    for (size_t i = 0; i < n; i++) {
        char key_field[TARN_FIELD_PATH_MAX + 32];
        snprintf(key_field, sizeof key_field, "%s.keys[%zu]", field, i);
        if (load_key(l, json_array_get(keys, i), key_field, f, with_fov, &times[i], &values[i * channels]))
            return -1;
    }
    return check_key_times(l, field, out);
}

void tarn_key_curve_free(tarn_key_curve *curve)
{
    free((void *)curve->times_ms);
    free((void *)curve->values);
    memset(curve, 0, sizeof *curve);
}

/* ---- camera ----------------------------------------------------------------- */

static int load_orbit(tarn_loader *l, const json_t *orbit, const char *field, tarn_camera_path *out)
{
    static const char *const fields[] = { "centre", "radius", "height", "period", "start", "direction",
                                          "target", NULL };
    double centre[3], target[3], radius, height, start;
    const char *direction;
    if (tarn_check_fields(l, orbit, field, fields, NULL, "") ||
        tarn_get_vec3(l, orbit, field, "centre", NULL, centre) ||
        tarn_get_number(l, orbit, field, "radius", &TARN_POSITIVE, NULL, &radius) ||
        tarn_get_number(l, orbit, field, "height", &TARN_COORDINATE, &(double){0}, &height) ||
        get_period(l, orbit, field, &out->period_ms) ||
        tarn_get_number(l, orbit, field, "start", &DEGREES, &(double){0}, &start) ||
        tarn_get_vec3(l, orbit, field, "target", centre, target) ||
        tarn_get_string(l, orbit, field, "direction", "\"counterclockwise\" or \"clockwise\"", 0, &direction))
        return -1;
    char sub[TARN_FIELD_PATH_MAX];
    if (direction != NULL && strcmp(direction, "counterclockwise") != 0 && strcmp(direction, "clockwise") != 0) {
        tarn_join_path(sub, field, "direction");
        return tarn_fail_field(l, sub, "expected \"counterclockwise\" or \"clockwise\", got \"%s\"", direction);
    }
    out->kind = TARN_CAMERA_ORBIT;
    out->centre = tarn_vec3_q16(centre);
    out->radius = tarn_q16_from_double(radius);
    out->height = tarn_q16_from_double(height);
    out->start_turns_q32 = turns_q32(start);
    out->clockwise = direction != NULL && strcmp(direction, "clockwise") == 0;
    out->target = tarn_vec3_q16(target);
    const double dx = target[0] - centre[0], dz = target[2] - centre[2];
    if (target[1] == centre[1] + height && fabs(sqrt(dx * dx + dz * dz) - radius) < 1.0 / 65536) {
        tarn_join_path(sub, field, "target");
        return tarn_fail_field(l, sub, "lies on the orbit, where the camera would stand on it");
    }
    return 0;
}

static int check_camera_keys(tarn_loader *l, const char *field, const tarn_key_curve *c)
{
    for (uint32_t i = 0; i < c->key_count; i++) {
        const tarn_q16 *v = &c->values[i * c->channels];
        if (v[0] == v[3] && v[1] == v[4] && v[2] == v[5]) {
            char key_field[TARN_FIELD_PATH_MAX + 32];
            snprintf(key_field, sizeof key_field, "%s.keys[%u].target", field, i);
            return tarn_fail_field(l, key_field, "must differ from the key's position");
        }
    }
    return 0;
}

int tarn_camera_path_load(tarn_loader *l, const json_t *camera, tarn_camera_path *out, int *present)
{
    static const char *const fields[] = { "orbit", "keys", "loop", NULL };
    static const char *const key_fields[] = { "time", "position", "target", "fov", NULL };
    static const char *const key_vectors[] = { "position", "target", NULL };
    static const key_format format = { key_fields, key_vectors, 1 };
    json_t *path, *orbit;
    *present = 0;
    if (tarn_get_object(l, camera, "camera", "path", "an object {\"orbit\"} or {\"keys\", \"loop\"}", 0, &path))
        return -1;
    if (path == NULL) return 0;
    *present = 1;
    if (tarn_check_fields(l, path, "camera.path", fields, NULL, "") ||
        tarn_get_object(l, path, "camera.path", "orbit", "an object {\"centre\", \"radius\"...}", 0, &orbit))
        return -1;
    const int keyed = json_object_get(path, "keys") != NULL;
    if ((orbit != NULL) == keyed)
        return tarn_fail_field(l, "camera.path", "expected either \"orbit\" or \"keys\", not %s",
                               keyed ? "both" : "neither");
    if (orbit != NULL) {
        if (json_object_get(path, "loop") != NULL)
            return tarn_fail_field(l, "camera.path.loop", "belongs with \"keys\"; an orbit repeats every period");
        return load_orbit(l, orbit, "camera.path.orbit", out);
    }
    out->kind = TARN_CAMERA_KEYS;
    return load_keys(l, path, "camera.path", &format, &out->keys) || check_camera_keys(l, "camera.path", &out->keys);
}

/* ---- spin, light and objects -------------------------------------------------- */

static int load_spin(tarn_loader *l, const json_t *motion, const char *parent, tarn_vec3 *axis, uint32_t *period)
{
    static const char *const fields[] = { "axis", "period", NULL };
    json_t *spin;
    char field[TARN_FIELD_PATH_MAX];
    tarn_join_path(field, parent, "spin");
    if (tarn_get_object(l, motion, parent, "spin", "an object {\"axis\", \"period\"}", 0, &spin)) return -1;
    if (spin == NULL) return 0;
    return tarn_check_fields(l, spin, field, fields, NULL, "") || get_axis(l, spin, field, "axis", axis) ||
           get_period(l, spin, field, period);
}

static int load_path(tarn_loader *l, const json_t *motion, const char *parent, const key_format *format,
                     tarn_key_curve *out)
{
    json_t *path;
    char field[TARN_FIELD_PATH_MAX];
    tarn_join_path(field, parent, "path");
    if (tarn_get_object(l, motion, parent, "path", "an object {\"keys\", \"loop\"}", 0, &path)) return -1;
    return path == NULL ? 0 : load_keys(l, path, field, format, out);
}

int tarn_light_motion_load(tarn_loader *l, const json_t *light, tarn_light_motion *out, int *present)
{
    static const char *const fields[] = { "spin", "path", NULL };
    static const char *const key_fields[] = { "time", "direction", NULL };
    static const char *const key_vectors[] = { "direction", NULL };
    static const key_format format = { key_fields, key_vectors, 0 };
    json_t *motion;
    *present = 0;
    if (tarn_get_object(l, light, "light", "motion", "an object {\"spin\", \"path\"}", 0, &motion)) return -1;
    if (motion == NULL) return 0;
    *present = 1;
    if (tarn_check_fields(l, motion, "light.motion", fields, NULL, "") ||
        load_spin(l, motion, "light.motion", &out->spin_axis, &out->spin_period_ms) ||
        load_path(l, motion, "light.motion", &format, &out->direction))
        return -1;
    for (uint32_t i = 0; i < out->direction.key_count; i++) {
        const tarn_q16 *v = &out->direction.values[3 * i];
        if (v[0] == 0 && v[1] == 0 && v[2] == 0) {
            char field[TARN_FIELD_PATH_MAX + 32];
            snprintf(field, sizeof field, "light.motion.path.keys[%u].direction", i);
            return tarn_fail_field(l, field, "expected a non-zero vector");
        }
    }
    return 0;
}

static int load_bob(tarn_loader *l, const json_t *motion, const char *parent, tarn_object_motion *out)
{
    static const char *const fields[] = { "axis", "amplitude", "period", "phase", NULL };
    json_t *bob;
    char field[TARN_FIELD_PATH_MAX];
    tarn_join_path(field, parent, "bob");
    if (tarn_get_object(l, motion, parent, "bob", "an object {\"axis\", \"amplitude\", \"period\"}", 0, &bob))
        return -1;
    if (bob == NULL) return 0;
    tarn_vec3 axis;
    double amplitude, phase;
    if (tarn_check_fields(l, bob, field, fields, NULL, "") || get_axis(l, bob, field, "axis", &axis) ||
        tarn_get_number(l, bob, field, "amplitude", &TARN_COORDINATE, NULL, &amplitude) ||
        get_period(l, bob, field, &out->bob_period_ms) ||
        tarn_get_number(l, bob, field, "phase", &DEGREES, &(double){0}, &phase))
        return -1;
    const double crest[3] = { axis.x / 65536.0 * amplitude, axis.y / 65536.0 * amplitude,
                              axis.z / 65536.0 * amplitude };
    out->bob = tarn_vec3_q16(crest);
    out->bob_phase_q32 = turns_q32(phase);
    return 0;
}

int tarn_object_motion_load(tarn_loader *l, const json_t *object, const char *field, tarn_object_motion *out,
                            int *present)
{
    static const char *const fields[] = { "bob", "spin", "path", NULL };
    static const char *const key_fields[] = { "time", "position", NULL };
    static const char *const key_vectors[] = { "position", NULL };
    static const key_format format = { key_fields, key_vectors, 0 };
    json_t *motion;
    char motion_field[TARN_FIELD_PATH_MAX];
    tarn_join_path(motion_field, field, "motion");
    *present = 0;
    if (tarn_get_object(l, object, field, "motion", "an object {\"bob\", \"spin\", \"path\"}", 0, &motion))
        return -1;
    if (motion == NULL) return 0;
    *present = 1;
    return tarn_check_fields(l, motion, motion_field, fields, NULL, "") || load_bob(l, motion, motion_field, out) ||
           load_spin(l, motion, motion_field, &out->spin_axis, &out->spin_period_ms) ||
           load_path(l, motion, motion_field, &format, &out->path);
}
