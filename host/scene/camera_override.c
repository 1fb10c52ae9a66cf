/* camera_override.c: --camera (camera_override.h). */
#include "camera_override.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_gen.h"

/* The loader's bound on every number (scene_load.h): |v| < 32768. */
#define COORDINATE_LIMIT 32768.0

/* One number of the list and the separator after it: 0 with *end past it, or -1. */
static int read_number(const char *text, char separator, double min, double max, double *out, const char **end)
{
    char *after;
    *out = strtod(text, &after);
    if (after == text || !(*out > min && *out < max)) return -1;
    if (*after != separator) return -1;
    *end = separator ? after + 1 : after;
    return 0;
}

static int read_point(const char *text, char last, tarn_vec3 *out, const char **end)
{
    double v[3];
    if (read_number(text, ',', -COORDINATE_LIMIT, COORDINATE_LIMIT, &v[0], &text) ||
        read_number(text, ',', -COORDINATE_LIMIT, COORDINATE_LIMIT, &v[1], &text) ||
        read_number(text, last, -COORDINATE_LIMIT, COORDINATE_LIMIT, &v[2], end))
        return -1;
    out->x = tarn_q16_from_double(v[0]);
    out->y = tarn_q16_from_double(v[1]);
    out->z = tarn_q16_from_double(v[2]);
    return 0;
}

int tarn_camera_override_parse(const char *text, tarn_camera_override *out, tarn_error *err)
{
    const char *at = text ? text : "";
    memset(out, 0, sizeof *out);
    const char *colon = strchr(at, ':');
    const int has_fov = colon != NULL && strchr(colon + 1, ':') != NULL;
    double fov = 0;
    if (read_point(at, ':', &out->position, &at) || read_point(at, has_fov ? ':' : '\0', &out->target, &at) ||
        (has_fov && read_number(at, '\0', 1.0 - 1e-9, 179.0 + 1e-9, &fov, &at)))
        return tarn_fail(err, "--camera: expected X,Y,Z:TX,TY,TZ[:FOV] (world units each above -32768 and "
                         "below 32768, FOV degrees 1..179), got '%s'", text ? text : "");
    if (memcmp(&out->position, &out->target, sizeof out->position) == 0)
        return tarn_fail(err, "--camera: the position and the target are the same point");
    out->fov_y_degrees = has_fov ? tarn_q16_from_double(fov) : 0;
    out->given = 1;
    return 0;
}

void tarn_camera_override_apply(const tarn_camera_override *camera, tarn_scene *scene)
{
    if (!camera->given) return;
    scene->camera.position = camera->position;
    scene->camera.target = camera->target;
    if (camera->fov_y_degrees) scene->camera.fov_y_degrees = camera->fov_y_degrees;
    scene->camera_path = NULL;
}

/* A Q16.16 value's exact decimal: the fraction f / 65536 is f * 5^16 / 10^16, so
 * 16 digits hold it whole; trailing zeros are dropped. */
static void q16_text(tarn_q16 v, char *out, size_t size)
{
    const uint32_t magnitude = v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
    const unsigned long long fraction = (unsigned long long)(magnitude & 0xffffu) * 152587890625ull;
    int length = snprintf(out, size, "%s%lu.%016llu", v < 0 ? "-" : "", (unsigned long)(magnitude >> 16), fraction);
    if (length < 0 || (size_t)length >= size) return;
    while (out[length - 1] == '0') out[--length] = '\0';
    if (out[length - 1] == '.') out[length - 1] = '\0';
}

void tarn_camera_override_text(const tarn_camera *camera, char *out, size_t size)
{
    const tarn_q16 values[7] = {camera->position.x, camera->position.y, camera->position.z, camera->target.x,
                                camera->target.y,   camera->target.z,   camera->fov_y_degrees};
    static const char separators[7] = {',', ',', ':', ',', ',', ':', '\0'};
    size_t used = 0;
    out[0] = '\0';
    for (int k = 0; k < 7 && used < size; k++) {
        char number[32];
        q16_text(values[k], number, sizeof number);
        int written = snprintf(out + used, size - used, "%s%.1s", number, &separators[k]);
        if (written < 0) return;
        used += (size_t)written;
    }
}
