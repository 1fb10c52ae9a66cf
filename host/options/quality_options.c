/* quality_options.c: the QUALITY options (quality_options.h). */
#include "quality_options.h"

#include <stdlib.h>
#include <string.h>

#include "option_values.h"

static int parse_perspective(const char *text, tarn_quality *q, tarn_error *err)
{
    unsigned long span;
    if (text && strcmp(text, "affine") == 0) {
        q->perspective = TARN_PERSPECTIVE_AFFINE;
    } else if (text && strcmp(text, "pixel") == 0) {
        q->perspective = TARN_PERSPECTIVE_PIXEL;
    } else if (text && strncmp(text, "span:", 5) == 0 && tarn_parse_whole(text + 5, 2, 64, &span) == 0 &&
               (span & (span - 1)) == 0) {
        q->perspective = TARN_PERSPECTIVE_SPAN;
        q->perspective_span = (uint8_t)span;
    } else {
        return tarn_fail(err, "--perspective: expected affine, pixel or span:N (N a power of two 2..64), got '%s'",
                         text ? text : "");
    }
    return 0;
}

static int parse_exp2(const char *text, tarn_quality *q, tarn_error *err)
{
    const char *colon = text ? strchr(text, ':') : NULL;
    const char *mode = colon ? colon + 1 : "linear";
    size_t length = colon ? (size_t)(colon - text) : (text ? strlen(text) : 0);
    int mode_known = strcmp(mode, "nearest") == 0 || strcmp(mode, "linear") == 0;
    char entries_text[8];
    unsigned long entries;
    if (text && mode_known && length < sizeof entries_text) {
        memcpy(entries_text, text, length);
        entries_text[length] = '\0';
        if (tarn_parse_whole(entries_text, TARN_EXP2_ENTRIES_MIN, TARN_EXP2_ENTRIES_MAX, &entries) == 0 &&
            (entries & (entries - 1)) == 0) {
            q->exp2.entries = (uint16_t)entries;
            q->exp2.interpolate = strcmp(mode, "linear") == 0;
            return 0;
        }
    }
    return tarn_fail(err, "--exp2: expected N[:nearest|:linear] with N a power of two 8..256, got '%s'",
                     text ? text : "");
}

/* --water-block 1|2|4. */
static int parse_water_block(const char *value, tarn_quality *q, tarn_error *err)
{
    if (value && (strcmp(value, "1") == 0 || strcmp(value, "2") == 0 || strcmp(value, "4") == 0)) {
        q->water_block = (uint8_t)(value[0] - '0');
        return 0;
    }
    return tarn_fail(err, "--water-block: expected 1, 2 or 4, got '%s'", value ? value : "");
}

/* A knob taking a whole number in a range, stored in a uint8_t field. */
static int parse_knob(const char *name, const char *text, unsigned long min, unsigned long max,
                      uint8_t *field, tarn_error *err)
{
    unsigned long value;
    if (tarn_parse_whole(text, min, max, &value) != 0)
        return tarn_fail(err, "%s: expected a whole number %lu..%lu, got '%s'", name, min, max,
                         text ? text : "");
    *field = (uint8_t)value;
    return 0;
}

static int parse_apron(const char *value, tarn_quality *q, tarn_error *err)
{
    unsigned long pixels;
    if (value && strcmp(value, "on") == 0) q->refraction_apron = TARN_APRON_FULL;
    else if (value && strcmp(value, "off") == 0) q->refraction_apron = 0;
    else if (tarn_parse_whole(value, 0, TARN_WATER_APRON_MAX, &pixels) == 0) q->refraction_apron = (uint8_t)pixels;
    else
        return tarn_fail(err, "--apron: expected on (refraction moves samples as far as it reaches), off "
                         "(moves nothing: least memory) or a limit in pixels 0..%u, got '%s'",
                         TARN_WATER_APRON_MAX, value ? value : "");
    return 0;
}

static int parse_bins(const char *value, tarn_quality *q, tarn_error *err)
{
    if (value && strcmp(value, "on") == 0) q->cluster_bins = 1;
    else if (value && strcmp(value, "off") == 0) q->cluster_bins = 0;
    else
        return tarn_fail(err, "--bins: expected on (find each cluster's screen box once a frame) or off "
                         "(each tile tests every cluster's sphere: least memory), got '%s'", value ? value : "");
    return 0;
}

