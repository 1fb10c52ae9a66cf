/* view.c: tarn view's loop (view.h): events, edits, the picture, the window. */
#include "view.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "clock.h"
#include "frame_path.h"
#include "option_values.h"
#include "png_io.h"
#include "scene_load.h"
#include "view_camera.h"
#include "view_frame.h"
#include "view_options.h"
#include "view_script.h"
#include "view_text.h"
#include "view_watch.h"
#include "view_window.h"

/* How often a hand's view looks for edits, and measures the picture on the
 * yardstick while the clock runs (a measure takes about as long as 5 frames). */
#define WATCH_PERIOD_MS 250
#define MEASURE_PERIOD_MS 1000
/* The longest a view at rest sleeps between looks at its events and files. */
#define IDLE_WAIT_MS 50
#define FRAME_PERIOD_MS 16.0

typedef struct {
    const tarn_view_options *options;
    tarn_loaded_scene scene;  /* the last scene that loaded */
    tarn_view_watch watch;
    tarn_view_state state;
    tarn_view_frame frame;
    tarn_view_window *window;
    tarn_script script;
    int scripted;
    uint32_t frame_number;    /* frames drawn (a script's clock) */
    int waiting_for_edit;
    int edit_seen;            /* this turn ended a wait: its frame is drawn again */
    int screenshot_due, quit_after_frame;
    /* what the title shows, until it is put right: a bad edit until the scene
     * loads again, a picture the core refused until one is drawn */
    char edit_error[TARN_ERROR_MESSAGE_MAX], draw_error[TARN_ERROR_MESSAGE_MAX];
    int have_numbers;
    uint32_t measured_at_ms;
    int camera_chosen;        /* --camera or the mouse chose the last picture's camera, */
    tarn_camera drawn_camera; /* which was this */
    double last_measure, last_watch, last_title; /* wall-clock ms */
} view_session;

/* The monotonic clock in ms. */
static double now_ms(void)
{
    return 1e3 * tarn_clock_seconds();
}

/* The error the title leads with, or "". */
static const char *shown_error(const view_session *v)
{
    return v->edit_error[0] ? v->edit_error : v->draw_error;
}

static int report(const tarn_error *err)
{
    fprintf(stderr, "tarn: %s\n", err->message);
    return TARN_EXIT_BAD_INPUT;
}

/* SDL would find no display and say so less plainly, or pick another driver. */
static int check_display(tarn_error *err)
{
    const char *names[] = {"SDL_VIDEODRIVER", "DISPLAY", "WAYLAND_DISPLAY"};
    for (int k = 0; k < 3; k++) {
        const char *value = getenv(names[k]);
        if (value != NULL && value[0] != '\0') return 0;
    }
    return tarn_fail(err, "view: no display: DISPLAY and WAYLAND_DISPLAY are not set (over SSH, connect with "
                     "'ssh -X'; without a screen, run it under xvfb-run with --script and --screenshot)");
}

static int load_scene(view_session *v, tarn_loaded_scene *out, tarn_error *err)
{
    if (tarn_scene_load(v->options->scene_path, out, err) != 0) return -1;
    tarn_camera_override_apply(&v->options->camera, &out->scene);
    return 0;
}

/* The scene file or a texture changed: the new scene if it loads, else its error
 * and the last good scene kept. */
static void reload(view_session *v)
{
    tarn_loaded_scene next;
    tarn_error err;
    if (load_scene(v, &next, &err) != 0) {
        snprintf(v->edit_error, sizeof v->edit_error, "%s", err.message);
        report(&err); /* on stderr too, whole, beside the title that may cut it */
        return;
    }
    tarn_scene_free(&v->scene);
    v->scene = next;
    v->edit_error[0] = '\0';
    tarn_view_watch_set(&v->watch, v->options->scene_path, &v->scene);
}

/* Whether a watched file changed (and the scene was read again). */
static int look_for_edits(view_session *v)
{
    const double now = now_ms();
    if (!v->scripted && !v->waiting_for_edit && now - v->last_watch < WATCH_PERIOD_MS) return 0;
    v->last_watch = now;
    if (!tarn_view_watch_changed(&v->watch)) return 0;
    reload(v);
    v->edit_seen = v->waiting_for_edit;
    v->waiting_for_edit = 0;
    return 1;
}

/* The script's events due at this frame: keys and the mouse into the window's
 * queue, the rest marked for this frame. */
static void run_script(view_session *v)
{
    const tarn_script_event *e;
    while (!v->waiting_for_edit && (e = tarn_script_take(&v->script, v->frame_number)) != NULL) {
        if (e->kind == TARN_SCRIPT_SCREENSHOT) v->screenshot_due = 1;
        else if (e->kind == TARN_SCRIPT_WAIT_EDIT) v->waiting_for_edit = 1;
        else if (e->kind == TARN_SCRIPT_QUIT) v->quit_after_frame = 1;
        else tarn_view_window_push(v->window, e);
    }
    if (tarn_script_done(&v->script) && !v->waiting_for_edit) v->quit_after_frame = 1;
}

