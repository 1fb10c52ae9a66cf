#include "water_load.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mesh_gen.h"
#include "scene_textures.h"

static const tarn_rule UNIT = { "a number 0..1", 0, 1, 0 };
static const tarn_rule DENSITY = { "a number 0..64", 0, 64, 0 };
static const tarn_rule SPEED = { "a number -16..16", -16, 16, 0 };
static const tarn_rule NORMAL_STRENGTH = { "a number 0..8", 0, 8, 0 };
static const tarn_rule SPECULAR_INTENSITY = { "a number 0..4", 0, 4, 0 };
static const tarn_rule SPECULAR_POWER = { "an integer 1..256", 1, 256, TARN_INTEGER };
static const tarn_rule FOAM_LINES = { "an integer 0..16", 0, 16, TARN_INTEGER };

static const char PANNING_WHAT[] = "an object {\"image\", \"scale\", \"speed\"}";

/* One water block being read. */
typedef struct {
    tarn_loader *l;
    const json_t *block;   /* the "water" object */
    const char *field;     /* its path: "materials.NAME.water" */
    uint16_t frame_width;
    tarn_water *out;
} water_reader;

/* The value of every absent optional field. A feature that is off keeps them too,
 * so each field stays in its range whatever the flags (the core checks some, such
 * as specular_power, regardless). */
#define STILL_PANNING { .scale = TARN_Q16_ONE, .speed_u = 0, .speed_v = 0 }
static const tarn_water WATER_DEFAULTS = {
    .albedo_rgb = 0xFFFFFF,
    .normal_strength = TARN_Q16_ONE,
    .pan_a = STILL_PANNING,
    .pan_b = STILL_PANNING,
    .specular = TARN_Q16_ONE,
    .specular_power = 32,
    .foam_pan = STILL_PANNING,
    .foam_rgb = 0xFFFFFF,
    .foam_opacity = TARN_Q16_ONE,
    .sparkle_rgb = 0xFFFFFF,
};

/* ---- shared pieces --------------------------------------------------------------- */

/* Colours have a fallback in the common reader; a required one is checked here. */
static int required_colour(tarn_loader *l, const json_t *object, const char *parent,
                           const char *key, uint32_t *out)
{
    if (!json_object_get(object, key)) {
        char field[TARN_FIELD_PATH_MAX];
        tarn_join_path(field, parent, key);
        return tarn_fail_field(l, field, "missing (expected a colour \"#rrggbb\")");
    }
    return tarn_get_colour(l, object, parent, key, 0, out);
}

enum { OPTIONAL = 0, REQUIRED = 1 };

/* A number field straight to Q16.16. An absent optional one keeps *inout: every
 * default is in WATER_DEFAULTS (or the underwater one), nowhere else. */
static int get_q16(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                   const tarn_rule *rule, int required, tarn_q16 *inout)
{
    const double current = *inout / 65536.0; /* exact: a double holds any Q16.16 */
    double v;
    if (tarn_get_number(l, object, parent, key, rule, required ? NULL : &current, &v)) return -1;
    *inout = tarn_q16_from_double(v);
    return 0;
}

/* A whole-number field, also keeping *inout when absent. */
static int get_whole(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                     const tarn_rule *rule, unsigned *inout)
{
    const double current = *inout;
    double v;
    if (tarn_get_number(l, object, parent, key, rule, &current, &v)) return -1;
    *inout = (unsigned)v;
    return 0;
}

/* "scale" and "speed" [u, v] of a panning texture, each keeping *out when absent. */
static int get_panning(tarn_loader *l, const json_t *object, const char *parent,
                       tarn_panning *out)
{
    const double still[2] = { out->speed_u / 65536.0, out->speed_v / 65536.0 };
    double speed[2];
    if (get_q16(l, object, parent, "scale", &TARN_POSITIVE, OPTIONAL, &out->scale) ||
        tarn_get_numbers(l, object, parent, "speed", 2, &SPEED, still, speed)) {
        return -1;
    }
    out->speed_u = tarn_q16_from_double(speed[0]);
    out->speed_v = tarn_q16_from_double(speed[1]);
    return 0;
}

