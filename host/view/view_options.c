/* view_options.c: tarn view's command line (view_options.h). */
#include "view_options.h"

#include <string.h>

#include "option_values.h"
#include "quality_options.h"

const char tarn_view_usage[] =
    "usage: tarn view SCENE [--size WxH] [--time MS] [--fps F] [--scale N] [--camera X,Y,Z:TX,TY,TZ[:FOV]]\n"
    "                 [--script FILE] [--screenshot OUT.png] [QUALITY]\n"
    "  a window that draws the scene live with the integer core; the scene file and its textures\n"
    "  are read again when they change (a bad edit shows its error, the last good scene stays)\n"
    "  --size WxH   the frame (the scene's own by default)\n"
    "  --time MS    the clock at the start (0 by default)\n"
    "  --fps F      a frame's step for the arrow keys and a script (30 by default)\n"
    "  --scale N    window pixels a frame pixel, 1..8 (the most that fits 720 by default)\n"
    "  --camera X,Y,Z:TX,TY,TZ[:FOV]  a still camera in place of the scene's, as render takes it\n"
    "  --script FILE  input events at given frames instead of a hand: one a line,\n"
    "               FRAME key NAME | drag DX DY | wheel STEPS | screenshot | wait-edit | quit\n"
    "               (wait-edit holds the script until the scene file changes)\n"
    "  --screenshot OUT.png  with a script, each screenshot to OUT-FRAME.png and a line on stdout\n"
    "               with the render command that draws it; without, the first frame, then exit\n"
    "  Needs a display: DISPLAY or WAYLAND_DISPLAY (over SSH: ssh -X; headless: xvfb-run).\n"
    "mouse: a drag with the left button turns the camera about its target; the wheel zooms\n"
    "keys:\n";

/* A tarn_option_reader. */
static int read_option(void *options, const char *name, const char *value, tarn_error *err)
{
    tarn_view_options *o = options;
    unsigned long n;
    if (strcmp(name, "--size") == 0) return tarn_parse_size(name, value, &o->width, &o->height, err);
    if (strcmp(name, "--camera") == 0) return tarn_camera_override_parse(value, &o->camera, err);
    if (strcmp(name, "--time") == 0) {
        if (tarn_parse_number(name, value, 0, UINT32_MAX, &n, err) != 0) return -1;
        o->time_ms = (uint32_t)n;
    } else if (strcmp(name, "--fps") == 0) {
        if (tarn_parse_number(name, value, 1, TARN_CLI_FPS_MAX, &n, err) != 0) return -1;
        o->fps = (uint8_t)n;
    } else if (strcmp(name, "--scale") == 0) {
        if (tarn_parse_number(name, value, 1, TARN_VIEW_SCALE_MAX, &n, err) != 0) return -1;
        o->scale = (uint8_t)n;
    } else if (strcmp(name, "--script") == 0 || strcmp(name, "--screenshot") == 0) {
        if (value == NULL || *value == '\0') return tarn_fail(err, "%s: expected a file name", name);
        *(strcmp(name, "--script") == 0 ? &o->script_path : &o->screenshot_path) = value;
    } else {
        for (int p = 0; p < TARN_PRESET_COUNT && strcmp(name, "--quality") == 0; p++)
            if (value && strcmp(value, tarn_preset_name((tarn_preset)p)) == 0) o->preset = (tarn_preset)p;
        return tarn_cli_parse_quality_option(name, value, &o->quality, err);
    }
    return TARN_OPTION_VALUE;
}

int tarn_view_parse(int argc, char **argv, tarn_view_options *o, tarn_error *err)
{
    memset(o, 0, sizeof *o);
    o->fps = TARN_CLI_FPS_DEFAULT;
    o->quality = tarn_quality_default();
    o->preset = TARN_PRESET_BALANCED;
    if (tarn_cli_apply_preset(argc - 2, argv + 2, &o->quality, err) != 0 ||
        tarn_parse_arguments(argc, argv, &o->scene_path, read_option, o, err) != 0 ||
        tarn_cli_check_quality(&o->quality, err) != 0)
        return -1;
    if (o->scene_path == NULL || o->scene_path[0] == '\0') return tarn_fail(err, "expected a scene file");
    return 0;
}
