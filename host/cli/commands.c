#include "commands.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accuracy_math.h"
#include "bake.h"
#include "compare.h"
#include "core_render.h"
#include "frame_path.h"
#include "gif_io.h"
#include "option_values.h"
#include "png_io.h"
#include "progress.h"
#include "reference.h"
#include "scene_load.h"
#include "backdrop.h"
#include "static_view.h"
#include "yardstick.h"

/* Room for a sequence frame's file name: -o's name plus "-0000.png". */
#define FRAME_PATH_MAX 4096

/* Both renderers' output for one frame. */
typedef struct {
    int width, height;
    uint8_t *rgb, *covered;
} frame_image;

static int report(const tarn_error *err)
{
    fprintf(stderr, "tarn: %s\n", err->message);
    return TARN_EXIT_BAD_INPUT;
}

static tarn_frame_config frame_config(const tarn_cli_options *o, const tarn_loaded_scene *scene)
{
    tarn_frame_config config;
    config.width = o->width ? o->width : scene->width;
    config.height = o->height ? o->height : scene->height;
    config.quality = o->quality;
    config.time_ms = o->time_ms;
    return config;
}

static int frame_alloc(frame_image *f, int width, int height, tarn_error *err)
{
    size_t pixels = (size_t)width * (size_t)height;
    f->width = width;
    f->height = height;
    f->rgb = malloc(3 * pixels);
    f->covered = malloc(pixels);
    if (f->rgb == NULL || f->covered == NULL) return tarn_fail(err, "out of memory for a %dx%d frame", width, height);
    return 0;
}

static void frame_free(frame_image *f)
{
    free(f->rgb);
    free(f->covered);
}

static int render_reference(const tarn_loaded_scene *scene, const tarn_frame_config *config,
                            int snapped, frame_image *f, tarn_error *err)
{
    tarn_reference_options options = {.geometry = snapped ? TARN_REF_CORE_TRIANGLES : TARN_REF_CONTINUOUS,
                                      .subpixel_bits = config->quality.subpixel_bits,
                                      .time_ms = config->time_ms, .quality = &config->quality};
    if (tarn_reference_render(&scene->scene, config->width, config->height, &options, f->rgb,
                              f->covered) != 0)
        return tarn_fail(err, "%s: the reference cannot render this scene at %ux%u",
                         scene->name, config->width, config->height);
    return 0;
}

typedef int (*scene_action)(const tarn_cli_options *o, const tarn_loaded_scene *scene,
                            const tarn_frame_config *config, tarn_error *err);

/* The loader checks refraction at the scene's own width; a --size can widen the
 * frame past what the apron holds. */
static int check_refraction_reach(const char *path, const tarn_loaded_scene *scene,
                                  const tarn_frame_config *config, tarn_error *err)
{
    for (size_t m = 0; m < scene->material_count; m++) {
        int32_t reach = tarn_water_reach_pixels(scene->materials[m].water, config->width);
        if (reach > (int32_t)TARN_WATER_APRON_MAX)
            return tarn_fail(err, "%s: materials.%s.water.refraction reaches %d pixels at width %u; the apron "
                             "holds %u (lower refraction or normal_strength, or render narrower)",
                             path, scene->material_names[m], (int)reach, config->width,
                             TARN_WATER_APRON_MAX);
    }
    return 0;
}

/* Loads the scene, runs the action on it and reports any failure as one line. */
static int run_on_scene(const tarn_cli_options *o, scene_action action)
{
    tarn_error err;
    tarn_loaded_scene scene;
    if (tarn_scene_load(o->scene_path, &scene, &err) != 0) return report(&err);
    tarn_camera_override_apply(&o->camera, &scene.scene);
    tarn_frame_config config = frame_config(o, &scene);
    int failed = check_refraction_reach(o->scene_path, &scene, &config, &err) ||
                 action(o, &scene, &config, &err);
    tarn_scene_free(&scene);
    return failed ? report(&err) : 0;
}

