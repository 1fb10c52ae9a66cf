#include "sweep_stability.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_load.h"
#include "sweep_error.h"
#include "sweep_grid.h"

#define VARIANTS_MAX 64

typedef struct {
    double psnr;
    int max_error;
    double over8;
    const char *psnr_scene, *max_scene, *over8_scene;
    size_t refusals; /* scenes whose frame is too large for the value's subpixel bits */
} worst_case;

static void note_case(worst_case *w, const tarn_compare_metrics *m, const char *scene)
{
    if (w->psnr_scene == NULL || m->psnr_db < w->psnr) {
        w->psnr = m->psnr_db;
        w->psnr_scene = scene;
    }
    if (w->max_scene == NULL || m->max_channel_error > w->max_error) {
        w->max_error = m->max_channel_error;
        w->max_scene = scene;
    }
    if (w->over8_scene == NULL || m->share_over8 > w->over8) {
        w->over8 = m->share_over8;
        w->over8_scene = scene;
    }
}

static void write_row(FILE *f, const tarn_sweep_variant *v, const worst_case *w, size_t scene_count)
{
    fprintf(f, "| `%s %s` |", v->option, v->value);
    if (w->psnr_scene == NULL) fprintf(f, " - | - | - |");
    else
        fprintf(f, " %.2f (%s) | %d (%s) | %.3f%% (%s) |", w->psnr, w->psnr_scene, w->max_error, w->max_scene,
                100.0 * w->over8, w->over8_scene);
    if (w->refusals > 0) fprintf(f, " %zu of %zu |\n", w->refusals, scene_count);
    else fprintf(f, " |\n");
}

/* One scene under every variant; a config the frame refuses is noted, not fatal. */
static int measure_scene(const char *path, const tarn_sweep_variant *variants, size_t count, worst_case *worst,
                         char *name, size_t name_size, tarn_error *err)
{
    tarn_loaded_scene loaded;
    if (tarn_scene_load(path, &loaded, err) != 0) return -1;
    snprintf(name, name_size, "%s", loaded.name);
    tarn_sweep_reference reference = {NULL, NULL, 0, 0};
    int failed = tarn_sweep_reference_render(&loaded, &reference, err);
    for (size_t v = 0; v < count && !failed; v++) {
        const tarn_frame_config config = {loaded.width, loaded.height, variants[v].quality, TARN_SWEEP_TIME_MS};
        if (tarn_frame_memory_bytes(&config, &loaded.scene) == 0) {
            worst[v].refusals++;
            continue;
        }
        tarn_compare_metrics m;
        failed = tarn_sweep_error_of(&loaded, &reference, &variants[v].quality, &m, err);
        if (!failed) note_case(&worst[v], &m, name);
    }
    tarn_sweep_reference_free(&reference);
    tarn_scene_free(&loaded);
    return failed ? -1 : 0;
}

int tarn_sweep_stability(const char *const *scene_paths, size_t scene_count, FILE *out, tarn_error *err)
{
    tarn_sweep_variant variants[VARIANTS_MAX];
    worst_case worst[VARIANTS_MAX];
    const size_t count = tarn_sweep_variants(variants, VARIANTS_MAX);
    char (*names)[64] = calloc(scene_count, sizeof *names);
    memset(worst, 0, sizeof worst);
    int failed = names == NULL ? tarn_fail(err, "out of memory") : 0;
    for (size_t s = 0; s < scene_count && !failed; s++)
        failed = measure_scene(scene_paths[s], variants, count, worst, names[s], sizeof names[s], err);
    if (!failed) {
        fprintf(out, "| knob (rest balanced) | lowest PSNR dB (scene) | largest channel error (scene) | "
                     "most pixels off by >8 (scene) | scenes refusing it |\n| --- | --- | --- | --- | --- |\n");
        for (size_t v = 0; v < count; v++) write_row(out, &variants[v], &worst[v], scene_count);
    }
    free(names);
    return failed ? -1 : 0;
}