static int parse_depth_interpolation(const char *value, tarn_quality *q, tarn_error *err)
{
    if (value && strcmp(value, "exact") == 0) q->depth_interpolation = TARN_DEPTH_EXACT;
    else if (value && strcmp(value, "plane") == 0) q->depth_interpolation = TARN_DEPTH_PLANE;
    else
        return tarn_fail(err, "--depth-interpolation: expected exact (near/d rounded exactly at each pixel) or "
                         "plane (stepped on a plane, a division less a triangle), got '%s'", value ? value : "");
    return 0;
}

static int parse_preset(const char *value, tarn_quality *q, tarn_error *err)
{
    for (int p = 0; p < TARN_PRESET_COUNT; p++) {
        if (value && strcmp(value, tarn_preset_name((tarn_preset)p)) == 0) {
            *q = tarn_quality_preset((tarn_preset)p);
            return 0;
        }
    }
    return tarn_fail(err, "--quality: expected fast, balanced or exact, got '%s'", value ? value : "");
}

int tarn_cli_parse_quality_option(const char *name, const char *value, tarn_quality *q, tarn_error *err)
{
    if (strcmp(name, "--quality") == 0) {
        tarn_quality ignored; /* applied before the others, by tarn_cli_apply_preset */
        return parse_preset(value, &ignored, err);
    }
    if (strcmp(name, "--fog-bits") == 0)
        return parse_knob(name, value, TARN_FOG_ARGUMENT_BITS_MIN, TARN_FOG_ARGUMENT_BITS_MAX,
                          &q->fog_argument_bits, err);
    if (strcmp(name, "--tile") == 0)
        return parse_knob(name, value, TARN_TILE_SIZE_MIN, TARN_TILE_SIZE_MAX, &q->tile_size, err);
    if (strcmp(name, "--water-block") == 0) return parse_water_block(value, q, err);
    if (strcmp(name, "--subpixel") == 0)
        return parse_knob(name, value, TARN_SUBPIXEL_BITS_MIN, TARN_SUBPIXEL_BITS_MAX, &q->subpixel_bits, err);
    if (strcmp(name, "--recip-steps") == 0)
        return parse_knob(name, value, 0, TARN_RECIP_STEPS_MAX, &q->recip_newton_steps, err);
    if (strcmp(name, "--depth") == 0) {
        if (value && (strcmp(value, "16") == 0 || strcmp(value, "32") == 0)) {
            q->depth_bits = (uint8_t)atoi(value);
            return 0;
        }
        return tarn_fail(err, "--depth: expected 16 or 32, got '%s'", value ? value : "");
    }
    if (strcmp(name, "--apron") == 0) return parse_apron(value, q, err);
    if (strcmp(name, "--bins") == 0) return parse_bins(value, q, err);
    if (strcmp(name, "--depth-interpolation") == 0) return parse_depth_interpolation(value, q, err);
    if (strcmp(name, "--perspective") == 0) return parse_perspective(value, q, err);
    if (strcmp(name, "--exp2") == 0) return parse_exp2(value, q, err);
    return 1; /* not a quality option */
}

int tarn_cli_check_quality(const tarn_quality *q, tarn_error *err)
{
    if (q->water_block > 1 && q->tile_size % q->water_block != 0)
        return tarn_fail(err, "--water-block %u: expected a --tile that is a multiple of %u (a tile must hold whole "
                         "blocks), got %u", (unsigned)q->water_block, (unsigned)q->water_block, (unsigned)q->tile_size);
    return 0;
}

int tarn_cli_apply_preset(int argc, char *const argv[], tarn_quality *quality, tarn_error *err)
{
    const char *preset = NULL;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--quality") != 0) continue;
        if (preset != NULL) return tarn_fail(err, "--quality: given twice ('%s', then '%s')", preset,
                                             i + 1 < argc ? argv[i + 1] : "");
        preset = i + 1 < argc ? argv[i + 1] : "";
        if (parse_preset(preset, quality, err) != 0) return -1;
    }
    return 0;
}