/* One frame into `f`, by the renderer the options pick; with --rgb565 as the
 * panel shows it. */
static int render_frame(const tarn_cli_options *o, const tarn_loaded_scene *scene,
                        const tarn_frame_config *config, frame_image *f, tarn_error *err)
{
    int failed = o->reference ? render_reference(scene, config, o->snapped, f, err)
                              : tarn_core_render(&scene->scene, config, f->rgb, f->covered, err);
    if (!failed && o->rgb565) tarn_as_panel_shows(f->rgb, config->width, config->height, f->rgb);
    return failed;
}

/* One frame into `f` and then to `path`. */
static int render_frame_to(const char *path, const tarn_cli_options *o,
                           const tarn_loaded_scene *scene, const tarn_frame_config *config,
                           frame_image *f, tarn_error *err)
{
    return render_frame(o, scene, config, f, err) ||
                   tarn_png_write_rgb(path, f->rgb, config->width, config->height, err)
               ? -1
               : 0;
}

/* Frames [0, count) of the sequence, which this run wrote. */
static void remove_frames(const char *output, unsigned count)
{
    char path[FRAME_PATH_MAX];
    for (unsigned k = 0; k < count; k++) {
        if (tarn_frame_path(output, k, path, sizeof path) == 0) remove(path);
    }
}

/* --frames N: OUT-0000.png onward, each at its own clock. A failure removes the
 * frames already written, so that no partial sequence is left behind. */
static int render_sequence(const tarn_cli_options *o, const tarn_loaded_scene *scene,
                           const tarn_frame_config *config, frame_image *f, tarn_error *err)
{
    tarn_frame_config at = *config;
    char path[FRAME_PATH_MAX];
    /* every frame's name is as long as the last one's */
    if (tarn_frame_path(o->output_path, o->frames - 1u, path, sizeof path) != 0)
        return tarn_fail(err, "-o: '%s' is too long for a frame's file name", o->output_path);
    tarn_progress progress;
    tarn_progress_start(&progress, "tarn render: frames", o->frames, o->quiet);
    int failed = 0;
    for (unsigned k = 0; k < o->frames && !failed; k++) {
        at.time_ms = tarn_cli_frame_time(o, k);
        tarn_frame_path(o->output_path, k, path, sizeof path);
        failed = render_frame_to(path, o, scene, &at, f, err);
        if (failed) remove_frames(o->output_path, k);
        tarn_progress_step(&progress, k + 1u);
    }
    tarn_progress_end(&progress);
    return failed ? -1 : 0;
}

/* -o NAME.gif: every frame is held until the last, since one palette is chosen
 * over them all (gif_io.h), then the one file is written. */
static int render_gif(const tarn_cli_options *o, const tarn_loaded_scene *scene,
                      const tarn_frame_config *config, frame_image *f, tarn_error *err)
{
    const unsigned frames = o->frames ? o->frames : 1u;
    const size_t frame_pixels = (size_t)config->width * config->height, frame_bytes = 3u * frame_pixels;
    if (frame_pixels * frames > TARN_CLI_GIF_PIXELS_MAX)
        return tarn_fail(err, "%s: %u frames of %ux%u are %zu pixels to choose one palette over; a GIF holds at "
                         "most %lu (fewer frames, or a smaller --size)", o->output_path, frames, config->width,
                         config->height, frame_pixels * frames, (unsigned long)TARN_CLI_GIF_PIXELS_MAX);
    uint8_t *all = malloc(frame_bytes * frames);
    if (all == NULL) return tarn_fail(err, "%s: out of memory for %u frames", o->output_path, frames);
    tarn_frame_config at = *config;
    tarn_progress progress;
    tarn_progress_start(&progress, "tarn render: frames", frames, o->quiet);
    int failed = 0;
    for (unsigned k = 0; k < frames && !failed; k++) {
        at.time_ms = tarn_cli_frame_time(o, k);
        failed = render_frame(o, scene, &at, f, err);
        if (!failed) memcpy(all + k * frame_bytes, f->rgb, frame_bytes);
        tarn_progress_step(&progress, k + 1u);
    }
    tarn_progress_end(&progress);
    const tarn_gif_animation animation = {config->width, config->height, frames,
                                          o->fps ? o->fps : TARN_CLI_FPS_DEFAULT, all};
    failed = failed || tarn_gif_write(o->output_path, &animation, err);
    free(all);
    return failed ? -1 : 0;
}

