/* cli_options.h: the command line of the `tarn` tool, parsed and range-checked.
 *
 *   tarn render SCENE -o OUT.png|OUT.gif [--size WxH] [--time MS] [--frames N [--fps F]]
 *               [--camera X,Y,Z:TX,TY,TZ[:FOV]] [--reference [--snapped]]
 *               [--backdrop on|off|still [--landing-depth U]] [--rgb565] [--quiet] [QUALITY]
 *   tarn compare SCENE [--size WxH] [--time MS] [--camera ...] [--diff HEAT.png]
 *                [--backdrop on|off|still [--landing-depth U]] [QUALITY]   (the core, through a backdrop with
 *                                              --backdrop, on the yardstick: yardstick.h)
 *   tarn accuracy --math
 *   tarn memory SCENE [--size WxH] [QUALITY]   (the working memory a frame needs)
 *   tarn bake SCENE -o OUT.c [--name NAME] [--size WxH] [--points FILE]
 *             [--static-view on|off] [--backdrop on|off|still [--landing-depth U]] [--quiet] [QUALITY]
 *                                              (the scene as const C data: host/bake/bake.h)
 * QUALITY knobs (defaults from tarn_quality_default()):
 *   --tile N (8..64)  --subpixel N (1..8)  --perspective affine|pixel|span:N
 *   --depth 16|32  --depth-interpolation exact|plane  --recip-steps N (0..2)
 *   --exp2 N[:nearest|:linear] (8..256)
 *   --apron on|off|N  --bins on|off  --fog-bits N (4..16)  --water-block 1|2|4
 *   --quality fast|balanced|exact   a preset (core/scene/presets.c) as the base of the others
 * (parsed by quality_options.h). cli_help.c prints each command's usage. */
#ifndef TARN_HOST_CLI_OPTIONS_H
#define TARN_HOST_CLI_OPTIONS_H

#include <stddef.h>
#include <stdint.h>
#include "backdrop.h"
#include "camera_override.h"
#include "error.h"
#include "tarn/tarn_render.h"

typedef enum {
    TARN_CMD_RENDER,
    TARN_CMD_COMPARE,
    TARN_CMD_ACCURACY,
    TARN_CMD_MEMORY,
    TARN_CMD_BAKE
} tarn_command;

typedef struct {
    tarn_command command;
    const char *scene_path;
    const char *output_path; /* render, bake: -o */
    const char *diff_path;   /* compare: --diff, or NULL */
    const char *name;        /* bake: --name, or NULL (checked by the bake itself) */
    const char *points_path; /* bake: --points, or NULL (host/bake/bake_points.h) */
    int no_static_view;      /* bake --static-view off: vertices computed each frame */
    int static_view_given;   /* --static-view appeared */
    int backdrop;            /* render, bake --backdrop: a tarn_backdrop_kind, what is
                                drawn once (host/bake/backdrop.h) */
    uint32_t landing_depth_q16; /* --landing-depth (with --backdrop still), Q16.16
                                   world units; 0 when not given: the deepest */
    uint16_t width, height;  /* 0: the scene's own frame size */
    uint32_t time_ms;
    tarn_camera_override camera; /* render, compare --camera: in place of the scene's */
    uint16_t frames;         /* render --frames: 0 for one frame written to -o itself */
    uint8_t fps;             /* frame k is at time_ms + floor(k * 1000 / fps) */
    int reference;           /* render with the float reference */
    int snapped;             /* the reference rasterizes the core's snapped triangles */
    int math;                /* accuracy --math */
    int quiet;               /* render, bake --quiet: no progress line on stderr */
    int rgb565;              /* render --rgb565: each frame as the panel shows it */
    tarn_quality quality;
    int argc;                /* the whole command line, as given */
    char **argv;
} tarn_cli_options;

/* 0, or -1 with a one-line message in `err`. */
int tarn_cli_parse(int argc, char **argv, tarn_cli_options *options, tarn_error *err);

#define TARN_CLI_FRAMES_MAX 10000u

/* The most pixels (frames times width times height) one GIF chooses its palette
 * over: 7 bytes each while it does (the frames, the palette's work, the indices),
 * so about 1 GB; 10 s of a 240x240 scene at 30 frames a second is 17.3 M. */
#define TARN_CLI_GIF_PIXELS_MAX 150000000u

/* Whether render writes one animated GIF (-o NAME.gif) rather than PNG. */
int tarn_cli_writes_gif(const tarn_cli_options *options);
/* What --backdrop and --landing-depth ask to draw once. */
tarn_backdrop_request tarn_cli_backdrop(const tarn_cli_options *options);

/* The clock of frame `index`: time_ms + floor(index * 1000 / fps). */
uint32_t tarn_cli_frame_time(const tarn_cli_options *options, unsigned index);

/* argv[1] when it names one of the commands tarn_cli_parse reads, else NULL: for
 * the "try 'tarn render --help'" of a usage error. */
const char *tarn_cli_known_command(int argc, char **argv);

#endif
