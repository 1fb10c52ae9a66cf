/* quality_options.c: the QUALITY options (quality_options.h). */
#include "quality_options.h"

#include <stddef.h>
#include <string.h>

#include "option_values.h"

static const tarn_option_choice water_block_values[] = {{"1", 1, NULL}, {"2", 2, NULL}, {"4", 4, NULL}};
static const tarn_option_choice depth_bits_values[] = {{"16", 16, NULL}, {"32", 32, NULL}};
static const tarn_option_choice bins_values[] = {
    {"on", 1, "find each cluster's screen box once a frame"},
    {"off", 0, "each tile tests every cluster's sphere: least memory"}};
static const tarn_option_choice refraction_normal_values[] = {
    {"shared", TARN_REFRACTION_NORMAL_SHARED, "the highlight's 14-bit normal"},
    {"exact", TARN_REFRACTION_NORMAL_EXACT, "found again from the maps' texels, to 2^-15"}};
static const tarn_option_choice frame_shape_values[] = {
    {"tiles", TARN_FRAME_TILES, "square tiles, each drawing the opaque scene its water samples: least memory"},
    {"strips", TARN_FRAME_STRIPS, "rows of the whole width, the opaque pass kept for the next strips: each pixel drawn once"}};
static const tarn_option_choice vertex_pass_values[] = {
    {"tile", TARN_VERTICES_PER_TILE, "each tile's walk finds the vertices it meets: no memory"},
    {"frame", TARN_VERTICES_PER_FRAME, "once a frame, into memory: 16 bytes a vertex"},
    {"frame-view", TARN_VERTICES_PER_FRAME_VIEW,
     "once a frame with each view position, which clipped triangles read: 28 bytes a vertex"}};
static const tarn_option_choice lit_colour_values[] = {
    {"planes", TARN_LIT_PLANES, "a plane each channel"},
    {"line", TARN_LIT_LINE, "one channel's plane, the others along the line the vertices' colours lie on"}};
static const tarn_option_choice water_coordinates_values[] = {
    {"triangles", TARN_WATER_UV_TRIANGLES, "interpolated on each triangle from its snapped corners'"},
    {"plane", TARN_WATER_UV_PLANE, "where the pixel's ray meets a flat mesh's plane, as the reference"}};
static const tarn_option_choice depth_interpolation_values[] = {
    {"exact", TARN_DEPTH_EXACT, "near/d rounded exactly at each pixel"},
    {"plane", TARN_DEPTH_PLANE, "stepped on a plane, a division less a triangle"}};

/* A knob held in one uint8_t of tarn_quality: a word of `choices`, or without
 * them a whole number in [min, max]. Most knobs are one; the others, below, take
 * words and numbers together or set two fields. */
typedef struct {
    const char *option;
    size_t field; /* offsetof(tarn_quality, ...) */
    const tarn_option_choice *choices;
    size_t choice_count;
    unsigned long min, max;
} byte_knob;

#define NUMBER_KNOB(option, field, min, max) {option, offsetof(tarn_quality, field), NULL, 0, min, max}
#define CHOICE_KNOB(option, field, choices) {option, offsetof(tarn_quality, field), TARN_CHOICES(choices), 0, 0}

static const byte_knob byte_knobs[] = {
    NUMBER_KNOB("--fog-bits", fog_argument_bits, TARN_FOG_ARGUMENT_BITS_MIN, TARN_FOG_ARGUMENT_BITS_MAX),
    NUMBER_KNOB("--tile", tile_size, TARN_TILE_SIZE_MIN, TARN_TILE_SIZE_MAX),
    NUMBER_KNOB("--subpixel", subpixel_bits, TARN_SUBPIXEL_BITS_MIN, TARN_SUBPIXEL_BITS_MAX),
    NUMBER_KNOB("--recip-steps", recip_newton_steps, 0, TARN_RECIP_STEPS_MAX),
    CHOICE_KNOB("--water-block", water_block, water_block_values),
    CHOICE_KNOB("--depth", depth_bits, depth_bits_values),
    CHOICE_KNOB("--bins", cluster_bins, bins_values),
    CHOICE_KNOB("--depth-interpolation", depth_interpolation, depth_interpolation_values),
    CHOICE_KNOB("--refraction-normal", refraction_normal, refraction_normal_values),
    CHOICE_KNOB("--frame", frame_shape, frame_shape_values),
    CHOICE_KNOB("--vertices", vertex_pass, vertex_pass_values),
    CHOICE_KNOB("--lit", lit_colour, lit_colour_values),
    CHOICE_KNOB("--water-uv", water_coordinates, water_coordinates_values)};