/* {"image", "scale", "speed"}, the object itself at `field`. */
static int get_panned_map(tarn_loader *l, const json_t *map, const char *field,
                          const tarn_texture **texture, tarn_panning *pan)
{
    static const char *const fields[] = { "image", "scale", "speed", NULL };
    if (!json_is_object(map)) {
        return tarn_fail_field(l, field, "expected %s, got %s", PANNING_WHAT,
                               tarn_json_type(map));
    }
    if (tarn_check_fields(l, map, field, fields, NULL, "") ||
        tarn_get_texture(l, map, field, "image", texture) ||
        get_panning(l, map, field, pan)) {
        return -1;
    }
    return 0;
}

/* The feature's required sub-object `key` of the water block, checked against `fields`. */
static int feature_object(water_reader *w, const char *key, const char *what,
                          const char *const *fields, json_t **object, char *field)
{
    tarn_join_path(field, w->field, key);
    if (tarn_get_object(w->l, w->block, w->field, key, what, 1, object)) return -1;
    return tarn_check_fields(w->l, *object, field, fields, NULL, "");
}

/* Refraction and sparkles read the normal maps, which come first in FEATURES. */
static int needs_normals(water_reader *w, const char *key, const char *why)
{
    if (w->out->features & TARN_WATER_NORMALS) return 0;
    char field[TARN_FIELD_PATH_MAX];
    tarn_join_path(field, w->field, key);
    return tarn_fail_field(w->l, field, "needs normal_maps (%s)", why);
}

/* ---- features, each present exactly when its flag is set ---------------------- */

static int read_fog(water_reader *w)
{
    static const char *const fields[] = { "colour", "density", NULL };
    char field[TARN_FIELD_PATH_MAX];
    json_t *fog;
    if (feature_object(w, "fog", "an object {\"colour\", \"density\"}", fields, &fog, field) ||
        required_colour(w->l, fog, field, "colour", &w->out->fog_rgb) ||
        get_q16(w->l, fog, field, "density", &DENSITY, REQUIRED, &w->out->fog_density)) {
        return -1;
    }
    return 0;
}

static int read_absorption(water_reader *w)
{
    static const char *const fields[] = { "colour", "strength", "squared", NULL };
    char field[TARN_FIELD_PATH_MAX];
    json_t *a;
    int squared;
    if (feature_object(w, "absorption", "an object {\"colour\", \"strength\", \"squared\"}",
                       fields, &a, field) ||
        required_colour(w->l, a, field, "colour", &w->out->absorb_rgb) ||
        get_q16(w->l, a, field, "strength", &DENSITY, REQUIRED, &w->out->absorption) ||
        tarn_get_bool(w->l, a, field, "squared", 0, &squared)) {
        return -1;
    }
    w->out->absorption_squared = (uint8_t)squared;
    return 0;
}

/* With a ramp the two colours are unused, so they are only required without one. */
static int read_depth_colour(water_reader *w)
{
    static const char *const fields[] = { "shallow", "deep", "scale", "ramp", NULL };
    char field[TARN_FIELD_PATH_MAX];
    json_t *d;
    tarn_water *out = w->out;
    if (feature_object(w, "depth_colour", "an object {\"shallow\", \"deep\", \"scale\", \"ramp\"}",
                       fields, &d, field) ||
        get_q16(w->l, d, field, "scale", &TARN_POSITIVE, REQUIRED, &out->depth_scale)) {
        return -1;
    }
    if (json_object_get(d, "ramp")) {
        if (tarn_get_texture(w->l, d, field, "ramp", &out->colour_ramp) ||
            tarn_get_colour(w->l, d, field, "shallow", 0, &out->shallow_rgb) ||
            tarn_get_colour(w->l, d, field, "deep", 0, &out->deep_rgb)) {
            return -1;
        }
        return 0;
    }
    if (required_colour(w->l, d, field, "shallow", &out->shallow_rgb) ||
        required_colour(w->l, d, field, "deep", &out->deep_rgb)) {
        return -1;
    }
    return 0;
}

