/* scene_fields.c: the readers of a scene file's fields (scene_fields.h). */
#include "scene_fields.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_gen.h"

int tarn_fail_field(tarn_loader *l, const char *field, const char *format, ...)
{
    char message[sizeof l->err->message];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    return tarn_fail(l->err, "%s: %s: %s", l->file, field, message);
}

void tarn_join_path(char out[TARN_FIELD_PATH_MAX], const char *parent, const char *key)
{
    int length = snprintf(out, TARN_FIELD_PATH_MAX, "%s%s%s", parent, parent[0] ? "." : "", key);
    /* only absurdly long material names get here; say the path was cut */
    if (length >= TARN_FIELD_PATH_MAX) memcpy(out + TARN_FIELD_PATH_MAX - 4, "...", 4);
}

const char *tarn_json_type(const json_t *v)
{
    switch (json_typeof(v)) {
    case JSON_OBJECT: return "object";
    case JSON_ARRAY: return "array";
    case JSON_STRING: return "string";
    case JSON_INTEGER:
    case JSON_REAL: return "number";
    case JSON_TRUE:
    case JSON_FALSE: return "boolean";
    default: return "null";
    }
}

/* ---- field rules ------------------------------------------------------------ */

/* Q16.16 holds |v| < 32768: the widest any field may be. */
const tarn_rule TARN_COORDINATE = { "a number, -32768 < v < 32768", -32768, 32768,
                                    TARN_MIN_OPEN | TARN_MAX_OPEN };
const tarn_rule TARN_POSITIVE = { "a number > 0 and < 32768", 0, 32768,
                                  TARN_MIN_OPEN | TARN_MAX_OPEN };
const tarn_rule TARN_FOV = { "a number of degrees, 1..179", 1, 179, 0 };

static int number_fits(const tarn_rule *rule, double v)
{
    if (!isfinite(v) || v < rule->min || v > rule->max) return 0;
    if ((rule->flags & TARN_MIN_OPEN) && v == rule->min) return 0;
    if ((rule->flags & TARN_MAX_OPEN) && v == rule->max) return 0;
    if ((rule->flags & TARN_INTEGER) && v != floor(v)) return 0;
    return 1;
}

static int read_number(tarn_loader *l, const json_t *value, const char *field,
                       const tarn_rule *rule, double *out)
{
    if (!json_is_number(value)) {
        return tarn_fail_field(l, field, "expected a number, got %s", tarn_json_type(value));
    }
    double v = json_number_value(value);
    if (!number_fits(rule, v)) {
        return tarn_fail_field(l, field, "expected %s, got %g", rule->what, v);
    }
    /* "> 0" must still hold once rounded to Q16.16 */
    if ((rule->flags & TARN_MIN_OPEN) && rule->min == 0 && tarn_q16_from_double(v) <= 0) {
        return tarn_fail_field(l, field, "expected %s, got %g (0 in Q16.16)", rule->what, v);
    }
    *out = v;
    return 0;
}

/* `key` of `object` (at `parent`): the rule's number, `fallback` when absent, or
 * an error when absent and fallback is NULL. */
int tarn_get_number(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                    const tarn_rule *rule, const double *fallback, double *out)
{
    char field[TARN_FIELD_PATH_MAX];
    tarn_join_path(field, parent, key);
    const json_t *value = json_object_get(object, key);
    if (value) return read_number(l, value, field, rule, out);
    if (!fallback) return tarn_fail_field(l, field, "missing (expected %s)", rule->what);
    *out = *fallback;
    return 0;
}

/* An array of exactly `n` numbers, each following `rule`. */
int tarn_get_numbers(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                     size_t n, const tarn_rule *rule, const double *fallback, double *out)
{
    char field[TARN_FIELD_PATH_MAX];
    tarn_join_path(field, parent, key);
    const json_t *value = json_object_get(object, key);
    if (!value) {
        if (!fallback) {
            return tarn_fail_field(l, field, "missing (expected an array of %zu numbers)", n);
        }
        memcpy(out, fallback, n * sizeof *out);
        return 0;
    }
    if (!json_is_array(value)) {
        return tarn_fail_field(l, field, "expected an array of %zu numbers, got %s", n,
                               tarn_json_type(value));
    }
    if (json_array_size(value) != n) {
        return tarn_fail_field(l, field, "expected an array of %zu numbers, got %zu", n,
                               json_array_size(value));
    }
    for (size_t k = 0; k < n; k++) {
        char element[TARN_FIELD_PATH_MAX + 24]; /* room for "[index]" */
        snprintf(element, sizeof element, "%s[%zu]", field, k);
        if (read_number(l, json_array_get(value, k), element, rule, &out[k])) return -1;
    }
    return 0;
}

