/* show.c: `tarn show` (show.h). */
#include "show.h"

#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "display.h"
#include "frame_sender.h"
#include "option_values.h"
#include "png_io.h"
#include "scene_load.h"
#include "show_options.h"

static volatile sig_atomic_t interrupted;

static void on_interrupt(int signal_number)
{
    (void)signal_number;
    interrupted = 1;
}

static int report(const tarn_error *err, int status)
{
    fprintf(stderr, "tarn: %s\n", err->message);
    return status;
}

/* ---- Rendering a frame into host memory, on its own thread ---- */

typedef struct {
    const tarn_scene *scene;
    tarn_frame_config config;
    void *memory;
    size_t memory_bytes;
    uint32_t *frame;        /* width x height, 0x00RRGGBB */
    tarn_status status;
} render_job;

static int store_tile(void *user, const tarn_tile *tile)
{
    render_job *job = user;
    for (uint16_t row = 0; row < tile->height; row++)
        memcpy(job->frame + (size_t)(tile->y + row) * job->config.width + tile->x,
               tile->rgb + (size_t)row * tile->stride, tile->width * sizeof *tile->rgb);
    return 0;
}

static void *render_job_run(void *arg)
{
    render_job *job = arg;
    job->status = tarn_render_frame(job->scene, &job->config, job->memory, job->memory_bytes, store_tile, job);
    return NULL;
}

/* ---- The run ---- */

typedef struct {
    const tarn_show_options *options;
    tarn_display display;
    tarn_frame_sender sender;
    render_job job;
    uint32_t *frames[2];
    tarn_link_counts after_init;
    uint32_t frames_sent;
    double wall_s;
} show_run;

static uint32_t frame_time(const tarn_show_options *o, uint32_t index)
{
    return o->time_ms + (uint32_t)((uint64_t)index * 1000u / o->fps);
}

static int render_into(show_run *r, uint32_t index, uint32_t *frame)
{
    r->job.config.time_ms = frame_time(r->options, index);
    r->job.frame = frame;
    render_job_run(&r->job);
    return r->job.status == TARN_OK ? 0 : -1;
}

/* Frame k goes out while frame k + 1 renders into the other buffer. */
static int animate(show_run *r, tarn_error *err)
{
    const tarn_show_options *o = r->options;
    double start = tarn_clock_seconds();
    for (uint32_t k = 0; (o->frames == 0 || k < o->frames) && !interrupted; k++) {
        int more = o->frames == 0 || k + 1 < o->frames;
        pthread_t renderer;
        if (more) {
            r->job.config.time_ms = frame_time(o, k + 1);
            r->job.frame = r->frames[(k + 1) & 1u];
            if (pthread_create(&renderer, NULL, render_job_run, &r->job) != 0) {
                more = 0; /* no thread: render after sending */
                r->job.frame = NULL;
            }
        }
        tarn_status sent = tarn_frame_sender_send(&r->sender, r->frames[k & 1u]);
        if (more) pthread_join(renderer, NULL);
        if (sent != TARN_OK) {
            r->wall_s = tarn_clock_seconds() - start;
            return tarn_fail(err, "%s", sent == TARN_ERR_SINK ? tarn_display_failure(&r->display)
                                                              : "a tile does not fit the panel");
        }
        r->frames_sent++;
        if ((o->frames == 0 || k + 1 < o->frames) && !more && render_into(r, k + 1, r->frames[(k + 1) & 1u]) != 0)
            return tarn_fail(err, "%s: render failed: %s", o->scene_path, tarn_status_text(r->job.status));
        if (more && r->job.status != TARN_OK)
            return tarn_fail(err, "%s: render failed: %s", o->scene_path, tarn_status_text(r->job.status));
    }
    r->wall_s = tarn_clock_seconds() - start;
    return 0;
}

static const char *link_name(tarn_display_kind kind)
{
    static const char *const names[] = {"panel", "spidev", "gpio-spi", "mcp2210"};
    return names[kind];
}

static const char *send_name(tarn_send_mode mode)
{
    static const char *const names[] = {"bands", "tiles", "changed"};
    return names[mode];
}

static void print_figures(const show_run *r)
{
    const tarn_show_options *o = r->options;
    const tarn_link_counts *c = r->display.counts;
    uint64_t bytes = c->spi_bytes - r->after_init.spi_bytes;
    uint64_t ns = c->link_ns - r->after_init.link_ns;
    uint32_t frames = r->frames_sent ? r->frames_sent : 1;
    uint64_t full_frame_bytes = 2u * (uint64_t)o->panel.width * o->panel.height + 11u; /* bands */
    printf("show panel=%s rotation=%u display=%s link=%s send=%s tile=%u frames=%u bytes_per_frame=%llu "
           "spi_bytes=%llu transfers=%llu busy=%llu tiles_sent=%llu tiles_skipped=%llu",
           o->panel_name, o->panel.rotation, o->display_text, link_name(r->display.link), send_name(o->send),
           o->quality.tile_size, r->frames_sent, (unsigned long long)(bytes / frames), (unsigned long long)bytes,
           (unsigned long long)(c->transfers - r->after_init.transfers),
           (unsigned long long)(c->busy_replies - r->after_init.busy_replies),
           (unsigned long long)r->sender.tiles_sent, (unsigned long long)r->sender.tiles_skipped);
    if (ns > 0)
        printf(" link_ms=%.1f link_bytes_per_s=%.0f link_fps=%.2f", (double)ns / 1e6, (double)bytes * 1e9 / (double)ns,
               (double)r->frames_sent * 1e9 / (double)ns);
    if (r->display.spi_hz > 0)
        printf(" ceiling_fps=%.1f", (double)r->display.spi_hz / (8.0 * (double)full_frame_bytes));
    printf(" wall_s=%.3f wall_bytes_per_s=%.0f wall_fps=%.2f\n", r->wall_s,
           r->wall_s > 0 ? (double)bytes / r->wall_s : 0.0, r->wall_s > 0 ? r->frames_sent / r->wall_s : 0.0);
    if (r->display.link == TARN_DISPLAY_GPIO_SPI && !r->display.emulated)
        fprintf(stderr, "tarn: gpio-spi is bit-banged through GPIO system calls: %.0f bytes/s measured here, "
                "far below a hardware SPI controller\n", r->wall_s > 0 ? (double)bytes / r->wall_s : 0.0);
}

