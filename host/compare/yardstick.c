/* yardstick.c: the three errors and the coverage of a frame (see yardstick.h). */
#include "yardstick.h"

#include <stdlib.h>

#include "panel_emulator.h"
#include "reference.h"
#include "tarn/tarn_panel.h"

/* Every board sends its frames with the ordered dither (firmware/main.c). */
#define PANEL_DITHER 1

void tarn_continuous_reference_free(tarn_continuous_reference *reference)
{
    free(reference->rgb);
    free(reference->surface);
    reference->rgb = NULL;
    reference->surface = NULL;
}

int tarn_continuous_reference_render(const tarn_scene *scene, const char *scene_name, int width, int height,
                                     uint32_t time_ms, tarn_continuous_reference *out, tarn_error *err)
{
    const size_t pixels = (size_t)width * (size_t)height;
    out->width = width;
    out->height = height;
    out->time_ms = time_ms;
    out->rgb = malloc(3 * pixels);
    out->surface = malloc(pixels * sizeof *out->surface);
    if (out->rgb == NULL || out->surface == NULL) {
        tarn_continuous_reference_free(out);
        return tarn_fail(err, "out of memory for a %dx%d reference", width, height);
    }
    const tarn_reference_options options = {.geometry = TARN_REF_CONTINUOUS,
                                            .subpixel_bits = (int)TARN_SUBPIXEL_BITS_MAX,
                                            .time_ms = time_ms};
    if (tarn_reference_render_surfaces(scene, width, height, &options, out->rgb, out->surface) != TARN_OK) {
        tarn_continuous_reference_free(out);
        return tarn_fail(err, "%s: the reference cannot render this scene at %dx%d", scene_name, width, height);
    }
    return 0;
}

void tarn_as_panel_shows(const uint8_t *rgb, int width, int height, uint8_t *out)
{
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            const size_t i = 3 * ((size_t)y * (size_t)width + (size_t)x);
            const uint32_t pixel = ((uint32_t)rgb[i] << 16) | ((uint32_t)rgb[i + 1] << 8) | rgb[i + 2];
            tarn_rgb565_to_rgb888(tarn_rgb565(pixel, (uint16_t)x, (uint16_t)y, PANEL_DITHER), &out[i]);
        }
}

static double panel_psnr(const uint8_t *rgb, const uint8_t *shading_rgb, int width, int height,
                         uint8_t *scratch_a, uint8_t *scratch_b)
{
    tarn_compare_metrics m;
    tarn_as_panel_shows(rgb, width, height, scratch_a);
    tarn_as_panel_shows(shading_rgb, width, height, scratch_b);
    tarn_compare_images(scratch_a, scratch_b, NULL, NULL, width, height, &m);
    return m.psnr_db;
}

static double coverage_share(const uint32_t *a, const uint32_t *b, size_t pixels, uint8_t *differs)
{
    size_t count = 0;
    for (size_t p = 0; p < pixels; p++) {
        const int differ = a[p] != b[p];
        count += (size_t)differ;
        if (differs != NULL) differs[p] = (uint8_t)differ;
    }
    return pixels ? (double)count / (double)pixels : 0.0;
}

/* The reference of the core's own triangles at the frame's quality. */
static int render_shading_reference(const tarn_scene *scene, const char *scene_name,
                                    const tarn_frame_config *config, uint8_t *rgb, uint32_t *surface,
                                    tarn_error *err)
{
    const tarn_reference_options options = {.geometry = TARN_REF_CORE_TRIANGLES,
                                            .subpixel_bits = config->quality.subpixel_bits,
                                            .time_ms = config->time_ms, .quality = &config->quality};
    if (tarn_reference_render_surfaces(scene, config->width, config->height, &options, rgb, surface) != TARN_OK)
        return tarn_fail(err, "%s: the reference cannot draw the core's triangles at %ux%u", scene_name,
                         config->width, config->height);
    return 0;
}

int tarn_yardstick_measure(const tarn_scene *scene, const char *scene_name, const tarn_frame_config *config,
                           const uint8_t *rgb, const tarn_continuous_reference *reference,
                           tarn_yardstick *out, uint8_t *surface_differs, tarn_error *err)
{
    const int w = config->width, h = config->height;
    if (w != reference->width || h != reference->height || config->time_ms != reference->time_ms)
        return tarn_fail(err, "%s: the frame is not the reference's size and time", scene_name);
    const size_t pixels = (size_t)w * (size_t)h;
    uint8_t *shading = malloc(3 * pixels), *panel_a = malloc(3 * pixels), *panel_b = malloc(3 * pixels);
    uint32_t *surface = malloc(pixels * sizeof *surface);
    int failed = shading == NULL || panel_a == NULL || panel_b == NULL || surface == NULL
        ? tarn_fail(err, "out of memory for a %dx%d frame", w, h)
        : render_shading_reference(scene, scene_name, config, shading, surface, err);
    if (!failed) {
        tarn_compare_images(rgb, reference->rgb, NULL, NULL, w, h, &out->whole);
        tarn_compare_images(rgb, shading, NULL, NULL, w, h, &out->shading);
        out->panel_psnr_db = panel_psnr(rgb, shading, w, h, panel_a, panel_b);
        out->coverage_share = coverage_share(surface, reference->surface, pixels, surface_differs);
    }
    free(shading);
    free(panel_a);
    free(panel_b);
    free(surface);
    return failed ? -1 : 0;
}

void tarn_yardstick_print(FILE *out, const char *scene_name, const tarn_frame_config *config,
                          const tarn_yardstick *y)
{
    fprintf(out,
            "compare scene=%s size=%ux%u time=%lu psnr=%.2f maxerr=%d over2=%.3f%% over8=%.3f%%"
            " shading_psnr=%.2f shading_over2=%.3f%% panel_psnr=%.2f coverage=%.3f%%\n",
            scene_name, config->width, config->height, (unsigned long)config->time_ms, y->whole.psnr_db,
            y->whole.max_channel_error, 100.0 * y->whole.share_over2, 100.0 * y->whole.share_over8,
            y->shading.psnr_db, 100.0 * y->shading.share_over2, y->panel_psnr_db, 100.0 * y->coverage_share);
}
