/* view_text.c: tarn view's title and printed commands (view_text.h). */
#include "view_text.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "camera_override.h"
#include "quality_text.h"

/* printf onto the end of `out`, as far as it holds. */
static void append(char *out, size_t size, const char *format, ...)
{
    const size_t used = strlen(out);
    if (used + 1 >= size) return;
    va_list args;
    va_start(args, format);
    vsnprintf(out + used, size - used, format, args);
    va_end(args);
}

static const char *const picture_names[] = {"core", "reference", "heat map"};

void tarn_view_title(const tarn_view_title_parts *parts, char *out, size_t size)
{
    const tarn_view_state *s = parts->state;
    char quality[TARN_VIEW_TEXT_MAX];
    tarn_view_quality_text(s, quality, sizeof quality);
    out[0] = '\0';
    append(out, size, "tarn view: ");
    if (parts->error != NULL && parts->error[0] != '\0') append(out, size, "%s (the last good picture stays) | ", parts->error);
    if (s->message != NULL) append(out, size, "%s | ", s->message);
    const uint32_t t = tarn_view_time_ms(s);
    append(out, size, "%s | %s | %lu.%03lu s x%s%d%s", parts->scene_name, quality, (unsigned long)(t / 1000u),
           (unsigned long)(t % 1000u), s->speed_log2 < 0 ? "1/" : "", 1 << (s->speed_log2 < 0 ? -s->speed_log2 : s->speed_log2),
           s->paused ? " paused" : "");
    append(out, size, " | core %.1f ms", parts->frame->core_ms);
    if (parts->have_numbers) {
        const tarn_yardstick *y = &parts->frame->error;
        append(out, size, " | psnr %.2f shading %.2f panel %.2f (at %lu.%03lu s)", y->whole.psnr_db,
               y->shading.psnr_db, y->panel_psnr_db, (unsigned long)(parts->measured_at_ms / 1000u),
               (unsigned long)(parts->measured_at_ms % 1000u));
    }
    if (s->picture != TARN_VIEW_CORE) append(out, size, " | %s", picture_names[s->picture]);
    if (s->panel && s->picture != TARN_VIEW_HEATMAP) append(out, size, " | RGB565");
}

/* A word as a shell reads it back: quoted unless it is plain. */
static void append_word(char *out, size_t size, const char *word)
{
    if (word[0] != '\0' && strspn(word, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./,:+=") ==
                               strlen(word)) {
        append(out, size, " %s", word);
        return;
    }
    append(out, size, " '");
    for (const char *c = word; *c; c++) append(out, size, *c == '\'' ? "'\\''" : "%c", *c);
    append(out, size, "'");
}

void tarn_view_command(const char *scene_path, const tarn_view_state *s, int width, int height,
                       const tarn_camera *camera, const char *output, char *out, size_t size)
{
    char quality[TARN_QUALITY_TEXT_MAX];
    tarn_quality_text(&s->quality, quality, sizeof quality);
    out[0] = '\0';
    append(out, size, "tarn %s", s->picture == TARN_VIEW_HEATMAP ? "compare" : "render");
    append_word(out, size, scene_path);
    append(out, size, " --size %dx%d --time %lu", width, height, (unsigned long)tarn_view_time_ms(s));
    if (camera != NULL) {
        char text[TARN_CAMERA_TEXT_MAX];
        tarn_camera_override_text(camera, text, sizeof text);
        append(out, size, " --camera %s", text);
    }
    append(out, size, " %s", quality);
    if (s->picture == TARN_VIEW_HEATMAP) {
        append(out, size, " --diff");
    } else {
        if (s->picture == TARN_VIEW_REFERENCE) append(out, size, " --reference");
        if (s->panel) append(out, size, " --rgb565");
        append(out, size, " -o");
    }
    append_word(out, size, output);
}