static int read_normal_maps(water_reader *w)
{
    static const char what[] = "an array of 1 or 2 normal maps {\"image\", \"scale\", \"speed\"}";
    char field[TARN_FIELD_PATH_MAX];
    tarn_water *out = w->out;
    tarn_join_path(field, w->field, "normal_maps");
    const json_t *maps = json_object_get(w->block, "normal_maps");
    if (!json_is_array(maps)) {
        return tarn_fail_field(w->l, field, "expected %s, got %s", what, tarn_json_type(maps));
    }
    size_t n = json_array_size(maps);
    if (n < 1 || n > 2) return tarn_fail_field(w->l, field, "expected %s, got %zu", what, n);
    const tarn_texture **textures[2] = { &out->normal_a, &out->normal_b };
    tarn_panning *pans[2] = { &out->pan_a, &out->pan_b };
    for (size_t k = 0; k < n; k++) {
        char element[TARN_FIELD_PATH_MAX + 24]; /* room for "[index]" */
        snprintf(element, sizeof element, "%s[%zu]", field, k);
        if (get_panned_map(w->l, json_array_get(maps, k), element, textures[k], pans[k])) {
            return -1;
        }
    }
    if (get_q16(w->l, w->block, w->field, "normal_strength", &NORMAL_STRENGTH, OPTIONAL,
                &out->normal_strength)) {
        return -1;
    }
    out->normal_xy_max = tarn_water_normal_xy_max(out->normal_a, out->normal_b,
                                                  out->normal_strength);
    return 0;
}

/* Pixels `refraction` reaches with these normals, by the core's own rule (which the
 * frame's apron is sized from). */
static int32_t reach_at(const tarn_water *water, tarn_q16 refraction, uint16_t width)
{
    tarn_water probe = *water;
    probe.features |= TARN_WATER_REFRACTION;
    probe.refraction = refraction;
    return tarn_water_reach_pixels(&probe, width);
}

/* The largest Q16.16 strength whose reach fits the apron (the reach grows with it). */
static tarn_q16 largest_refraction(const tarn_water *water, uint16_t width)
{
    tarn_q16 fits = 0, too_far = water->refraction;
    while (too_far - fits > 1) {
        tarn_q16 middle = fits + (too_far - fits) / 2;
        if (reach_at(water, middle, width) <= (int32_t)TARN_WATER_APRON_MAX) fits = middle;
        else too_far = middle;
    }
    return fits;
}

/* A strength that reaches past the apron at the scene's width is refused, naming
 * the largest that fits. */
static int read_refraction(water_reader *w)
{
    tarn_water *out = w->out;
    if (needs_normals(w, "refraction", "the offset comes from the normals") ||
        get_q16(w->l, w->block, w->field, "refraction", &UNIT, REQUIRED, &out->refraction)) {
        return -1;
    }
    int32_t reach = reach_at(out, out->refraction, w->frame_width);
    if (reach <= (int32_t)TARN_WATER_APRON_MAX) return 0;
    /* printed rounded down, so that the number as written still fits */
    double largest = floor(largest_refraction(out, w->frame_width) / 65536.0 * 10000) / 10000;
    char field[TARN_FIELD_PATH_MAX];
    tarn_join_path(field, w->field, "refraction");
    return tarn_fail_field(w->l, field,
                           "expected at most %.4f at width %u (normal_xy_max %.4f; the apron "
                           "holds %u pixels), got %g (%d pixels)",
                           largest, w->frame_width, out->normal_xy_max / 65536.0,
                           TARN_WATER_APRON_MAX, out->refraction / 65536.0, reach);
}

static int read_fresnel(water_reader *w)
{
    return get_q16(w->l, w->block, w->field, "fresnel", &UNIT, REQUIRED, &w->out->fresnel);
}

static int read_specular(water_reader *w)
{
    static const char *const fields[] = { "intensity", "power", NULL };
    char field[TARN_FIELD_PATH_MAX];
    json_t *s;
    unsigned power = w->out->specular_power;
    if (feature_object(w, "specular", "an object {\"intensity\", \"power\"}", fields, &s, field) ||
        get_q16(w->l, s, field, "intensity", &SPECULAR_INTENSITY, OPTIONAL, &w->out->specular) ||
        get_whole(w->l, s, field, "power", &SPECULAR_POWER, &power)) {
        return -1;
    }
    w->out->specular_power = (uint16_t)power;
    return 0;
}

static int read_foam(water_reader *w)
{
    static const char *const fields[] = { "texture", "scale", "speed", "distance", "line_speed",
                                          "lines", "colour", "opacity", NULL };
    char field[TARN_FIELD_PATH_MAX];
    json_t *f;
    tarn_water *out = w->out;
    unsigned lines = out->foam_line_count;
    if (feature_object(w, "foam", "an object {\"texture\", \"distance\"...}", fields, &f, field) ||
        tarn_get_texture(w->l, f, field, "texture", &out->foam_texture) ||
        get_panning(w->l, f, field, &out->foam_pan) ||
        get_q16(w->l, f, field, "distance", &TARN_POSITIVE, REQUIRED, &out->foam_distance) ||
        get_q16(w->l, f, field, "line_speed", &SPEED, OPTIONAL, &out->foam_line_speed) ||
        get_whole(w->l, f, field, "lines", &FOAM_LINES, &lines) ||
        tarn_get_colour(w->l, f, field, "colour", out->foam_rgb, &out->foam_rgb) ||
        get_q16(w->l, f, field, "opacity", &UNIT, OPTIONAL, &out->foam_opacity)) {
        return -1;
    }
    out->foam_line_count = (uint8_t)lines;
    return 0;
}

