/* view_script.h: a script of input events for `tarn view --script FILE`, so that a
 * view runs the same way every time (the Xvfb test, a headless render of what a
 * hand would do). One event a line, at a frame number; frames count from 0 and
 * the lines' frames never fall; `#` starts a comment:
 *   12 key Space          a key by SDL's name (view_state.h lists them)
 *   20 drag 40 -10        the left button dragged by 40, -10 window pixels
 *   24 wheel 2            the mouse wheel, two steps nearer (negative: farther)
 *   30 screenshot         the window as it shows this frame, to --screenshot's name
 *   31 wait-edit          the script (and the clock) wait until the scene file changes
 *   40 quit
 * Keys and the mouse go through the window's own event queue, as a hand's do. */
#ifndef TARN_HOST_VIEW_SCRIPT_H
#define TARN_HOST_VIEW_SCRIPT_H

#include <stddef.h>
#include <stdint.h>
#include "error.h"

typedef enum {
    TARN_SCRIPT_KEY,
    TARN_SCRIPT_DRAG,
    TARN_SCRIPT_WHEEL,
    TARN_SCRIPT_SCREENSHOT,
    TARN_SCRIPT_WAIT_EDIT,
    TARN_SCRIPT_QUIT
} tarn_script_event_kind;

typedef struct {
    uint32_t frame;
    tarn_script_event_kind kind;
    char key[16];   /* TARN_SCRIPT_KEY: a name tarn_view_find_key knows */
    int dx, dy;     /* TARN_SCRIPT_DRAG; dy the steps of TARN_SCRIPT_WHEEL */
} tarn_script_event;

#define TARN_SCRIPT_EVENTS_MAX 4096u
#define TARN_SCRIPT_FILE_BYTES_MAX (256u * 1024u)
/* A frame past which a script cannot wait: about 9 hours at 30 frames a second. */
#define TARN_SCRIPT_FRAME_MAX 999999u

typedef struct {
    tarn_script_event *events;
    size_t count;
    size_t next;    /* the first event not yet run */
} tarn_script;

/* 0, or -1 with "FILE:LINE: expected ..." in `err` and nothing to free. */
int tarn_script_load(const char *path, tarn_script *out, tarn_error *err);
void tarn_script_free(tarn_script *script);

/* The next event if it is due at `frame`, else NULL; taking it moves on. */
const tarn_script_event *tarn_script_take(tarn_script *script, uint32_t frame);

/* Whether the script has an event left (the view quits at the end of one that
 * does not say quit, after its last event's frame). */
int tarn_script_done(const tarn_script *script);

#endif
