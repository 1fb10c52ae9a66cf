/* view_options.h: the command line of `tarn view`, parsed and range-checked.
 *
 *   tarn view SCENE [--size WxH] [--time MS] [--fps F] [--scale N]
 *             [--camera X,Y,Z:TX,TY,TZ[:FOV]] [--script FILE] [--screenshot OUT.png] [QUALITY] */
#ifndef TARN_HOST_VIEW_OPTIONS_H
#define TARN_HOST_VIEW_OPTIONS_H

#include <stdint.h>
#include "camera_override.h"
#include "error.h"
#include "tarn/tarn_render.h"

typedef struct {
    const char *scene_path;
    uint16_t width, height;   /* 0: the scene's own frame size */
    uint32_t time_ms;         /* the clock at the start */
    uint8_t fps;              /* a frame's step: the arrow keys, and a script's frames */
    uint8_t scale;            /* window pixels a frame pixel, each way; 0: fit the display */
    tarn_camera_override camera; /* in place of the scene's, before the mouse turns it */
    const char *script_path;  /* NULL: a hand at the keys (view_script.h) */
    const char *screenshot_path; /* NULL: none; with a script, its screenshots' name;
                                    alone, the first frame's, then the view ends */
    tarn_quality quality;
    tarn_preset preset;       /* the --quality it starts from (balanced by default) */
} tarn_view_options;

#define TARN_VIEW_SCALE_MAX 8u

/* argv[1] is "view". 0, or -1 with one line in `err`. */
int tarn_view_parse(int argc, char **argv, tarn_view_options *options, tarn_error *err);

extern const char tarn_view_usage[];

#endif
