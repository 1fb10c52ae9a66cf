#include "sweep_error.h"

#include <stdlib.h>

#include "accuracy_math.h"
#include "core_render.h"
#include "image_checksum.h"

int tarn_sweep_reference_render(const tarn_loaded_scene *loaded, tarn_continuous_reference *reference,
                                tarn_error *err)
{
    return tarn_continuous_reference_render(&loaded->scene, loaded->name, loaded->width, loaded->height,
                                            TARN_SWEEP_TIME_MS, reference, err);
}

/* The core's frame of `quality`, measured; with `checksum`, also the frame's. */
static int measure(const tarn_loaded_scene *loaded, const tarn_continuous_reference *r, const tarn_quality *quality,
                   tarn_yardstick *error, uint32_t *checksum, tarn_error *err)
{
    const tarn_frame_config config = {(uint16_t)r->width, (uint16_t)r->height, *quality, TARN_SWEEP_TIME_MS};
    uint8_t *rgb = malloc(3 * (size_t)r->width * (size_t)r->height);
    int failed = rgb == NULL ? tarn_fail(err, "out of memory for a %dx%d frame", r->width, r->height)
                             : tarn_core_render(&loaded->scene, &config, rgb, NULL, err);
    if (!failed) failed = tarn_yardstick_measure(&loaded->scene, loaded->name, &config, rgb, r, error, NULL, err);
    if (!failed && checksum != NULL) *checksum = tarn_image_checksum(rgb, (uint32_t)r->width, (uint32_t)r->height);
    free(rgb);
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

int tarn_sweep_measure_errors(const tarn_loaded_scene *loaded, tarn_sweep_scene *scene, tarn_progress *progress,
                              tarn_error *err)
{
    tarn_continuous_reference reference = {NULL, NULL, 0, 0, 0};
    math_errors math;
    for (unsigned i = 0; i < 6; i++) math.exp2[i][0] = math.exp2[i][1] = -1.0;
    for (unsigned i = 0; i <= TARN_RECIP_STEPS_MAX; i++) math.recip[i] = -1.0;
    int failed = tarn_sweep_reference_render(loaded, &reference, err);
    for (size_t i = 0; i < scene->count && !failed; i++) {
        tarn_sweep_point *p = &scene->points[i];
        failed = measure(loaded, &reference, &p->quality, &p->error, &p->checksum, err);
        knob_math_errors(&math, p);
        tarn_progress_step(progress, i + 1u);
    }
    tarn_continuous_reference_free(&reference);
    return failed ? -1 : 0;
}

int tarn_sweep_error_of(const tarn_loaded_scene *loaded, const tarn_continuous_reference *reference,
                        const tarn_quality *quality, tarn_yardstick *error, tarn_error *err)
{
    return measure(loaded, reference, quality, error, NULL, err);
}
