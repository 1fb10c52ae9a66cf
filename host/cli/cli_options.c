#include "cli_options.h"
#include "backdrop.h"
#include "option_values.h"
#include "gif_io.h"
#include "quality_options.h"

#include <stdio.h>
#include <string.h>

static const tarn_option_choice commands[] = {
    {"render", TARN_CMD_RENDER, NULL}, {"compare", TARN_CMD_COMPARE, NULL}, {"accuracy", TARN_CMD_ACCURACY, NULL},
    {"memory", TARN_CMD_MEMORY, NULL}, {"bake", TARN_CMD_BAKE, NULL}};

/* bake --static-view on|off: whether the baked objects carry static vertices. */
static const tarn_option_choice static_views[] = {{"on", 0, NULL}, {"off", 1, NULL}};

/* render, bake --backdrop on|off|still. */
static const tarn_option_choice backdrops[] = {
    {"on", TARN_BACKDROP_OPAQUE, NULL}, {"off", TARN_BACKDROP_NONE, NULL}, {"still", TARN_BACKDROP_STILL, NULL}};

/* The command word (NULL when there is none). */
static int parse_command(const char *word, tarn_cli_options *o, tarn_error *err)
{
    int command;
    if (tarn_find_choice(word, TARN_CHOICES(commands), &command) == 0) {
        o->command = (tarn_command)command;
        return 0;
    }
    /* show and sweep have parsers of their own (main.c), but are commands as much */
    static const char expected[] = "render, compare, memory, bake, show, view, sweep or accuracy";
    if (word == NULL) return tarn_fail(err, "expected a command: %s", expected);
    return tarn_fail(err, "unknown command '%s'; expected %s", word, expected);
}

const char *tarn_cli_known_command(int argc, char **argv)
{
    int command;
    return argc >= 2 && tarn_find_choice(argv[1], TARN_CHOICES(commands), &command) == 0 ? argv[1] : NULL;
}

/* --frames N and --fps F. */
static int parse_sequence_option(const char *name, const char *value, tarn_cli_options *o,
                                 tarn_error *err)
{
    unsigned long n;
    if (strcmp(name, "--frames") == 0) {
        if (tarn_parse_number(name, value, 1, TARN_CLI_FRAMES_MAX, &n, err) != 0) return -1;
        o->frames = (uint16_t)n;
        return 0;
    }
    if (tarn_parse_number(name, value, 1, TARN_CLI_FPS_MAX, &n, err) != 0) return -1;
    o->fps = (uint8_t)n;
    return 0;
}

/* Options with a value: TARN_OPTION_VALUE, TARN_OPTION_UNKNOWN for none of them,
 * or -1. */
static int parse_valued_option(const char *name, const char *value, tarn_cli_options *o,
                               tarn_error *err)
{
    unsigned long ms;
    if (strcmp(name, "-o") == 0) o->output_path = value;
    else if (strcmp(name, "--diff") == 0) o->diff_path = value;
    else if (strcmp(name, "--points") == 0) o->points_path = value;
    else if (strcmp(name, "--static-view") == 0) {
        o->static_view_given = 1;
        return tarn_parse_choice(name, value, TARN_CHOICES(static_views), &o->no_static_view, err);
    } else if (strcmp(name, "--backdrop") == 0) {
        return tarn_parse_choice(name, value, TARN_CHOICES(backdrops), &o->backdrop, err);
    } else if (strcmp(name, "--landing-depth") == 0) {
        return tarn_parse_units(name, value, TARN_LANDING_DEPTH_MIN_Q16, TARN_LANDING_DEPTH_MAX_Q16,
                                &o->landing_depth_q16, err);
    } else if (strcmp(name, "--name") == 0) {
        o->name = value; /* checked by bake, so that "" gets the one-line error "3d" gets */
        return value ? 0 : tarn_fail(err, "--name: expected a C identifier");
    } else if (strcmp(name, "--size") == 0) return tarn_parse_size(name, value, &o->width, &o->height, err);
    else if (strcmp(name, "--camera") == 0) return tarn_camera_override_parse(value, &o->camera, err);
    else if (strcmp(name, "--frames") == 0 || strcmp(name, "--fps") == 0)
        return parse_sequence_option(name, value, o, err);
    else if (strcmp(name, "--time") == 0) {
        if (tarn_parse_whole(value, 0, UINT32_MAX, &ms) != 0)
            return tarn_fail(err, "--time: expected milliseconds 0..%lu, got '%s'",
                             (unsigned long)UINT32_MAX, value ? value : "");
        o->time_ms = (uint32_t)ms;
    } else return tarn_cli_parse_quality_option(name, value, &o->quality, err);
    if (value == NULL || *value == '\0') return tarn_fail(err, "%s: expected a file name", name);
    return 0;
}

