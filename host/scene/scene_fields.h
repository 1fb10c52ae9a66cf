/* scene_fields.h: the readers of a scene file's fields, shared by the loader's parts
 * (scene_load.c, water_load.c, scene_textures.c).
 *
 * Each reads `key` of the JSON `object`, whose field path is `parent` ("" at the top
 * level, "materials.NAME"...), and returns 0, or -1 with the one-line error
 * "file: parent.key: what was expected, got what" set. They know the file being
 * read (its name for messages, its directory for asset paths) and nothing of the
 * scene it fills, so the loader's parts call them and they call none of those. */
#ifndef TARN_HOST_SCENE_FIELDS_H
#define TARN_HOST_SCENE_FIELDS_H

#include <stddef.h>
#include <stdint.h>
#include <jansson.h>
#include "error.h"
#include "tarn/tarn_scene.h"

struct tarn_loaded_scene;

/* One scene file being loaded. */
typedef struct tarn_loader {
    const char *file; /* the scene path as given: every message starts with it */
    char *dir;        /* its directory with a trailing '/', or "" */
    tarn_error *err;
    struct tarn_loaded_scene *out; /* what the loader fills (scene_load.h); no reader here
                                      touches it */
} tarn_loader;

#define TARN_FIELD_PATH_MAX 256

enum { TARN_MIN_OPEN = 1, TARN_MAX_OPEN = 2, TARN_INTEGER = 4 };

/* A number field's range, and how messages describe it ("expected <what>"). */
typedef struct {
    const char *what;
    double min, max;
    unsigned flags; /* TARN_MIN_OPEN, TARN_MAX_OPEN, TARN_INTEGER */
} tarn_rule;

extern const tarn_rule TARN_COORDINATE; /* |v| < 32768: anything Q16.16 holds */
extern const tarn_rule TARN_POSITIVE;   /* 0 < v < 32768, and not 0 once in Q16.16 */
extern const tarn_rule TARN_FOV;        /* degrees, 1..179 */

/* "file: field: message"; always -1. */
int tarn_fail_field(tarn_loader *l, const char *field, const char *format, ...)
    __attribute__((format(printf, 3, 4)));
/* "parent.key" (or "key" at the top level), cut with "..." if too long. */
void tarn_join_path(char out[TARN_FIELD_PATH_MAX], const char *parent, const char *key);
/* "object", "array", "string", "number", "boolean" or "null". */
const char *tarn_json_type(const json_t *v);

/* Optional fields take the fallback when absent; a NULL fallback makes them required. */
int tarn_get_number(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                    const tarn_rule *rule, const double *fallback, double *out);
/* An array of exactly `n` numbers, each following `rule`. */
int tarn_get_numbers(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                     size_t n, const tarn_rule *rule, const double *fallback, double *out);
/* [x, y, z], each TARN_COORDINATE. */
int tarn_get_vec3(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                  const double *fallback, double out[3]);
/* Rounded to Q16.16. */
tarn_vec3 tarn_vec3_q16(const double v[3]);
/* A string; *out stays NULL when absent and optional. `what` describes it. */
int tarn_get_string(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                    const char *what, int required, const char **out);
/* "#rrggbb" -> 0xRRGGBB, `fallback` when absent. */
int tarn_get_colour(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                    uint32_t fallback, uint32_t *out);
int tarn_get_bool(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                  int fallback, int *out);
/* A nested object; *out stays NULL when absent and optional. `what` describes it. */
int tarn_get_object(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                    const char *what, int required, json_t **out);
/* Every key of `object` must be in `common` or `specific` (NULL-terminated, either may
 * be NULL); `kind` (may be "") names the object in the message: " for a sphere". */
int tarn_check_fields(tarn_loader *l, const json_t *object, const char *parent,
                      const char *const *common, const char *const *specific, const char *kind);
/* A required, non-empty file name, resolved against the scene's directory (absolute
 * paths stay); the caller frees *out. `what` describes it. */
int tarn_get_asset_path(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                        const char *what, char **out);

#endif