/* A string field; *out stays NULL when absent and optional. */
int tarn_get_string(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                     const char *what, int required, const char **out)
{
    char field[TARN_FIELD_PATH_MAX];
    tarn_join_path(field, parent, key);
    const json_t *value = json_object_get(object, key);
    *out = NULL;
    if (!value) return required ? tarn_fail_field(l, field, "missing (expected %s)", what) : 0;
    if (!json_is_string(value)) {
        return tarn_fail_field(l, field, "expected %s, got %s", what, tarn_json_type(value));
    }
    *out = json_string_value(value);
    return 0;
}

static int hex_digit(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* "#rrggbb" -> 0xRRGGBB */
int tarn_get_colour(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                    uint32_t fallback, uint32_t *out)
{
    static const char what[] = "a colour \"#rrggbb\"";
    const char *text;
    if (tarn_get_string(l, object, parent, key, what, 0, &text)) return -1;
    *out = fallback;
    if (!text) return 0;
    uint32_t rgb = 0;
    int ok = strlen(text) == 7 && text[0] == '#';
    for (int k = 1; ok && k < 7; k++) {
        int digit = hex_digit(text[k]);
        ok = digit >= 0;
        rgb = rgb << 4 | (uint32_t)(digit & 15);
    }
    if (!ok) {
        char field[TARN_FIELD_PATH_MAX];
        tarn_join_path(field, parent, key);
        return tarn_fail_field(l, field, "expected %s, got \"%s\"", what, text);
    }
    *out = rgb;
    return 0;
}

int tarn_get_bool(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                  int fallback, int *out)
{
    const json_t *value = json_object_get(object, key);
    *out = fallback;
    if (!value) return 0;
    if (!json_is_boolean(value)) {
        char field[TARN_FIELD_PATH_MAX];
        tarn_join_path(field, parent, key);
        return tarn_fail_field(l, field, "expected true or false, got %s", tarn_json_type(value));
    }
    *out = json_is_true(value);
    return 0;
}

/* A nested object; *out stays NULL when absent and optional. */
int tarn_get_object(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                    const char *what, int required, json_t **out)
{
    char field[TARN_FIELD_PATH_MAX];
    tarn_join_path(field, parent, key);
    json_t *value = json_object_get(object, key);
    *out = NULL;
    if (!value) return required ? tarn_fail_field(l, field, "missing (expected %s)", what) : 0;
    if (!json_is_object(value)) {
        return tarn_fail_field(l, field, "expected %s, got %s", what, tarn_json_type(value));
    }
    *out = value;
    return 0;
}

static int name_in(const char *name, const char *const *names)
{
    for (; names && *names; names++) {
        if (strcmp(name, *names) == 0) return 1;
    }
    return 0;
}

static void append_names(char *out, size_t size, const char *const *names)
{
    for (; names && *names; names++) {
        size_t used = strlen(out);
        snprintf(out + used, size - used, "%s%s", used ? ", " : "", *names);
    }
}

/* Every key of `object` must be in `common` or `specific` (NULL-terminated lists).
 * `kind` (may be "") says what the object is in the message: " for a sphere". */
int tarn_check_fields(tarn_loader *l, const json_t *object, const char *parent,
                      const char *const *common, const char *const *specific, const char *kind)
{
    const char *key;
    const json_t *value;
    json_object_foreach((json_t *)object, key, value) {
        if (name_in(key, common) || name_in(key, specific)) continue;
        char field[TARN_FIELD_PATH_MAX], allowed[256] = "";
        tarn_join_path(field, parent, key);
        append_names(allowed, sizeof allowed, common);
        append_names(allowed, sizeof allowed, specific);
        return tarn_fail_field(l, field, "unknown field%s (expected %s)", kind, allowed);
    }
    return 0;
}

/* An asset path relative to the scene file's directory (absolute paths stay). */
static char *resolve_asset(const tarn_loader *l, const char *name)
{
    const char *dir = name[0] == '/' ? "" : l->dir;
    size_t size = strlen(dir) + strlen(name) + 1;
    char *path = malloc(size);
    if (path) snprintf(path, size, "%s%s", dir, name);
    return path;
}

/* A file-name field, resolved; the caller frees *out. */
int tarn_get_asset_path(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                        const char *what, char **out)
{
    const char *name;
    *out = NULL;
    if (tarn_get_string(l, object, parent, key, what, 1, &name)) return -1;
    if (name[0] == '\0') {
        char field[TARN_FIELD_PATH_MAX];
        tarn_join_path(field, parent, key);
        return tarn_fail_field(l, field, "expected %s, got \"\"", what);
    }
    *out = resolve_asset(l, name);
    return *out ? 0 : tarn_fail(l->err, "%s: out of memory", l->file);
}

int tarn_get_vec3(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                  const double *fallback, double out[3])
{
    return tarn_get_numbers(l, object, parent, key, 3, &TARN_COORDINATE, fallback, out);
}

tarn_vec3 tarn_vec3_q16(const double v[3])
{
    tarn_vec3 q = { tarn_q16_from_double(v[0]), tarn_q16_from_double(v[1]),
                    tarn_q16_from_double(v[2]) };
    return q;
}