static int read_sparkles(water_reader *w)
{
    static const char *const fields[] = { "amount", "colour", NULL };
    char field[TARN_FIELD_PATH_MAX];
    json_t *s;
    if (needs_normals(w, "sparkles", "sparkles come from the normal maps' x") ||
        feature_object(w, "sparkles", "an object {\"amount\", \"colour\"}", fields, &s, field) ||
        get_q16(w->l, s, field, "amount", &TARN_POSITIVE, REQUIRED, &w->out->sparkle_amount) ||
        tarn_get_colour(w->l, s, field, "colour", w->out->sparkle_rgb, &w->out->sparkle_rgb)) {
        return -1;
    }
    return 0;
}

typedef struct {
    const char *key;
    uint32_t flag;
    int (*read)(water_reader *w);
} water_feature;

/* In reading order: normal_maps before the features that need them. */
static const water_feature FEATURES[] = {
    { "fog", TARN_WATER_FOG, read_fog },
    { "absorption", TARN_WATER_ABSORPTION, read_absorption },
    { "depth_colour", TARN_WATER_DEPTH_COLOUR, read_depth_colour },
    { "normal_maps", TARN_WATER_NORMALS, read_normal_maps },
    { "refraction", TARN_WATER_REFRACTION, read_refraction },
    { "fresnel", TARN_WATER_FRESNEL, read_fresnel },
    { "specular", TARN_WATER_SPECULAR, read_specular },
    { "foam", TARN_WATER_FOAM, read_foam },
    { "sparkles", TARN_WATER_SPARKLES, read_sparkles },
};
#define FEATURE_COUNT (sizeof FEATURES / sizeof FEATURES[0])

static int read_water(water_reader *w)
{
    static const char *const surface[] = { "albedo", "alpha", "normal_strength", NULL };
    const char *keys[FEATURE_COUNT + 1];
    for (size_t k = 0; k < FEATURE_COUNT; k++) keys[k] = FEATURES[k].key;
    keys[FEATURE_COUNT] = NULL;
    if (tarn_check_fields(w->l, w->block, w->field, surface, keys, "") ||
        tarn_get_colour(w->l, w->block, w->field, "albedo", w->out->albedo_rgb,
                        &w->out->albedo_rgb) ||
        get_q16(w->l, w->block, w->field, "alpha", &UNIT, OPTIONAL, &w->out->alpha)) {
        return -1;
    }
    for (size_t k = 0; k < FEATURE_COUNT; k++) {
        if (!json_object_get(w->block, FEATURES[k].key)) continue;
        if (FEATURES[k].read(w)) return -1;
        w->out->features |= FEATURES[k].flag;
    }
    /* read with the maps; alone it would silently do nothing */
    if (json_object_get(w->block, "normal_strength") && !(w->out->features & TARN_WATER_NORMALS)) {
        return needs_normals(w, "normal_strength", "it scales them");
    }
    return 0;
}

int tarn_water_load(tarn_loader *l, const json_t *material, const char *parent,
                    uint16_t frame_width, tarn_water *out, int *present)
{
    static const char what[] = "an object of water features {\"fog\", \"refraction\"...}";
    char field[TARN_FIELD_PATH_MAX];
    json_t *block;
    *out = WATER_DEFAULTS;
    *present = 0;
    if (tarn_get_object(l, material, parent, "water", what, 0, &block)) return -1;
    if (!block) return 0;
    tarn_join_path(field, parent, "water");
    water_reader w = { l, block, field, frame_width, out };
    if (read_water(&w)) return -1;
    *present = 1;
    return 0;
}

/* ---- underwater ------------------------------------------------------------------ */

