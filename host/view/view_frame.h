/* view_frame.h: one picture of tarn view: the core's frame, timed, and what the
 * window shows of it (the frame, the float reference or the error heat map, each
 * through the panel's RGB565 or not), with the compare line's numbers when asked. */
#ifndef TARN_HOST_VIEW_FRAME_H
#define TARN_HOST_VIEW_FRAME_H

#include <stdint.h>
#include "error.h"
#include "view_state.h"
#include "yardstick.h"

typedef struct {
    int width, height;
    uint8_t *core;    /* width*height*3: the core's frame, RGB888 */
    uint8_t *shown;   /* width*height*3: the picture the window shows */
    uint8_t *marks;   /* width*height: 1 where the surface differs from the reference's */
    tarn_continuous_reference reference; /* drawn for the reference, the heat map and a measure */
    double core_ms;   /* the core's frame, in wall-clock ms on this machine */
    int measured;     /* `error` holds this picture's numbers */
    tarn_yardstick error;
} tarn_view_frame;

/* Draws `picture` of `scene` (named `name`) at `config` into `f`, its buffers sized
 * to the config; measures it on the yardstick when `measure` is set (always for
 * the heat map, which is that measure's picture). 0, or -1 with `err` set (the
 * window keeps what it showed: it is given `shown` only after a success). */
int tarn_view_frame_draw(tarn_view_frame *f, const tarn_scene *scene, const char *name,
                         const tarn_frame_config *config, tarn_view_picture picture, int panel, int measure,
                         tarn_error *err);

void tarn_view_frame_free(tarn_view_frame *f);

#endif