static int render_images(const tarn_cli_options *o, const tarn_loaded_scene *scene,
                         const tarn_frame_config *config, tarn_error *err)
{
    frame_image f = {0, 0, NULL, NULL};
    int failed = frame_alloc(&f, config->width, config->height, err) ||
                 (tarn_cli_writes_gif(o)  ? render_gif(o, scene, config, &f, err)
                  : o->frames ? render_sequence(o, scene, config, &f, err)
                              : render_frame_to(o->output_path, o, scene, config, &f, err));
    frame_free(&f);
    return failed ? -1 : 0;
}

/* --backdrop on|still: the scene's water over its opaque objects (and still water)
 * drawn once, as firmware baked with the option draws it. The backdrop does not
 * change with time, so one serves every frame of a sequence. */
static int render_to_png(const tarn_cli_options *o, const tarn_loaded_scene *scene,
                         const tarn_frame_config *config, tarn_error *err)
{
    if (o->backdrop == TARN_BACKDROP_NONE) return render_images(o, scene, config, err);
    tarn_backdrop_scene backdrop;
    if (tarn_backdrop_scene_make(&scene->scene, config, tarn_cli_backdrop(o), 0, &backdrop, err) != 0)
        return tarn_fail_in(err, o->scene_path);
    tarn_loaded_scene over = *scene;
    over.scene = backdrop.water.scene;
    const int failed = render_images(o, &over, config, err);
    tarn_backdrop_scene_free(&backdrop);
    return failed;
}

int tarn_command_render(const tarn_cli_options *o)
{
    return run_on_scene(o, render_to_png);
}

/* The core's frame as the options draw it: with --backdrop, the water over the
 * picture the bake would hold in flash (the same image, or within 1 for still). */
static int render_core_frame(const tarn_cli_options *o, const tarn_loaded_scene *scene,
                             const tarn_frame_config *config, uint8_t *rgb, tarn_error *err)
{
    if (o->backdrop == TARN_BACKDROP_NONE) return tarn_core_render(&scene->scene, config, rgb, NULL, err);
    tarn_backdrop_scene backdrop;
    if (tarn_backdrop_scene_make(&scene->scene, config, tarn_cli_backdrop(o), 0, &backdrop, err) != 0)
        return tarn_fail_in(err, o->scene_path);
    int failed = tarn_core_render(&backdrop.water.scene, config, rgb, NULL, err);
    tarn_backdrop_scene_free(&backdrop);
    return failed;
}

static int write_heatmap(const char *path, const uint8_t *rgb, const tarn_continuous_reference *reference,
                         const uint8_t *surface_differs, tarn_error *err)
{
    uint8_t *heat = malloc(3u * (size_t)reference->width * (size_t)reference->height);
    if (heat == NULL) return tarn_fail(err, "out of memory for the heat-map");
    tarn_compare_heatmap(rgb, reference->rgb, surface_differs, reference->width, reference->height, heat);
    int written = tarn_png_write_rgb(path, heat, reference->width, reference->height, err);
    free(heat);
    return written;
}

/* The frame against the continuous reference and the core's own triangles
 * (yardstick.h); --diff maps the whole error, magenta where the surface differs
 * (`core->covered` holds that mark: compare needs no coverage of its own). The
 * references draw the scene itself, --backdrop or not. */