static int read_tint(tarn_loader *l, const json_t *u, tarn_underwater *out)
{
    static const char *const fields[] = { "colour", "density", NULL };
    json_t *tint;
    if (tarn_get_object(l, u, "underwater", "tint", "an object {\"colour\", \"density\"}", 0,
                        &tint)) {
        return -1;
    }
    if (!tint) return 0; /* no tint: density 0 */
    if (tarn_check_fields(l, tint, "underwater.tint", fields, NULL, "") ||
        required_colour(l, tint, "underwater.tint", "colour", &out->tint_rgb) ||
        get_q16(l, tint, "underwater.tint", "density", &DENSITY, REQUIRED,
                &out->tint_density)) {
        return -1;
    }
    return 0;
}

int tarn_underwater_load(tarn_loader *l, const json_t *root, tarn_underwater *out, int *present)
{
    static const char *const fields[] = { "level", "normal_map", "distortion", "tint", NULL };
    json_t *u, *map;
    *out = (tarn_underwater){ .pan = STILL_PANNING };
    *present = 0;
    if (tarn_get_object(l, root, "", "underwater",
                        "an object {\"level\", \"normal_map\", \"distortion\", \"tint\"}", 0, &u)) {
        return -1;
    }
    if (!u) return 0;
    if (tarn_check_fields(l, u, "underwater", fields, NULL, "") ||
        get_q16(l, u, "underwater", "level", &TARN_COORDINATE, REQUIRED, &out->level) ||
        tarn_get_object(l, u, "underwater", "normal_map", PANNING_WHAT, 1, &map) ||
        get_panned_map(l, map, "underwater.normal_map", &out->normal_map, &out->pan) ||
        get_q16(l, u, "underwater", "distortion", &UNIT, OPTIONAL, &out->distortion) ||
        read_tint(l, u, out)) {
        return -1;
    }
    *present = 1;
    return 0;
}

/* ---- the normals' bound ------------------------------------------------------------ */

/* A texel channel c decodes to (2c - 255) / 255 (tarn_water.h step 1). */
static double decode(uint8_t c)
{
    return (2.0 * c - 255.0) / 255.0;
}

/* |2c - 255| is odd, 1..255: index 0..127 of a decoded magnitude. */
static int magnitude_index(uint8_t c)
{
    int v = 2 * c - 255;
    return ((v < 0 ? -v : v) - 1) / 2;
}

static double index_magnitude(int k)
{
    return (2.0 * k + 1.0) / 255.0;
}

/* One map: max(|N.x|, |N.y|) of N = normalize(s * a.xy, a.z), exactly, over its texels. */
static double one_map_bound(const tarn_texture *a, double s)
{
    double bound = 0;
    for (size_t k = 0; k < (size_t)a->width * a->height; k++) {
        const uint8_t *t = a->rgb + 3 * k;
        double x = s * decode(t[0]), y = s * decode(t[1]), z = decode(t[2]);
        double lean = fmax(fabs(x), fabs(y)) / sqrt(x * x + y * y + z * z);
        bound = fmax(bound, lean);
    }
    return bound;
}

/* For each magnitude index of max(|x|, |y|), the smallest |z| with it; 2 where none. */
static void smallest_z(const tarn_texture *a, double z_of[128])
{
    for (int k = 0; k < 128; k++) z_of[k] = 2;
    for (size_t k = 0; k < (size_t)a->width * a->height; k++) {
        const uint8_t *t = a->rgb + 3 * k;
        int m = magnitude_index(t[0]) > magnitude_index(t[1]) ? magnitude_index(t[0])
                                                                : magnitude_index(t[1]);
        z_of[m] = fmin(z_of[m], index_magnitude(magnitude_index(t[2])));
    }
}

static double two_map_bound(const tarn_texture *a, const tarn_texture *b, double s)
{
    double za[128], zb[128], bound = 0;
    smallest_z(a, za);
    smallest_z(b, zb);
    for (int i = 0; i < 128; i++) {
        for (int j = 0; j < 128 && za[i] <= 1; j++) {
            if (zb[j] > 1) continue;
            double xy = s * (index_magnitude(i) + index_magnitude(j)), z = za[i] * zb[j];
            bound = fmax(bound, xy / sqrt(xy * xy + z * z));
        }
    }
    return bound;
}

tarn_q16 tarn_water_normal_xy_max(const tarn_texture *a, const tarn_texture *b,
                                  tarn_q16 strength)
{
    double s = strength / 65536.0;
    double bound = b ? two_map_bound(a, b, s) : one_map_bound(a, s);
    /* rounded up, with room for the double's own rounding: an upper bound stays one */
    double q = ceil(bound * 65536.0 * (1 + 1e-12));
    return q >= 65536 ? TARN_Q16_ONE : (tarn_q16)q;
}