static int parse_flag(const char *name, tarn_cli_options *o)
{
    if (strcmp(name, "--reference") == 0) o->reference = 1;
    else if (strcmp(name, "--snapped") == 0) o->snapped = 1;
    else if (strcmp(name, "--math") == 0) o->math = 1;
    else if (strcmp(name, "--quiet") == 0) o->quiet = 1;
    else if (strcmp(name, "--rgb565") == 0) o->rgb565 = 1;
    else return 1;
    return 0;
}

/* A tarn_option_reader. */
static int read_option(void *options, const char *name, const char *value, tarn_error *err)
{
    tarn_cli_options *o = options;
    return parse_flag(name, o) == 0 ? TARN_OPTION_FLAG : parse_valued_option(name, value, o, err);
}

/* In 64 bits, so that a clock past UINT32_MAX shows instead of wrapping. */
static uint64_t frame_clock(const tarn_cli_options *o, unsigned index)
{
    return o->time_ms + (uint64_t)index * 1000u / (o->fps ? o->fps : 1u);
}

/* A sequence is for render; its last frame's clock must not wrap. */
static int check_sequence(tarn_cli_options *o, tarn_error *err)
{
    if (o->frames && o->command != TARN_CMD_RENDER)
        return tarn_fail(err, "--frames applies to render");
    if (o->fps && !o->frames) return tarn_fail(err, "--fps applies to a sequence: add --frames N");
    if (!o->frames) return 0;
    if (!o->fps) o->fps = TARN_CLI_FPS_DEFAULT;
    uint64_t last = frame_clock(o, o->frames - 1u);
    if (last > UINT32_MAX)
        return tarn_fail(err, "--frames: the last frame would be at %llu ms, past %lu",
                         (unsigned long long)last, (unsigned long)UINT32_MAX);
    return 0;
}

