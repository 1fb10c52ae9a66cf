/* view_text.h: what tarn view says: its window's title, and the tarn command that
 * draws the picture it shows (printed for a screenshot and for the C key). */
#ifndef TARN_HOST_VIEW_TEXT_H
#define TARN_HOST_VIEW_TEXT_H

#include <stddef.h>
#include "error.h"
#include "tarn/tarn_scene.h"
#include "view_frame.h"
#include "view_state.h"

/* Room for a title or a command. */
#define TARN_VIEW_TEXT_MAX (TARN_ERROR_MESSAGE_MAX + 4096)

/* What the title shows:
 *   tarn view: pond | balanced | 1.233 s x1 | core 3.1 ms | psnr 34.81 shading 59.36 panel 57.49 (at 1.200 s)
 * then "paused", the picture other than the core's, "RGB565"; an error (a bad
 * edit, a camera or knob that cannot be drawn) first of all. */
typedef struct {
    const char *scene_name;
    const tarn_view_state *state;
    const tarn_view_frame *frame;
    uint32_t measured_at_ms; /* the clock of the numbers frame->error holds */
    int have_numbers;
    const char *error;       /* NULL or "" when none */
} tarn_view_title_parts;

void tarn_view_title(const tarn_view_title_parts *parts, char *out, size_t size);

/* The command that draws the picture to `output`:
 *   tarn render SCENE --size WxH --time MS [--camera ...] QUALITY [--reference] [--rgb565] -o OUTPUT
 * or for the heat map, tarn compare ... --diff OUTPUT. `camera` is NULL for the
 * scene's own. */
void tarn_view_command(const char *scene_path, const tarn_view_state *state, int width, int height,
                       const tarn_camera *camera, const char *output, char *out, size_t size);

#endif
