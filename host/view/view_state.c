/* view_state.c: the view's state and what each key does (view_state.h). */
#include "view_state.h"

#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "quality_options.h"
#include "quality_text.h"

static const char *const water_blocks[] = {"1", "2", "4", NULL};
static const char *const on_off[] = {"on", "off", NULL};
static const char *const depths[] = {"16", "32", NULL};
static const char *const interpolations[] = {"exact", "plane", NULL};
static const char *const perspectives[] = {"affine", "span:16", "pixel", NULL};
static const char *const subpixels[] = {"1", "2", "4", "8", NULL};
static const char *const fog_bits[] = {"8", "12", "16", NULL};
static const char *const exp2_sizes[] = {"16", "64", "256", NULL};
static const char *const normals[] = {"shared", "exact", NULL};
static const char *const shapes[] = {"tiles", "strips", NULL};

static const tarn_view_key keys[] = {
    {"Space", TARN_VIEW_PAUSE, NULL, NULL, "pause or run the clock"},
    {"Right", TARN_VIEW_STEP_ON, NULL, NULL, "one frame on (pauses)"},
    {"Left", TARN_VIEW_STEP_BACK, NULL, NULL, "one frame back (pauses)"},
    {"-", TARN_VIEW_SLOWER, NULL, NULL, "the clock at half speed"},
    {"=", TARN_VIEW_FASTER, NULL, NULL, "the clock at double speed"},
    {"R", TARN_VIEW_RESET_CAMERA, NULL, NULL, "the scene's own camera (and its path) again"},
    {"V", TARN_VIEW_NEXT_PICTURE, NULL, NULL, "the core's frame, the float reference, the error heat map"},
    {"P", TARN_VIEW_PANEL, NULL, NULL, "as the panel shows it: RGB565 with the boards' dither, or not"},
    {"1", TARN_VIEW_FAST, NULL, NULL, "--quality fast"},
    {"2", TARN_VIEW_BALANCED, NULL, NULL, "--quality balanced"},
    {"3", TARN_VIEW_EXACT, NULL, NULL, "--quality exact"},
    {"B", TARN_VIEW_KNOB, "--water-block", water_blocks, "--water-block 1, 2, 4"},
    {"A", TARN_VIEW_KNOB, "--apron", on_off, "--apron on, off"},
    {"D", TARN_VIEW_KNOB, "--depth", depths, "--depth 16, 32"},
    {"I", TARN_VIEW_KNOB, "--depth-interpolation", interpolations, "--depth-interpolation exact, plane"},
    {"T", TARN_VIEW_KNOB, "--perspective", perspectives, "--perspective affine, span:16, pixel"},
    {"S", TARN_VIEW_KNOB, "--subpixel", subpixels, "--subpixel 1, 2, 4, 8"},
    {"F", TARN_VIEW_KNOB, "--fog-bits", fog_bits, "--fog-bits 8, 12, 16"},
    {"X", TARN_VIEW_KNOB, "--exp2", exp2_sizes, "--exp2 16, 64, 256"},
    {"N", TARN_VIEW_KNOB, "--refraction-normal", normals, "--refraction-normal shared, exact"},
    {"M", TARN_VIEW_KNOB, "--frame", shapes, "--frame tiles, strips"},
    {"C", TARN_VIEW_PRINT_COMMAND, NULL, NULL, "print the tarn render command of this picture"},
    {"H", TARN_VIEW_PRINT_KEYS, NULL, NULL, "print these keys"},
    {"Q", TARN_VIEW_QUIT, NULL, NULL, "quit (Escape too)"},
    {"Escape", TARN_VIEW_QUIT, NULL, NULL, NULL},
};

const tarn_view_key *tarn_view_find_key(const char *name)
{
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++)
        if (strcasecmp(keys[k].key, name) == 0) return &keys[k];
    return NULL;
}

