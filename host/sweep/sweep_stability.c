#include "sweep_stability.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_load.h"
#include "sweep_error.h"
#include "sweep_grid.h"

#define VARIANTS_MAX 64
#define SCENE_NAME_MAX 64

typedef struct {
    double psnr, shading_psnr;
    int max_error;
    double over8;
    const char *psnr_scene, *shading_scene, *max_scene, *over8_scene;
    size_t refusals; /* scenes whose frame is too large for the value's subpixel bits */
} worst_case;

/* Each scene's three errors under each preset: the second table. */
typedef struct {
    char name[SCENE_NAME_MAX];
    tarn_yardstick preset[TARN_PRESET_COUNT];
    int refused[TARN_PRESET_COUNT];
} scene_presets;

static void note_case(worst_case *w, const tarn_yardstick *y, const char *scene)
{
    if (w->psnr_scene == NULL || y->whole.psnr_db < w->psnr) {
        w->psnr = y->whole.psnr_db;
        w->psnr_scene = scene;
    }
    if (w->shading_scene == NULL || y->shading.psnr_db < w->shading_psnr) {
        w->shading_psnr = y->shading.psnr_db;
        w->shading_scene = scene;
    }
    if (w->max_scene == NULL || y->whole.max_channel_error > w->max_error) {
        w->max_error = y->whole.max_channel_error;
        w->max_scene = scene;
    }
    if (w->over8_scene == NULL || y->whole.share_over8 > w->over8) {
        w->over8 = y->whole.share_over8;
        w->over8_scene = scene;
    }
}

static void write_row(FILE *f, const tarn_sweep_variant *v, const worst_case *w, size_t scene_count)
{
    fprintf(f, "| `%s %s` |", v->option, v->value);
    if (w->psnr_scene == NULL) fprintf(f, " - | - | - | - |");
    else
        fprintf(f, " %.2f (%s) | %.2f (%s) | %d (%s) | %.3f%% (%s) |", w->psnr, w->psnr_scene, w->shading_psnr,
                w->shading_scene, w->max_error, w->max_scene, 100.0 * w->over8, w->over8_scene);
    if (w->refusals > 0) fprintf(f, " %zu of %zu |\n", w->refusals, scene_count);
    else fprintf(f, " |\n");
}

static void write_preset_rows(FILE *f, const scene_presets *s)
{
    for (int p = 0; p < TARN_PRESET_COUNT; p++) {
        const tarn_yardstick *y = &s->preset[p];
        fprintf(f, "| %s | %s |", s->name, tarn_preset_name((tarn_preset)p));
        if (s->refused[p]) fprintf(f, " refused | | | | | |\n");
        else
            fprintf(f, " %.2f | %d | %.2f | %.3f%% | %.2f | %.3f%% |\n", y->whole.psnr_db, y->whole.max_channel_error,
                    y->shading.psnr_db, 100.0 * y->shading.share_over2, y->panel_psnr_db, 100.0 * y->coverage_share);
    }
}

/* The error of `quality`, or 1 when the frame refuses it (too large for its
 * subpixel bits): noted, not fatal. -1 with `err` set on a failure. */
static int error_or_refusal(const tarn_loaded_scene *loaded, const tarn_continuous_reference *reference,
                            const tarn_quality *quality, tarn_yardstick *y, tarn_error *err)
{
    const tarn_frame_config config = {loaded->width, loaded->height, *quality, TARN_SWEEP_TIME_MS};
    if (tarn_frame_memory_bytes(&config, &loaded->scene) == 0) return 1;
    return tarn_sweep_error_of(loaded, reference, quality, y, err);
}

/* One scene under every variant and every preset. */
static int measure_scene(const char *path, const tarn_sweep_variant *variants, size_t count, worst_case *worst,
                         scene_presets *presets, tarn_error *err)
{
    tarn_loaded_scene loaded;
    if (tarn_scene_load(path, &loaded, err) != 0) return -1;
    snprintf(presets->name, sizeof presets->name, "%s", loaded.name);
    tarn_continuous_reference reference = {NULL, NULL, 0, 0, 0};
    int status = tarn_sweep_reference_render(&loaded, &reference, err);
    for (size_t v = 0; v < count && status >= 0; v++) {
        tarn_yardstick y;
        status = error_or_refusal(&loaded, &reference, &variants[v].quality, &y, err);
        if (status == 1) worst[v].refusals++;
        else if (status == 0) note_case(&worst[v], &y, presets->name);
    }
    for (int p = 0; p < TARN_PRESET_COUNT && status >= 0; p++) {
        const tarn_quality quality = tarn_quality_preset((tarn_preset)p);
        status = error_or_refusal(&loaded, &reference, &quality, &presets->preset[p], err);
        presets->refused[p] = status == 1;
    }
    tarn_continuous_reference_free(&reference);
    tarn_scene_free(&loaded);
    return status < 0 ? -1 : 0;
}

static void write_tables(FILE *out, const tarn_sweep_variant *variants, size_t count, const worst_case *worst,
                         const scene_presets *presets, size_t scene_count)
{
    fprintf(out, "| knob (rest balanced) | lowest PSNR dB (scene) | lowest shading PSNR dB (scene) | "
                 "largest channel error (scene) | most pixels off by >8 (scene) | scenes refusing it |\n"
                 "| --- | --- | --- | --- | --- | --- |\n");
    for (size_t v = 0; v < count; v++) write_row(out, &variants[v], &worst[v], scene_count);
    fprintf(out, "\n| scene | preset | PSNR dB | max error | shading dB | shading >2 | panel dB | coverage |\n"
                 "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (size_t s = 0; s < scene_count; s++) write_preset_rows(out, &presets[s]);
}

int tarn_sweep_stability(const char *const *scene_paths, size_t scene_count, FILE *out, tarn_progress *progress,
                         tarn_error *err)
{
    tarn_sweep_variant variants[VARIANTS_MAX];
    worst_case worst[VARIANTS_MAX];
    const size_t count = tarn_sweep_variants(variants, VARIANTS_MAX);
    scene_presets *presets = calloc(scene_count, sizeof *presets);
    memset(worst, 0, sizeof worst);
    int failed = presets == NULL ? tarn_fail(err, "out of memory") : 0;
    for (size_t s = 0; s < scene_count && !failed; s++) {
        failed = measure_scene(scene_paths[s], variants, count, worst, &presets[s], err);
        tarn_progress_step(progress, s + 1u);
    }
    if (!failed) write_tables(out, variants, count, worst, presets, scene_count);
    free(presets);
    return failed ? -1 : 0;
}
