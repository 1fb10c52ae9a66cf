/* view_window.h: tarn view's window: the one place that calls SDL2
 * (view_window_sdl.c; view_window_none.c in a build without libsdl2-dev).
 *
 * A frame is shown scaled up by a whole factor with no smoothing, so each frame
 * pixel is a square of identical window pixels. Keys, drags of the left button and
 * the wheel go to the view's state (view_state.h); a script's events are pushed
 * into the same queue, so they take the same path. */
#ifndef TARN_HOST_VIEW_WINDOW_H
#define TARN_HOST_VIEW_WINDOW_H

#include <stdint.h>
#include "error.h"
#include "view_script.h"
#include "view_state.h"

typedef struct tarn_view_window tarn_view_window;

/* The largest window side the default scale aims at, in window pixels. */
#define TARN_VIEW_WINDOW_SIDE 720

/* Opens a window for width x height frames, each pixel `scale` window pixels
 * each way (0: the most, up to TARN_VIEW_SCALE_MAX, that keeps the window within
 * TARN_VIEW_WINDOW_SIDE and the display). 0, or -1 with `err` set. */
int tarn_view_window_open(const char *title, int width, int height, unsigned scale, tarn_view_window **out,
                          tarn_error *err);

/* Shows `rgb` (width*height*3, R G B), or again what it showed last when `rgb` is
 * NULL. With `capture` set, *capture receives the window's pixels as shown
 * (malloc'd, *capture_width x *capture_height, R G B). 0, or -1 with `err` set. */
int tarn_view_window_show(tarn_view_window *w, const uint8_t *rgb, int width, int height, uint8_t **capture,
                          int *capture_width, int *capture_height, tarn_error *err);

void tarn_view_window_title(tarn_view_window *w, const char *title);

/* Every event waiting, applied to `state`, after waiting up to `wait_ms` for the
 * first; returns how many there were. */
int tarn_view_window_events(tarn_view_window *w, tarn_view_state *state, int wait_ms);

/* A script's key, drag or wheel, into the window's event queue. */
void tarn_view_window_push(tarn_view_window *w, const tarn_script_event *event);

void tarn_view_window_close(tarn_view_window *w);

/* "sdl2-2.26.5" in a build with SDL2, else "none": for tarn --version. */
const char *tarn_view_window_backend(void);

#endif
