/* view_state.h: what `tarn view` shows, and how keys, the mouse and the clock
 * change it; no window here (view_window.h turns events into these calls), so
 * the same state runs under a script and a hand.
 *
 * The clock counts in units of 1/(16 * fps) ms, so that a frame of the view's fps
 * at every speed from 1/16 to 16 is a whole number of units: under a script, frame
 * k at speed 1 is at start + floor(k * 1000 / fps) ms, as render --frames puts it. */
#ifndef TARN_HOST_VIEW_STATE_H
#define TARN_HOST_VIEW_STATE_H

#include <stddef.h>
#include <stdint.h>
#include "tarn/tarn_render.h"

/* Which picture the window shows. */
typedef enum {
    TARN_VIEW_CORE,      /* the integer core's frame */
    TARN_VIEW_REFERENCE, /* the float reference, vertices on no grid */
    TARN_VIEW_HEATMAP    /* the core's error against it: tarn compare --diff */
} tarn_view_picture;

/* What a key does (view_state.c's table names the key of each). */
typedef enum {
    TARN_VIEW_PAUSE,
    TARN_VIEW_STEP_ON,
    TARN_VIEW_STEP_BACK,
    TARN_VIEW_SLOWER,
    TARN_VIEW_FASTER,
    TARN_VIEW_RESET_CAMERA,
    TARN_VIEW_NEXT_PICTURE,
    TARN_VIEW_PANEL,
    TARN_VIEW_FAST,
    TARN_VIEW_BALANCED,
    TARN_VIEW_EXACT,
    TARN_VIEW_KNOB,          /* the next value of the key's knob */
    TARN_VIEW_PRINT_COMMAND, /* the render command of the picture, on stdout */
    TARN_VIEW_PRINT_KEYS,
    TARN_VIEW_QUIT
} tarn_view_action;

/* A key and what it does; `option` names the knob a TARN_VIEW_KNOB key cycles
 * through `values` (a NULL-ended list of the option's words). */
typedef struct {
    const char *key;   /* SDL's name of the key: "Space", "Right", "1", "B" */
    tarn_view_action action;
    const char *option;
    const char *const *values;
    const char *meaning;
} tarn_view_key;

/* The key named `name` (SDL's names, any case), or NULL. */
const tarn_view_key *tarn_view_find_key(const char *name);
/* Every key, one line each, for --help and the H key. */
void tarn_view_key_help(char *out, size_t size);

#define TARN_VIEW_SPEED_LOG2_MIN (-4)
#define TARN_VIEW_SPEED_LOG2_MAX 4

typedef struct {
    /* the clock */
    uint32_t start_ms;
    uint8_t fps;
    uint64_t clock_units;     /* since start_ms; 1 ms = 16 * fps units */
    int speed_log2;           /* the clock runs 2^speed_log2 times real time */
    int paused;
    /* the camera: the scene's own turned about its target; 0, 0, 1 leave it */
    double yaw_degrees, pitch_degrees, zoom;
    /* the quality, and the preset it started from */
    tarn_quality quality;
    tarn_preset preset;
    tarn_view_picture picture;
    int panel;                /* through the panel's RGB565 and dither */
    int quit;
    int print_command, print_keys; /* asked for, until the view prints them */
    const char *message;      /* a knob value that cannot be used, until the next key */
} tarn_view_state;

/* `quality` as the command line gave it, `preset` the --quality it started from. */
void tarn_view_state_init(tarn_view_state *s, const tarn_quality *quality, tarn_preset preset, uint32_t start_ms,
                          uint8_t fps);
void tarn_view_press(tarn_view_state *s, const tarn_view_key *key);
/* A drag of the left button by dx, dy window pixels: the camera turns about its
 * target, a quarter of a degree a pixel. */
void tarn_view_drag(tarn_view_state *s, int dx, int dy);
/* Mouse wheel steps: each one 10% nearer (up) or farther (down). */
void tarn_view_wheel(tarn_view_state *s, int steps);
/* The clock moved by `elapsed_ms` of real time (a hand) or one frame (a script);
 * nothing while paused. */
void tarn_view_run_ms(tarn_view_state *s, uint32_t elapsed_ms);
void tarn_view_run_frame(tarn_view_state *s);
/* The frame's clock: start_ms + the units run, held at UINT32_MAX. */
uint32_t tarn_view_time_ms(const tarn_view_state *s);
/* Whether the camera is the scene's own. */
int tarn_view_own_camera(const tarn_view_state *s);
/* "balanced", or "balanced, --water-block 2 --apron off" once knobs moved. */
void tarn_view_quality_text(const tarn_view_state *s, char *out, size_t size);

#endif