void tarn_view_key_help(char *out, size_t size)
{
    size_t used = 0;
    out[0] = '\0';
    for (size_t k = 0; k < sizeof keys / sizeof keys[0] && used < size; k++) {
        if (keys[k].meaning == NULL) continue;
        int written = snprintf(out + used, size - used, "  %-6s %s\n", keys[k].key, keys[k].meaning);
        if (written < 0) return;
        used += (size_t)written;
    }
}

static int same_quality(const tarn_quality *a, const tarn_quality *b)
{
    char text_a[TARN_QUALITY_TEXT_MAX], text_b[TARN_QUALITY_TEXT_MAX];
    tarn_quality_text(a, text_a, sizeof text_a);
    tarn_quality_text(b, text_b, sizeof text_b);
    return strcmp(text_a, text_b) == 0;
}

void tarn_view_state_init(tarn_view_state *s, const tarn_quality *quality, tarn_preset preset, uint32_t start_ms,
                          uint8_t fps)
{
    memset(s, 0, sizeof *s);
    s->start_ms = start_ms;
    s->fps = fps;
    s->zoom = 1.0;
    s->quality = *quality;
    s->preset = preset;
}

/* The quality with `option value` applied, if the knobs allow it together. */
static int with_knob(const tarn_quality *q, const char *option, const char *value, tarn_quality *out)
{
    tarn_error err;
    *out = *q;
    return tarn_cli_parse_quality_option(option, value, out, &err) == 0 && tarn_cli_check_quality(out, &err) == 0
               ? 0
               : -1;
}

/* The knob's value after its present one that the other knobs allow. */
static void next_knob_value(tarn_view_state *s, const tarn_view_key *key)
{
    size_t count = 0, present = 0;
    tarn_quality q;
    while (key->values[count] != NULL) {
        if (with_knob(&s->quality, key->option, key->values[count], &q) == 0 && same_quality(&q, &s->quality))
            present = count;
        count++;
    }
    for (size_t step = 1; step < count; step++) {
        if (with_knob(&s->quality, key->option, key->values[(present + step) % count], &q) == 0) {
            s->quality = q;
            return;
        }
    }
    s->message = "this knob has no other value the others allow";
}

static void choose_preset(tarn_view_state *s, tarn_preset preset)
{
    s->preset = preset;
    s->quality = tarn_quality_preset(preset);
}

/* One frame of the view's fps at speed 1: 1000 / fps ms of 16 * fps units each. */
#define FRAME_UNITS 16000u

void tarn_view_press(tarn_view_state *s, const tarn_view_key *key)
{
    s->message = NULL;
    switch (key->action) {
    case TARN_VIEW_PAUSE: s->paused = !s->paused; break;
    case TARN_VIEW_STEP_ON: s->paused = 1; s->clock_units += FRAME_UNITS; break;
    case TARN_VIEW_STEP_BACK:
        s->paused = 1;
        s->clock_units = s->clock_units > FRAME_UNITS ? s->clock_units - FRAME_UNITS : 0;
        break;
    case TARN_VIEW_SLOWER: if (s->speed_log2 > TARN_VIEW_SPEED_LOG2_MIN) s->speed_log2--; break;
    case TARN_VIEW_FASTER: if (s->speed_log2 < TARN_VIEW_SPEED_LOG2_MAX) s->speed_log2++; break;
    case TARN_VIEW_RESET_CAMERA: s->yaw_degrees = s->pitch_degrees = 0; s->zoom = 1.0; break;
    case TARN_VIEW_NEXT_PICTURE: s->picture = (tarn_view_picture)((s->picture + 1) % 3); break;
    case TARN_VIEW_PANEL: s->panel = !s->panel; break;
    case TARN_VIEW_FAST: choose_preset(s, TARN_PRESET_FAST); break;
    case TARN_VIEW_BALANCED: choose_preset(s, TARN_PRESET_BALANCED); break;
    case TARN_VIEW_EXACT: choose_preset(s, TARN_PRESET_EXACT); break;
    case TARN_VIEW_KNOB: next_knob_value(s, key); break;
    case TARN_VIEW_PRINT_COMMAND: s->print_command = 1; break;
    case TARN_VIEW_PRINT_KEYS: s->print_keys = 1; break;
    case TARN_VIEW_QUIT: s->quit = 1; break;
    }
}