static tarn_frame_config frame_config(const view_session *v)
{
    tarn_frame_config config;
    config.width = v->options->width ? v->options->width : v->scene.width;
    config.height = v->options->height ? v->options->height : v->scene.height;
    config.quality = v->state.quality;
    config.time_ms = tarn_view_time_ms(&v->state);
    return config;
}

/* The scene as drawn now: the mouse's camera in place of the scene's, when it
 * has moved one. */
static int scene_to_draw(const view_session *v, uint32_t time_ms, tarn_scene *out, tarn_error *err)
{
    *out = v->scene.scene;
    if (tarn_view_own_camera(&v->state)) return 0;
    if (tarn_view_camera(&v->scene.scene, time_ms, v->state.yaw_degrees, v->state.pitch_degrees, v->state.zoom,
                         &out->camera, err) != 0)
        return -1;
    out->camera_path = NULL;
    return 0;
}

/* Whether this frame is measured on the yardstick: a screenshot's, and a hand's
 * view at rest or once a second. */
static int measure_now(view_session *v)
{
    if (v->scripted) return v->screenshot_due;
    const double now = now_ms();
    if (!v->state.paused && now - v->last_measure < MEASURE_PERIOD_MS) return 0;
    v->last_measure = now;
    return 1;
}

/* The picture into the window; a failure shows what it showed, and the error. */
static void draw(view_session *v, uint8_t **capture, int *cw, int *ch)
{
    tarn_error err;
    const tarn_frame_config config = frame_config(v);
    tarn_scene scene;
    const int measure = measure_now(v);
    int failed = scene_to_draw(v, config.time_ms, &scene, &err) ||
                 tarn_view_frame_draw(&v->frame, &scene, v->scene.name, &config, v->state.picture, v->state.panel,
                                      measure, &err);
    if (failed) snprintf(v->draw_error, sizeof v->draw_error, "%s", err.message);
    else {
        v->draw_error[0] = '\0';
        v->camera_chosen = !tarn_view_own_camera(&v->state) || v->options->camera.given;
        v->drawn_camera = scene.camera;
        if (v->frame.measured) {
            v->have_numbers = 1;
            v->measured_at_ms = config.time_ms;
        }
    }
    if (tarn_view_window_show(v->window, failed ? NULL : v->frame.shown, v->frame.width, v->frame.height, capture,
                              cw, ch, &err) != 0)
        snprintf(v->draw_error, sizeof v->draw_error, "%s", err.message);
}

/* The command that draws the picture now, to `output`: with --camera when the
 * camera is not the scene's own. */
static void picture_command(const view_session *v, const char *output, char *out, size_t size)
{
    const tarn_frame_config config = frame_config(v);
    tarn_view_command(v->options->scene_path, &v->state, config.width, config.height,
                      v->camera_chosen ? &v->drawn_camera : NULL, output, out, size);
}

/* A script's screenshot: the window's pixels to OUT-FRAME.png, and a line on
 * stdout with the command that draws the same picture (scaled down). */
static int save_screenshot(view_session *v, const uint8_t *pixels, int width, int height, tarn_error *err)
{
    char path[4096], command[TARN_VIEW_TEXT_MAX];
    const int alone = !v->scripted;
    if (alone) snprintf(path, sizeof path, "%s", v->options->screenshot_path);
    else if (tarn_frame_path(v->options->screenshot_path, v->frame_number, path, sizeof path) != 0)
        return tarn_fail(err, "--screenshot: '%s' is too long for a frame's file name", v->options->screenshot_path);
    if (tarn_png_write_rgb(path, pixels, width, height, err) != 0) return -1;
    picture_command(v, "OUT.png", command, sizeof command);
    printf("view screenshot=%s frame=%lu time=%lu scale=%d error=%s command=%s\n", path,
           (unsigned long)v->frame_number, (unsigned long)tarn_view_time_ms(&v->state), width / v->frame.width,
           shown_error(v)[0] ? "yes" : "no", command);
    fflush(stdout);
    return 0;
}

static void update_title(view_session *v)
{
    const double now = now_ms();
    if (!v->scripted && now - v->last_title < 250) return;
    v->last_title = now;
    char title[TARN_VIEW_TEXT_MAX];
    const tarn_view_title_parts parts = {v->scene.name, &v->state, &v->frame, v->measured_at_ms, v->have_numbers,
                                         shown_error(v)};
    tarn_view_title(&parts, title, sizeof title);
    tarn_view_window_title(v->window, title);
    if (v->scripted && v->screenshot_due) printf("view title=%s\n", title);
}

