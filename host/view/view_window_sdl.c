/* view_window_sdl.c: tarn view's window on SDL2 (view_window.h). */
#include "view_window.h"

#include <SDL.h>
#include <stdio.h>
#include <stdlib.h>

#include "view_options.h"

struct tarn_view_window {
    SDL_Window *window;
    SDL_Renderer *renderer;
    SDL_Texture *texture;
    int width, height; /* the frame the texture holds */
    unsigned scale;
};

static int sdl_failure(const char *what, tarn_error *err)
{
    return tarn_fail(err, "view: %s: %s", what, SDL_GetError());
}

static unsigned fitting_scale(int width, int height)
{
    const int side = width > height ? width : height;
    unsigned scale = side < TARN_VIEW_WINDOW_SIDE ? (unsigned)(TARN_VIEW_WINDOW_SIDE / side) : 1u;
    SDL_Rect usable;
    if (SDL_GetDisplayUsableBounds(0, &usable) == 0) {
        while (scale > 1 && ((int)scale * width > usable.w || (int)scale * height > usable.h)) scale--;
    }
    return scale < TARN_VIEW_SCALE_MAX ? scale : TARN_VIEW_SCALE_MAX;
}

/* A texture for width x height frames, and the window sized to show it. */
static int fit_texture(tarn_view_window *w, int width, int height, tarn_error *err)
{
    if (w->texture != NULL && w->width == width && w->height == height) return 0;
    if (w->texture != NULL) SDL_DestroyTexture(w->texture);
    w->texture = SDL_CreateTexture(w->renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING, width, height);
    if (w->texture == NULL) return sdl_failure("cannot make a texture", err);
    w->width = width;
    w->height = height;
    SDL_SetWindowSize(w->window, width * (int)w->scale, height * (int)w->scale);
    SDL_RenderSetLogicalSize(w->renderer, width * (int)w->scale, height * (int)w->scale);
    return 0;
}

/* SDL on the display the environment names, Wayland's or X's: left to itself, SDL
 * falls back on drivers no one sees when that display cannot be reached.
 * SDL_VIDEODRIVER, when set, is the user's choice and SDL's to follow. */
static int open_display(tarn_error *err)
{
    const char *asked = getenv("SDL_VIDEODRIVER"), *wayland = getenv("WAYLAND_DISPLAY"), *x = getenv("DISPLAY");
    if (asked != NULL && asked[0] != '\0')
        return SDL_Init(SDL_INIT_VIDEO) == 0 ? 0 : sdl_failure("cannot open the display", err);
    /* libwayland finds a relative socket name in XDG_RUNTIME_DIR, and says so on
     * stderr itself when that is not set */
    const char *runtime = getenv("XDG_RUNTIME_DIR");
    if (wayland != NULL && wayland[0] != '\0' && (wayland[0] == '/' || (runtime != NULL && runtime[0] != '\0'))) {
        SDL_SetHint(SDL_HINT_VIDEODRIVER, "wayland");
        if (SDL_Init(SDL_INIT_VIDEO) == 0) return 0;
    }
    if (x != NULL && x[0] != '\0') {
        SDL_SetHint(SDL_HINT_VIDEODRIVER, "x11");
        if (SDL_Init(SDL_INIT_VIDEO) == 0) return 0;
    }
    const char *why = SDL_GetError()[0] != '\0' ? SDL_GetError() : "XDG_RUNTIME_DIR, which holds its socket, is not set";
    return tarn_fail(err, "view: cannot open the display %s: %s", x != NULL && x[0] ? x : wayland, why);
}

int tarn_view_window_open(const char *title, int width, int height, unsigned scale, tarn_view_window **out,
                          tarn_error *err)
{
    *out = NULL;
    if (open_display(err) != 0) return -1;
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "0"); /* whole pixels, no smoothing */
    tarn_view_window *w = calloc(1, sizeof *w);
    if (w == NULL) return tarn_fail(err, "view: out of memory");
    w->scale = scale ? scale : fitting_scale(width, height);
    w->window = SDL_CreateWindow(title, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width * (int)w->scale,
                                 height * (int)w->scale, 0);
    if (w->window != NULL) w->renderer = SDL_CreateRenderer(w->window, -1, 0);
    if (w->window == NULL || w->renderer == NULL || fit_texture(w, width, height, err) != 0) {
        const int failed = w->window == NULL || w->renderer == NULL ? sdl_failure("cannot open a window", err) : -1;
        tarn_view_window_close(w);
        return failed;
    }
    *out = w;
    return 0;
}