/* The camera stays short of the poles, where its up vector would turn over. */
#define PITCH_LIMIT_DEGREES 80.0
#define ZOOM_MIN 0.05
#define ZOOM_MAX 20.0

void tarn_view_drag(tarn_view_state *s, int dx, int dy)
{
    s->yaw_degrees -= 0.25 * dx;
    s->yaw_degrees -= 360.0 * (double)(long)(s->yaw_degrees / 360.0);
    s->pitch_degrees += 0.25 * dy;
    if (s->pitch_degrees > PITCH_LIMIT_DEGREES) s->pitch_degrees = PITCH_LIMIT_DEGREES;
    if (s->pitch_degrees < -PITCH_LIMIT_DEGREES) s->pitch_degrees = -PITCH_LIMIT_DEGREES;
}

void tarn_view_wheel(tarn_view_state *s, int steps)
{
    for (; steps > 0 && s->zoom > ZOOM_MIN; steps--) s->zoom *= 0.9;
    for (; steps < 0 && s->zoom < ZOOM_MAX; steps++) s->zoom /= 0.9;
}

/* `units` of clock at speed 1, at the state's speed: exact, as every count of
 * units given here is a multiple of 16 and the speed is at least 1/16. */
static uint64_t at_speed(const tarn_view_state *s, uint64_t units)
{
    return s->speed_log2 >= 0 ? units << s->speed_log2 : units >> -s->speed_log2;
}

void tarn_view_run_ms(tarn_view_state *s, uint32_t elapsed_ms)
{
    if (!s->paused) s->clock_units += at_speed(s, (uint64_t)elapsed_ms * 16u * s->fps);
}

void tarn_view_run_frame(tarn_view_state *s)
{
    if (!s->paused) s->clock_units += at_speed(s, FRAME_UNITS);
}

uint32_t tarn_view_time_ms(const tarn_view_state *s)
{
    const uint64_t ms = s->start_ms + s->clock_units / (16u * s->fps);
    return ms > UINT32_MAX ? UINT32_MAX : (uint32_t)ms;
}

int tarn_view_own_camera(const tarn_view_state *s)
{
    return s->yaw_degrees == 0 && s->pitch_degrees == 0 && s->zoom == 1.0;
}

/* Each "--option value" pair of `current` that `base` lacks, appended to `out`
 * after ", ". */
static void append_changed_knobs(const char *current, const char *base, char *out, size_t size)
{
    char pairs[TARN_QUALITY_TEXT_MAX];
    const char *separator = ", ";
    snprintf(pairs, sizeof pairs, "%s", current);
    for (char *option = strtok(pairs, " "); option != NULL; option = strtok(NULL, " ")) {
        const char *value = strtok(NULL, " ");
        char pair[128];
        snprintf(pair, sizeof pair, "%s %s", option, value ? value : "");
        const char *found = strstr(base, pair);
        const size_t length = strlen(pair);
        if (found != NULL && (found[length] == ' ' || found[length] == '\0')) continue;
        const size_t used = strlen(out);
        snprintf(out + used, size - used, "%s%s", separator, pair);
        separator = " ";
    }
}

void tarn_view_quality_text(const tarn_view_state *s, char *out, size_t size)
{
    char current[TARN_QUALITY_TEXT_MAX], base[TARN_QUALITY_TEXT_MAX];
    const tarn_quality preset = tarn_quality_preset(s->preset);
    tarn_quality_text(&s->quality, current, sizeof current);
    tarn_quality_text(&preset, base, sizeof base);
    snprintf(out, size, "%s", tarn_preset_name(s->preset));
    append_changed_knobs(current, base, out, size);
}