static int write_emulator_png(const show_run *r, tarn_error *err)
{
    const tarn_panel_emulator *e = r->display.emulator;
    uint16_t w = tarn_panel_emulator_width(e), h = tarn_panel_emulator_height(e);
    uint8_t *rgb = malloc(3u * (size_t)w * h);
    if (rgb == NULL) return tarn_fail(err, "out of memory for the emulator's picture");
    tarn_panel_emulator_image_rgb888(e, rgb);
    int status = tarn_png_write_rgb(r->options->target, rgb, w, h, err);
    free(rgb);
    return status;
}

static int prepare(show_run *r, const tarn_loaded_scene *scene, tarn_error *err)
{
    const tarn_show_options *o = r->options;
    r->job.scene = &scene->scene;
    r->job.config = (tarn_frame_config){o->panel.width, o->panel.height, o->quality, o->time_ms};
    r->job.memory_bytes = tarn_frame_memory_bytes(&r->job.config, &scene->scene);
    if (r->job.memory_bytes == 0)
        return tarn_fail(err, "%s: cannot render at the panel's %ux%u with these quality settings", o->scene_path,
                         o->panel.width, o->panel.height);
    for (size_t m = 0; m < scene->material_count; m++) {
        int32_t reach = tarn_water_reach_pixels(scene->materials[m].water, o->panel.width);
        if (reach > (int32_t)TARN_WATER_APRON_MAX)
            return tarn_fail(err, "%s: materials.%s.water.refraction reaches %d pixels on the %s's %u columns; "
                             "the apron holds %u (pick a narrower panel or rotation, or lower refraction)",
                             o->scene_path, scene->material_names[m], (int)reach, o->panel_name, o->panel.width,
                             TARN_WATER_APRON_MAX);
    }
    size_t pixels = (size_t)o->panel.width * o->panel.height;
    r->job.memory = malloc(r->job.memory_bytes);
    r->frames[0] = malloc(pixels * sizeof(uint32_t));
    r->frames[1] = malloc(pixels * sizeof(uint32_t));
    if (r->job.memory == NULL || r->frames[0] == NULL || r->frames[1] == NULL)
        return tarn_fail(err, "out of memory for two %ux%u frames", o->panel.width, o->panel.height);
    /* the first frame renders before any device is touched */
    if (render_into(r, 0, r->frames[0]) != 0)
        return tarn_fail(err, "%s: render failed: %s", o->scene_path, tarn_status_text(r->job.status));
    return 0;
}

static void release(show_run *r)
{
    tarn_frame_sender_free(&r->sender);
    tarn_display_close(&r->display);
    free(r->job.memory);
    free(r->frames[0]);
    free(r->frames[1]);
}

/* 0, 2 (bad input, a device that cannot be used) or 1 (the link failed mid-run). */
static int run(show_run *r, const tarn_loaded_scene *scene, tarn_error *err)
{
    const tarn_show_options *o = r->options;
    if (prepare(r, scene, err) != 0 || tarn_display_open(&r->display, o, err) != 0) return 2;
    if (tarn_frame_sender_init(&r->sender, &o->panel, &r->display.transport, o->send, o->dither,
                               o->quality.tile_size, err) != 0)
        return 2;
    tarn_status init = tarn_panel_init(&o->panel, &r->display.transport);
    if (init != TARN_OK) {
        tarn_fail(err, "%s", tarn_display_failure(&r->display));
        return 2;
    }
    r->after_init = *r->display.counts;
    if (animate(r, err) != 0) return 1;
    if (r->display.emulated && write_emulator_png(r, err) != 0) return 2;
    print_figures(r);
    return 0;
}

int tarn_command_show(int argc, char **argv)
{
    tarn_show_options options;
    tarn_error err;
    /* tarn show --help is main.c's: one line, as every error of tarn show */
    if (tarn_show_parse(argc, argv, &options, &err) != 0) return tarn_usage_error("show", &err);
    tarn_loaded_scene scene;
    if (tarn_scene_load(options.scene_path, &scene, &err) != 0) return report(&err, 2);
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_interrupt;
    sigaction(SIGINT, &action, NULL);
    sigaction(SIGTERM, &action, NULL);
    show_run *r = calloc(1, sizeof *r);
    int status = 2;
    if (r == NULL) {
        tarn_fail(&err, "out of memory");
    } else {
        r->options = &options;
        r->display.spidev.fd = -1;
        status = run(r, &scene, &err);
        release(r);
        free(r);
    }
    tarn_scene_free(&scene);
    return status == 0 ? 0 : report(&err, status);
}