static void print_requests(view_session *v)
{
    if (v->state.print_command) {
        char command[TARN_VIEW_TEXT_MAX];
        picture_command(v, "OUT.png", command, sizeof command);
        printf("%s\n", command);
        v->state.print_command = 0;
    }
    if (v->state.print_keys) {
        char keys[2048];
        tarn_view_key_help(keys, sizeof keys);
        printf("keys:\n%s", keys);
        v->state.print_keys = 0;
    }
    fflush(stdout);
}

/* A hand's clock runs with the wall clock; a script's a frame a turn, but not
 * while it waits for an edit, nor on the turn the edit came, so that the events
 * after the wait are at their frame. */
static void advance_clock(view_session *v, double *last_tick)
{
    if (v->scripted) {
        if (!v->waiting_for_edit && !v->edit_seen) {
            tarn_view_run_frame(&v->state);
            v->frame_number++;
        }
        v->edit_seen = 0;
        return;
    }
    const double now = now_ms();
    const uint32_t elapsed = (uint32_t)(now - *last_tick);
    tarn_view_run_ms(&v->state, elapsed);
    *last_tick += elapsed;
}

/* The screenshot this frame asked for, from the pixels the window showed. */
static int take_screenshot(view_session *v, uint8_t *capture, int width, int height, tarn_error *err)
{
    if (capture == NULL) return tarn_fail(err, "%s", v->draw_error);
    const int failed = save_screenshot(v, capture, width, height, err);
    free(capture);
    v->screenshot_due = 0;
    return failed;
}

/* Turns of events, edits, the picture and the clock until the view ends: 0, or
 * -1 with `err` set when a screenshot cannot be taken. */
static int run(view_session *v, tarn_error *err)
{
    double last_tick = now_ms();
    int changed = 1;
    while (!v->state.quit) {
        const double start = now_ms();
        if (v->scripted) run_script(v);
        const int resting = !v->scripted && v->state.paused && !changed;
        changed = tarn_view_window_events(v->window, &v->state, resting || v->waiting_for_edit ? IDLE_WAIT_MS : 0) > 0;
        changed |= look_for_edits(v);
        const int shoot = v->screenshot_due || (!v->scripted && v->options->screenshot_path != NULL);
        uint8_t *capture = NULL;
        int width = 0, height = 0;
        if (changed || !resting) draw(v, shoot ? &capture : NULL, &width, &height);
        update_title(v);
        if (shoot && take_screenshot(v, capture, width, height, err) != 0) return -1;
        print_requests(v);
        if (v->quit_after_frame || (!v->scripted && v->options->screenshot_path != NULL)) break;
        advance_clock(v, &last_tick);
        const double spent = now_ms() - start;
        if (!v->scripted && !v->state.paused && spent < FRAME_PERIOD_MS) /* no faster than the screen */
            changed |= tarn_view_window_events(v->window, &v->state, (int)(FRAME_PERIOD_MS - spent)) > 0;
    }
    return 0;
}

static int start(view_session *v, tarn_error *err)
{
    const tarn_view_options *o = v->options;
    if (load_scene(v, &v->scene, err) != 0) return -1;
    v->scripted = o->script_path != NULL;
    if (v->scripted && tarn_script_load(o->script_path, &v->script, err) != 0) return -1;
    for (size_t k = 0; k < v->script.count; k++)
        if (v->script.events[k].kind == TARN_SCRIPT_SCREENSHOT && o->screenshot_path == NULL)
            return tarn_fail(err, "%s: the script takes screenshots: add --screenshot OUT.png", o->script_path);
    tarn_view_state_init(&v->state, &o->quality, o->preset, o->time_ms, o->fps);
    if (tarn_view_watch_set(&v->watch, o->scene_path, &v->scene) != 0) return tarn_fail(err, "view: out of memory");
    const tarn_frame_config config = frame_config(v);
    return tarn_view_window_open("tarn view", config.width, config.height, o->scale, &v->window, err);
}

static void finish(view_session *v)
{
    if (v->window != NULL) tarn_view_window_close(v->window);
    tarn_view_frame_free(&v->frame);
    tarn_view_watch_free(&v->watch);
    tarn_script_free(&v->script);
    tarn_scene_free(&v->scene);
    free(v);
}

int tarn_command_view(int argc, char **argv)
{
    tarn_view_options options;
    tarn_error err;
    if (tarn_view_parse(argc, argv, &options, &err) != 0) return tarn_usage_error("view", &err);
    if (check_display(&err) != 0) return report(&err);
    view_session *v = calloc(1, sizeof *v);
    if (v == NULL) return report((tarn_fail(&err, "view: out of memory"), &err));
    v->options = &options;
    const int status = start(v, &err) != 0 || run(v, &err) != 0 ? report(&err) : 0;
    finish(v);
    return status;
}