static int parse_byte_knob(const byte_knob *knob, const char *text, tarn_quality *q, tarn_error *err)
{
    unsigned long value;
    int choice;
    if (knob->choices == NULL) {
        if (tarn_parse_number(knob->option, text, knob->min, knob->max, &value, err) != 0) return -1;
    } else {
        if (tarn_parse_choice(knob->option, text, knob->choices, knob->choice_count, &choice, err) != 0) return -1;
        value = (unsigned long)choice;
    }
    ((uint8_t *)q)[knob->field] = (uint8_t)value; /* the field is a uint8_t */
    return 0;
}

static int parse_perspective(const char *text, tarn_quality *q, tarn_error *err)
{
    static const tarn_option_choice spanless[] = {{"affine", TARN_PERSPECTIVE_AFFINE, NULL},
                                                  {"pixel", TARN_PERSPECTIVE_PIXEL, NULL}};
    unsigned long span;
    int mode;
    if (tarn_find_choice(text, TARN_CHOICES(spanless), &mode) == 0) {
        q->perspective = (uint8_t)mode;
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
    static const tarn_option_choice modes[] = {{"nearest", 0, NULL}, {"linear", 1, NULL}};
    const char *colon = text ? strchr(text, ':') : NULL;
    size_t length = colon ? (size_t)(colon - text) : (text ? strlen(text) : 0);
    int interpolate;
    char entries_text[8];
    unsigned long entries;
    /* N alone is N:linear */
    if (text && tarn_find_choice(colon ? colon + 1 : "linear", TARN_CHOICES(modes), &interpolate) == 0 &&
        length < sizeof entries_text) {
        memcpy(entries_text, text, length);
        entries_text[length] = '\0';
        if (tarn_parse_whole(entries_text, TARN_EXP2_ENTRIES_MIN, TARN_EXP2_ENTRIES_MAX, &entries) == 0 &&
            (entries & (entries - 1)) == 0) {
            q->exp2.entries = (uint16_t)entries;
            q->exp2.interpolate = (uint8_t)interpolate;
            return 0;
        }
    }
    return tarn_fail(err, "--exp2: expected N[:nearest|:linear] with N a power of two 8..256, got '%s'",
                     text ? text : "");
}

static int parse_apron(const char *value, tarn_quality *q, tarn_error *err)
{
    static const tarn_option_choice reach[] = {{"on", TARN_APRON_FULL, NULL}, {"off", 0, NULL}};
    unsigned long pixels;
    int on_or_off;
    if (tarn_find_choice(value, TARN_CHOICES(reach), &on_or_off) == 0) q->refraction_apron = (uint8_t)on_or_off;
    else if (tarn_parse_whole(value, 0, TARN_WATER_APRON_MAX, &pixels) == 0) q->refraction_apron = (uint8_t)pixels;
    else
        return tarn_fail(err, "--apron: expected on (refraction moves samples as far as it reaches), off "
                         "(moves nothing: least memory) or a limit in pixels 0..%u, got '%s'",
                         TARN_WATER_APRON_MAX, value ? value : "");
    return 0;
}

/* The presets by the names core/scene/presets.c gives them. */
static int parse_preset(const char *value, tarn_quality *q, tarn_error *err)
{
    tarn_option_choice presets[TARN_PRESET_COUNT];
    for (int p = 0; p < TARN_PRESET_COUNT; p++)
        presets[p] = (tarn_option_choice){tarn_preset_name((tarn_preset)p), p, NULL};
    int preset;
    if (tarn_parse_choice("--quality", value, presets, TARN_PRESET_COUNT, &preset, err) != 0) return -1;
    *q = tarn_quality_preset((tarn_preset)preset);
    return 0;
}

int tarn_cli_parse_quality_option(const char *name, const char *value, tarn_quality *q, tarn_error *err)
{
    for (size_t k = 0; k < sizeof byte_knobs / sizeof byte_knobs[0]; k++)
        if (strcmp(name, byte_knobs[k].option) == 0) return parse_byte_knob(&byte_knobs[k], value, q, err);
    if (strcmp(name, "--quality") == 0) {
        tarn_quality ignored; /* applied before the others, by tarn_cli_apply_preset */
        return parse_preset(value, &ignored, err);
    }
    if (strcmp(name, "--apron") == 0) return parse_apron(value, q, err);
    if (strcmp(name, "--perspective") == 0) return parse_perspective(value, q, err);
    if (strcmp(name, "--exp2") == 0) return parse_exp2(value, q, err);
    return TARN_OPTION_UNKNOWN;
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