static int compare_frames(const tarn_cli_options *o, const tarn_loaded_scene *scene,
                          const tarn_frame_config *config, frame_image *core,
                          tarn_continuous_reference *reference, tarn_error *err)
{
    tarn_yardstick y;
    if (frame_alloc(core, config->width, config->height, err) ||
        render_core_frame(o, scene, config, core->rgb, err) ||
        tarn_continuous_reference_render(&scene->scene, scene->name, config->width, config->height,
                                         config->time_ms, reference, err) ||
        tarn_yardstick_measure(&scene->scene, scene->name, config, core->rgb, reference, &y, core->covered, err) ||
        (o->diff_path && write_heatmap(o->diff_path, core->rgb, reference, core->covered, err) != 0))
        return -1;
    tarn_yardstick_print(stdout, scene->name, config, &y);
    return 0;
}

static int compare_with_reference(const tarn_cli_options *o, const tarn_loaded_scene *scene,
                                  const tarn_frame_config *config, tarn_error *err)
{
    frame_image core = {0, 0, NULL, NULL};
    tarn_continuous_reference reference = {NULL, NULL, 0, 0, 0};
    int failed = compare_frames(o, scene, config, &core, &reference, err);
    frame_free(&core);
    tarn_continuous_reference_free(&reference);
    return failed ? -1 : 0;
}

int tarn_command_compare(const tarn_cli_options *o)
{
    return run_on_scene(o, compare_with_reference);
}

static int print_memory(const tarn_cli_options *o, const tarn_loaded_scene *scene,
                        const tarn_frame_config *config, tarn_error *err)
{
    (void)o;
    size_t bytes = tarn_frame_memory_bytes(config, &scene->scene);
    if (bytes == 0)
        return tarn_fail(err, "%s: %ux%u with these quality settings: %s", scene->name, config->width,
                         config->height, tarn_status_text(TARN_ERR_CONFIG));
    /* what the frame needs in each shape, the rest of the quality as asked */
    tarn_frame_config shaped = *config;
    shaped.quality.frame_shape = TARN_FRAME_TILES;
    const size_t tiles = tarn_frame_memory_bytes(&shaped, &scene->scene);
    shaped.quality.frame_shape = TARN_FRAME_STRIPS;
    const size_t strips = tarn_frame_memory_bytes(&shaped, &scene->scene);
    const size_t pipeline = tarn_strip_pipeline_memory_bytes(&shaped, &scene->scene);
    printf("memory scene=%s size=%ux%u tile=%u frame=%s depth_bits=%u apron=%d bytes=%zu baked_bytes=%zu "
           "tiles_bytes=%zu strips_bytes=%zu pipeline_bytes=%zu\n",
           scene->name, config->width, config->height, config->quality.tile_size,
           config->quality.frame_shape == TARN_FRAME_STRIPS ? "strips" : "tiles", config->quality.depth_bits,
           (int)tarn_frame_apron_pixels(&scene->scene, config), bytes,
           tarn_static_memory_bytes(config, &scene->scene, config), tiles, strips, pipeline);
    return 0;
}

int tarn_command_memory(const tarn_cli_options *o)
{
    return run_on_scene(o, print_memory);
}

static int bake_to_c(const tarn_cli_options *o, const tarn_loaded_scene *scene,
                     const tarn_frame_config *config, tarn_error *err)
{
    tarn_bake_options options = {o->scene_path, o->output_path, o->name, o->points_path, !o->no_static_view,
                                  tarn_cli_backdrop(o), *config, o->argc, o->argv, o->quiet};
    tarn_bake_result result;
    if (tarn_bake(scene, &options, &result, err) != 0) return -1;
    printf("bake scene=%s const_bytes=%zu memory_bytes=%zu\n", result.name, result.const_bytes,
           result.memory_bytes);
    return 0;
}

int tarn_command_bake(const tarn_cli_options *o)
{
    tarn_error err;
    /* a bad name is reported before the scene is read */
    if (o->name && tarn_bake_check_name(o->name, &err) != 0) return report(&err);
    return run_on_scene(o, bake_to_c);
}

int tarn_command_accuracy(const tarn_cli_options *o)
{
    (void)o; /* --math is the only table so far; the parser requires it */
    return tarn_accuracy_math_print(stdout) == 0 ? 0 : 1;
}
