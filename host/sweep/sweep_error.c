#include "sweep_error.h"

#include <stdlib.h>

#include "accuracy_math.h"
#include "core_render.h"
#include "image_checksum.h"
#include "panel_emulator.h"
#include "tarn/tarn_panel.h"
#include "reference.h"

void tarn_sweep_reference_free(tarn_sweep_reference *r)
{
    free(r->rgb);
    free(r->covered);
    r->rgb = r->covered = NULL;
}

int tarn_sweep_reference_render(const tarn_loaded_scene *loaded, tarn_sweep_reference *r, tarn_error *err)
{
    r->width = loaded->width;
    r->height = loaded->height;
    const size_t pixels = (size_t)r->width * (size_t)r->height;
    r->rgb = malloc(3 * pixels);
    r->covered = malloc(pixels);
    if (r->rgb == NULL || r->covered == NULL)
        return tarn_fail(err, "out of memory for a %dx%d reference", r->width, r->height);
    const tarn_reference_options options = {.snapped = 0, .subpixel_bits = (int)TARN_SUBPIXEL_BITS_MAX,
                                            .time_ms = TARN_SWEEP_TIME_MS};
    if (tarn_reference_render(&loaded->scene, r->width, r->height, &options, r->rgb, r->covered) != 0)
        return tarn_fail(err, "%s: the reference cannot render this scene at %dx%d", loaded->name,
                         r->width, r->height);
    return 0;
}

/* The frame through the panel's RGB565, back to RGB888 as the panel shows it. */
static void as_panel_shows(const uint8_t *rgb, int width, int height, int dither, uint8_t *out)
{
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            const size_t i = 3 * ((size_t)y * (size_t)width + (size_t)x);
            const uint32_t pixel = ((uint32_t)rgb[i] << 16) | ((uint32_t)rgb[i + 1] << 8) | rgb[i + 2];
            tarn_rgb565_to_rgb888(tarn_rgb565(pixel, (uint16_t)x, (uint16_t)y, dither), &out[i]);
        }
}

/* `shown`: room for a frame, overwritten. */
static void panel_errors(const uint8_t *rgb, const tarn_sweep_reference *r, uint8_t *shown,
                         tarn_compare_metrics panel[2])
{
    for (int dither = 0; dither < 2; dither++) {
        as_panel_shows(rgb, r->width, r->height, dither, shown);
        tarn_compare_images(shown, r->rgb, NULL, NULL, r->width, r->height, &panel[dither]);
    }
}

/* The core's frame against the reference; with `point`, also its checksum and what
 * the panel shows of it. */
static int measure(const tarn_loaded_scene *loaded, const tarn_sweep_reference *r, const tarn_quality *quality,
                   tarn_compare_metrics *metrics, tarn_sweep_point *point, tarn_error *err)
{
    const size_t pixels = (size_t)r->width * (size_t)r->height;
    const tarn_frame_config config = {(uint16_t)r->width, (uint16_t)r->height, *quality, TARN_SWEEP_TIME_MS};
    uint8_t *rgb = malloc(3 * pixels), *covered = malloc(pixels), *shown = malloc(3 * pixels);
    int failed = rgb == NULL || covered == NULL || shown == NULL
        ? tarn_fail(err, "out of memory for a %dx%d frame", r->width, r->height)
        : tarn_core_render(&loaded->scene, &config, rgb, covered, err);
    if (!failed) {
        tarn_compare_images(rgb, r->rgb, covered, r->covered, r->width, r->height, metrics);
        if (point != NULL) {
            point->checksum = tarn_image_checksum(rgb, (uint32_t)r->width, (uint32_t)r->height);
            panel_errors(rgb, r, shown, point->panel);
        }
    }
    free(rgb);
    free(covered);
    free(shown);
    return failed ? -1 : 0;
}

/* The knobs' own function errors, each swept once per configuration: they cost
 * more than a frame. */
typedef struct {
    double exp2[6][2]; /* by log2(entries) - 3 and interpolation; negative: not yet */
    double recip[TARN_RECIP_STEPS_MAX + 1];
} math_errors;

static void knob_math_errors(math_errors *m, tarn_sweep_point *p)
{
    const unsigned size = 31u - tarn_clz32(p->quality.exp2.entries) - 3u; /* 8 entries: 0 */
    const unsigned mode = p->quality.exp2.interpolate ? 1u : 0u;
    if (m->exp2[size][mode] < 0) m->exp2[size][mode] = tarn_math_measure_exp2(p->quality.exp2).max_abs_lsb;
    if (m->recip[p->quality.recip_newton_steps] < 0)
        m->recip[p->quality.recip_newton_steps] = tarn_math_measure_recip(p->quality.recip_newton_steps).max_rel_excess;
    p->exp2_max_lsb = m->exp2[size][mode];
    p->recip_max_rel = m->recip[p->quality.recip_newton_steps];
}

int tarn_sweep_measure_errors(const tarn_loaded_scene *loaded, tarn_sweep_scene *scene, tarn_error *err)
{
    tarn_sweep_reference reference = {NULL, NULL, 0, 0};
    math_errors math;
    for (unsigned i = 0; i < 6; i++) math.exp2[i][0] = math.exp2[i][1] = -1.0;
    for (unsigned i = 0; i <= TARN_RECIP_STEPS_MAX; i++) math.recip[i] = -1.0;
    int failed = tarn_sweep_reference_render(loaded, &reference, err);
    for (size_t i = 0; i < scene->count && !failed; i++) {
        tarn_sweep_point *p = &scene->points[i];
        failed = measure(loaded, &reference, &p->quality, &p->error, p, err);
        knob_math_errors(&math, p);
    }
    tarn_sweep_reference_free(&reference);
    return failed ? -1 : 0;
}

int tarn_sweep_error_of(const tarn_loaded_scene *loaded, const tarn_sweep_reference *reference,
                        const tarn_quality *quality, tarn_compare_metrics *metrics, tarn_error *err)
{
    return measure(loaded, reference, quality, metrics, NULL, err);
}