/* The window's pixels as the renderer holds them before they are presented. */
static int capture_pixels(tarn_view_window *w, uint8_t **capture, int *cw, int *ch, tarn_error *err)
{
    if (SDL_GetRendererOutputSize(w->renderer, cw, ch) != 0) return sdl_failure("cannot read the window", err);
    *capture = malloc(3u * (size_t)*cw * (size_t)*ch);
    if (*capture == NULL) return tarn_fail(err, "view: out of memory for a screenshot");
    if (SDL_RenderReadPixels(w->renderer, NULL, SDL_PIXELFORMAT_RGB24, *capture, 3 * *cw) != 0) {
        free(*capture);
        *capture = NULL;
        return sdl_failure("cannot read the window", err);
    }
    return 0;
}

int tarn_view_window_show(tarn_view_window *w, const uint8_t *rgb, int width, int height, uint8_t **capture,
                          int *capture_width, int *capture_height, tarn_error *err)
{
    if (rgb != NULL) {
        if (fit_texture(w, width, height, err) != 0) return -1;
        if (SDL_UpdateTexture(w->texture, NULL, rgb, 3 * width) != 0) return sdl_failure("cannot show the frame", err);
    }
    SDL_RenderClear(w->renderer);
    SDL_RenderCopy(w->renderer, w->texture, NULL, NULL);
    if (capture != NULL && capture_pixels(w, capture, capture_width, capture_height, err) != 0) return -1;
    SDL_RenderPresent(w->renderer);
    return 0;
}

void tarn_view_window_title(tarn_view_window *w, const char *title)
{
    SDL_SetWindowTitle(w->window, title);
}

static void apply_event(const SDL_Event *e, tarn_view_state *state)
{
    if (e->type == SDL_QUIT) state->quit = 1;
    else if (e->type == SDL_KEYDOWN) {
        const tarn_view_key *key = tarn_view_find_key(SDL_GetKeyName(e->key.keysym.sym));
        if (key != NULL) tarn_view_press(state, key);
    } else if (e->type == SDL_MOUSEMOTION && (e->motion.state & SDL_BUTTON_LMASK))
        tarn_view_drag(state, e->motion.xrel, e->motion.yrel);
    else if (e->type == SDL_MOUSEWHEEL)
        tarn_view_wheel(state, e->wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -e->wheel.y : e->wheel.y);
}

int tarn_view_window_events(tarn_view_window *w, tarn_view_state *state, int wait_ms)
{
    (void)w;
    SDL_Event e;
    int count = 0;
    if (wait_ms > 0 && SDL_WaitEventTimeout(&e, wait_ms)) {
        apply_event(&e, state);
        count++;
    }
    while (SDL_PollEvent(&e)) {
        apply_event(&e, state);
        count++;
    }
    return count;
}

static void push_button(tarn_view_window *w, Uint32 type)
{
    SDL_Event e = {0};
    e.button.type = type;
    e.button.windowID = SDL_GetWindowID(w->window);
    e.button.button = SDL_BUTTON_LEFT;
    e.button.state = type == SDL_MOUSEBUTTONDOWN ? SDL_PRESSED : SDL_RELEASED;
    SDL_PushEvent(&e);
}

void tarn_view_window_push(tarn_view_window *w, const tarn_script_event *event)
{
    SDL_Event e = {0};
    if (event->kind == TARN_SCRIPT_KEY) {
        e.key.type = SDL_KEYDOWN;
        e.key.windowID = SDL_GetWindowID(w->window);
        e.key.state = SDL_PRESSED;
        e.key.keysym.sym = SDL_GetKeyFromName(event->key);
        SDL_PushEvent(&e);
    } else if (event->kind == TARN_SCRIPT_DRAG) {
        push_button(w, SDL_MOUSEBUTTONDOWN);
        e.motion.type = SDL_MOUSEMOTION;
        e.motion.windowID = SDL_GetWindowID(w->window);
        e.motion.state = SDL_BUTTON_LMASK;
        e.motion.xrel = event->dx;
        e.motion.yrel = event->dy;
        SDL_PushEvent(&e);
        push_button(w, SDL_MOUSEBUTTONUP);
    } else if (event->kind == TARN_SCRIPT_WHEEL) {
        e.wheel.type = SDL_MOUSEWHEEL;
        e.wheel.windowID = SDL_GetWindowID(w->window);
        e.wheel.y = event->dy;
        e.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
        SDL_PushEvent(&e);
    }
}

/* The window goes; SDL itself stays until the process ends, which closes its
 * connection to the display as SDL_Quit would. SDL_Quit would also unload the
 * X libraries SDL opened, and the sanitizer build's leak check could then no
 * longer name what those libraries keep to the end (tests/view.lsan). */
void tarn_view_window_close(tarn_view_window *w)
{
    if (w == NULL) return;
    if (w->texture) SDL_DestroyTexture(w->texture);
    if (w->renderer) SDL_DestroyRenderer(w->renderer);
    if (w->window) SDL_DestroyWindow(w->window);
    free(w);
}

const char *tarn_view_window_backend(void)
{
    static char text[32];
    SDL_version v;
    SDL_GetVersion(&v);
    snprintf(text, sizeof text, "sdl2-%u.%u.%u", v.major, v.minor, v.patch);
    return text;
}
