/* view_window_none.c: tarn view in a build without SDL2 (view_window.h): opening
 * the window says how to get one. */
#include "view_window.h"

int tarn_view_window_open(const char *title, int width, int height, unsigned scale, tarn_view_window **out,
                          tarn_error *err)
{
    (void)title, (void)width, (void)height, (void)scale;
    *out = NULL;
    return tarn_fail(err, "view: this tarn was built without SDL2; install it (apt-get install libsdl2-dev) "
                     "and build again");
}

int tarn_view_window_show(tarn_view_window *w, const uint8_t *rgb, int width, int height, uint8_t **capture,
                          int *capture_width, int *capture_height, tarn_error *err)
{
    (void)w, (void)rgb, (void)width, (void)height, (void)capture, (void)capture_width, (void)capture_height;
    return tarn_fail(err, "view: no window");
}

void tarn_view_window_title(tarn_view_window *w, const char *title)
{
    (void)w, (void)title;
}

int tarn_view_window_events(tarn_view_window *w, tarn_view_state *state, int wait_ms)
{
    (void)w, (void)state, (void)wait_ms;
    return 0;
}

void tarn_view_window_push(tarn_view_window *w, const tarn_script_event *event)
{
    (void)w, (void)event;
}

void tarn_view_window_close(tarn_view_window *w)
{
    (void)w;
}

const char *tarn_view_window_backend(void)
{
    return "none";
}
