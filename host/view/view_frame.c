/* view_frame.c: the picture tarn view shows (view_frame.h). */
#include "view_frame.h"

#include <stdlib.h>
#include <string.h>
#include "clock.h"
#include "compare.h"
#include "core_render.h"

/* The buffers for a width x height picture: 0, or -1 with `err` set. */
static int fit_buffers(tarn_view_frame *f, int width, int height, tarn_error *err)
{
    if (f->width == width && f->height == height && f->core != NULL) return 0;
    tarn_view_frame_free(f);
    const size_t pixels = (size_t)width * (size_t)height;
    f->core = malloc(3 * pixels);
    f->shown = malloc(3 * pixels);
    f->marks = malloc(pixels);
    if (f->core == NULL || f->shown == NULL || f->marks == NULL) {
        tarn_view_frame_free(f);
        return tarn_fail(err, "out of memory for a %dx%d picture", width, height);
    }
    f->width = width;
    f->height = height;
    return 0;
}

static int draw_reference_and_measure(tarn_view_frame *f, const tarn_scene *scene, const char *name,
                                      const tarn_frame_config *config, int measure, tarn_error *err)
{
    tarn_continuous_reference_free(&f->reference);
    if (tarn_continuous_reference_render(scene, name, f->width, f->height, config->time_ms, &f->reference, err))
        return -1;
    if (!measure) return 0;
    if (tarn_yardstick_measure(scene, name, config, f->core, &f->reference, &f->error, f->marks, err)) return -1;
    f->measured = 1;
    return 0;
}

int tarn_view_frame_draw(tarn_view_frame *f, const tarn_scene *scene, const char *name,
                         const tarn_frame_config *config, tarn_view_picture picture, int panel, int measure,
                         tarn_error *err)
{
    if (fit_buffers(f, config->width, config->height, err) != 0) return -1;
    f->measured = 0;
    const double start = tarn_clock_seconds();
    if (tarn_core_render(scene, config, f->core, NULL, err) != 0) return -1;
    f->core_ms = 1e3 * (tarn_clock_seconds() - start);
    measure = measure || picture == TARN_VIEW_HEATMAP;
    if ((picture != TARN_VIEW_CORE || measure) && draw_reference_and_measure(f, scene, name, config, measure, err))
        return -1;
    const size_t bytes = 3u * (size_t)f->width * (size_t)f->height;
    if (picture == TARN_VIEW_HEATMAP)
        tarn_compare_heatmap(f->core, f->reference.rgb, f->marks, f->width, f->height, f->shown);
    else memcpy(f->shown, picture == TARN_VIEW_REFERENCE ? f->reference.rgb : f->core, bytes);
    if (panel && picture != TARN_VIEW_HEATMAP) tarn_as_panel_shows(f->shown, f->width, f->height, f->shown);
    return 0;
}

void tarn_view_frame_free(tarn_view_frame *f)
{
    free(f->core);
    free(f->shown);
    free(f->marks);
    tarn_continuous_reference_free(&f->reference);
    memset(f, 0, sizeof *f);
}
