#include "sweep_error.h"

#include <stdlib.h>

#include "accuracy_math.h"
#include "core_render.h"
#include "reference.h"
#include "tarn_checksum.h"

/* The reference rounds screen positions to the core's subpixel grid, so there is
 * one reference image per subpixel precision. */
typedef struct {
    uint8_t *rgb[TARN_SUBPIXEL_BITS_MAX + 1], *covered[TARN_SUBPIXEL_BITS_MAX + 1];
    int width, height;
} reference_cache;

static void cache_free(reference_cache *c)
{
    for (unsigned s = 0; s <= TARN_SUBPIXEL_BITS_MAX; s++) {
        free(c->rgb[s]);
        free(c->covered[s]);
    }
}

static int cached_reference(const tarn_loaded_scene *loaded, reference_cache *c, unsigned subpixel_bits,
                            tarn_error *err)
{
    if (c->rgb[subpixel_bits] != NULL) return 0;
    const size_t pixels = (size_t)c->width * (size_t)c->height;
    c->rgb[subpixel_bits] = malloc(3 * pixels);
    c->covered[subpixel_bits] = malloc(pixels);
    if (c->rgb[subpixel_bits] == NULL || c->covered[subpixel_bits] == NULL)
        return tarn_fail(err, "out of memory for a %dx%d reference", c->width, c->height);
    const tarn_reference_options options = {.snapped = 0, .subpixel_bits = (int)subpixel_bits,
                                            .time_ms = TARN_SWEEP_TIME_MS};
    if (tarn_reference_render(&loaded->scene, c->width, c->height, &options, c->rgb[subpixel_bits],
                              c->covered[subpixel_bits]) != 0)
        return tarn_fail(err, "%s: the reference cannot render this scene at %dx%d", loaded->name,
                         c->width, c->height);
    return 0;
}

static uint32_t image_checksum(const uint8_t *rgb, int width, int height)
{
    uint32_t sum = 0;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            const uint8_t *p = &rgb[3 * ((size_t)y * (size_t)width + (size_t)x)];
            sum += tarn_checksum_pixel((uint32_t)x, (uint32_t)y, ((uint32_t)p[0] << 16) | ((uint32_t)p[1] << 8) | p[2]);
        }
    return sum;
}

/* The core's frame against the cached reference. */
static int measure(const tarn_loaded_scene *loaded, reference_cache *c, const tarn_quality *quality,
                   tarn_compare_metrics *metrics, uint32_t *checksum, tarn_error *err)
{
    const size_t pixels = (size_t)c->width * (size_t)c->height;
    const tarn_frame_config config = {(uint16_t)c->width, (uint16_t)c->height, *quality, TARN_SWEEP_TIME_MS};
    uint8_t *rgb = malloc(3 * pixels), *covered = malloc(pixels);
    int failed = rgb == NULL || covered == NULL
        ? tarn_fail(err, "out of memory for a %dx%d frame", c->width, c->height)
        : cached_reference(loaded, c, quality->subpixel_bits, err) ||
              tarn_core_render(&loaded->scene, &config, rgb, covered, err);
    if (!failed) {
        tarn_compare_images(rgb, c->rgb[quality->subpixel_bits], covered, c->covered[quality->subpixel_bits],
                            c->width, c->height, metrics);
        if (checksum != NULL) *checksum = image_checksum(rgb, c->width, c->height);
    }
    free(rgb);
    free(covered);
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
    const unsigned size = 31u - (unsigned)__builtin_clz(p->quality.exp2.entries) - 3u;
    const unsigned mode = p->quality.exp2.interpolate ? 1u : 0u;
    if (m->exp2[size][mode] < 0) m->exp2[size][mode] = tarn_math_measure_exp2(p->quality.exp2).max_abs_lsb;
    if (m->recip[p->quality.recip_newton_steps] < 0)
        m->recip[p->quality.recip_newton_steps] = tarn_math_measure_recip(p->quality.recip_newton_steps).max_rel_excess;
    p->exp2_max_lsb = m->exp2[size][mode];
    p->recip_max_rel = m->recip[p->quality.recip_newton_steps];
}

int tarn_sweep_measure_errors(const tarn_loaded_scene *loaded, tarn_sweep_scene *scene, tarn_error *err)
{
    reference_cache cache = {{NULL}, {NULL}, scene->width, scene->height};
    math_errors math;
    for (unsigned i = 0; i < 6; i++) math.exp2[i][0] = math.exp2[i][1] = -1.0;
    for (unsigned i = 0; i <= TARN_RECIP_STEPS_MAX; i++) math.recip[i] = -1.0;
    int failed = 0;
    for (size_t i = 0; i < scene->count && !failed; i++) {
        tarn_sweep_point *p = &scene->points[i];
        failed = measure(loaded, &cache, &p->quality, &p->error, &p->checksum, err);
        knob_math_errors(&math, p);
    }
    cache_free(&cache);
    return failed ? -1 : 0;
}

int tarn_sweep_error_of(const tarn_loaded_scene *loaded, const tarn_quality *quality,
                        tarn_compare_metrics *metrics, tarn_error *err)
{
    reference_cache cache = {{NULL}, {NULL}, loaded->width, loaded->height};
    const int failed = measure(loaded, &cache, quality, metrics, NULL, err);
    cache_free(&cache);
    return failed;
}