static int check_combination(tarn_cli_options *o, tarn_error *err)
{
    if (tarn_cli_check_quality(&o->quality, err) != 0) return -1;
    if (o->command == TARN_CMD_ACCURACY && o->scene_path != NULL)
        return tarn_fail(err, "accuracy: unexpected argument '%s'", o->scene_path);
    if (o->command == TARN_CMD_ACCURACY)
        return o->math ? 0 : tarn_fail(err, "accuracy: expected --math");
    if (o->scene_path == NULL || o->scene_path[0] == '\0') return tarn_fail(err, "expected a scene file");
    if (o->command == TARN_CMD_RENDER && o->output_path == NULL)
        return tarn_fail(err, "render: expected -o OUT.png");
    if (o->command == TARN_CMD_BAKE && o->output_path == NULL) return tarn_fail(err, "bake: expected -o OUT.c");
    if (o->rgb565 && o->command != TARN_CMD_RENDER) return tarn_fail(err, "--rgb565 applies to render");
    if (o->camera.given && o->command != TARN_CMD_RENDER && o->command != TARN_CMD_COMPARE)
        return tarn_fail(err, "--camera applies to render and compare");
    if (tarn_cli_writes_gif(o) && o->fps > TARN_GIF_FPS_MAX)
        return tarn_fail(err, "--fps: a GIF shows at most %u frames a second, got %u", TARN_GIF_FPS_MAX, o->fps);
    if (o->quiet && o->command != TARN_CMD_RENDER && o->command != TARN_CMD_BAKE)
        return tarn_fail(err, "--quiet applies to render and bake");
    if (o->output_path && strcmp(o->output_path, "-") == 0 && (o->frames || o->command == TARN_CMD_BAKE))
        return tarn_fail(err, "-o -: standard output takes one image; %s writes several files",
                         o->frames ? "--frames" : "bake");
    if (o->diff_path && strcmp(o->diff_path, "-") == 0)
        return tarn_fail(err, "--diff -: standard output carries the compare line; name a file");
    if (o->name && o->command != TARN_CMD_BAKE) return tarn_fail(err, "--name applies to bake");
    if (o->points_path && o->command != TARN_CMD_BAKE) return tarn_fail(err, "--points applies to bake");
    if (o->static_view_given && o->command != TARN_CMD_BAKE) return tarn_fail(err, "--static-view applies to bake");
    if (o->backdrop && o->command != TARN_CMD_RENDER && o->command != TARN_CMD_BAKE && o->command != TARN_CMD_COMPARE)
        return tarn_fail(err, "--backdrop applies to render, compare and bake");
    if (o->backdrop && (o->reference || o->points_path || o->no_static_view))
        return tarn_fail(err, "--backdrop: draws one quality of the core with static vertices; "
                         "it excludes %s", o->reference ? "--reference" : o->points_path ? "--points" : "--static-view off");
    if (o->landing_depth_q16 != 0u && o->backdrop != TARN_BACKDROP_STILL)
        return tarn_fail(err, "--landing-depth applies to --backdrop still");
    if (o->snapped && (o->command != TARN_CMD_RENDER || !o->reference))
        return tarn_fail(err, "--snapped applies to render --reference");
    return check_sequence(o, err);
}

/* Whether the arguments name the option. */
static int option_given(const tarn_cli_options *o, const char *name)
{
    for (int k = 2; k < o->argc; k++)
        if (strcmp(o->argv[k], name) == 0) return 1;
    return 0;
}

/* Still water takes its texture coordinates from its plane (tarn_scene.h, "Still
 * water"): the quality says so, as the backdrop requires, and asking for the
 * triangles' is refused. */
static int still_water_coordinates(tarn_cli_options *o, tarn_error *err)
{
    if (o->backdrop != TARN_BACKDROP_STILL) return 0;
    if (o->quality.water_coordinates != TARN_WATER_UV_PLANE && option_given(o, "--water-uv"))
        return tarn_fail(err, "--backdrop still: still water takes its texture coordinates from its plane; "
                              "expected --water-uv plane, got triangles");
    o->quality.water_coordinates = TARN_WATER_UV_PLANE;
    return 0;
}

int tarn_cli_parse(int argc, char **argv, tarn_cli_options *o, tarn_error *err)
{
    memset(o, 0, sizeof *o);
    o->quality = tarn_quality_default();
    o->argc = argc;
    o->argv = argv;
    if (parse_command(argc < 2 ? NULL : argv[1], o, err) != 0) return -1;
    if (tarn_cli_apply_preset(argc - 2, argv + 2, &o->quality, err) != 0) return -1;
    if (tarn_parse_arguments(argc, argv, &o->scene_path, read_option, o, err) != 0) return -1;
    if (still_water_coordinates(o, err) != 0) return -1;
    return check_combination(o, err);
}

tarn_backdrop_request tarn_cli_backdrop(const tarn_cli_options *o)
{
    tarn_backdrop_request request = tarn_backdrop_of((tarn_backdrop_kind)o->backdrop);
    if (o->landing_depth_q16 != 0u) request.landing_depth_q16 = o->landing_depth_q16;
    return request;
}

int tarn_cli_writes_gif(const tarn_cli_options *o)
{
    const size_t length = o->output_path ? strlen(o->output_path) : 0;
    return o->command == TARN_CMD_RENDER && length >= 4 && strcmp(o->output_path + length - 4, ".gif") == 0;
}

uint32_t tarn_cli_frame_time(const tarn_cli_options *o, unsigned index)
{
    return (uint32_t)frame_clock(o, index); /* in range: the parser checked the last frame */
}
