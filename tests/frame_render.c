/* frame_render.c: see frame_render.h. */
#include "frame_render.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <cmocka.h>

#include "core_render.h"

const char *const test_frame_scenes[TEST_FRAME_SCENE_COUNT] = {
    "scenes/pond.json", "scenes/beach.json", "scenes/murky.json", "scenes/lake.json",
    "scenes/underwater.json", "scenes/effects/refraction.json", "scenes/effects/fresnel.json",
    "scenes/effects/foam.json", "scenes/effects/sparkles.json", "scenes/extremes/dense.json",
    "scenes/extremes/far.json", "scenes/extremes/grazing.json", "scenes/extremes/huge.json",
    "scenes/extremes/steep.json", "scenes/extremes/tiny.json", "scenes/extremes/deep-squared.json",
    "scenes/extremes/huge-near.json", "scenes/extremes/uv-scale.json", "scenes/extremes/skim-above.json",
    "scenes/extremes/skim-below.json", "scenes/extremes/late.json",
};

uint8_t *test_render_rgb(const tarn_scene *scene, const tarn_frame_config *config, const char *what)
{
    uint8_t *rgb = malloc(3u * config->width * config->height);
    assert_non_null(rgb);
    tarn_error err;
    if (tarn_core_render(scene, config, rgb, NULL, &err) != 0) fail_msg("%s: %s", what, err.message);
    return rgb;
}

tarn_status test_render_status(const tarn_scene *scene, const tarn_frame_config *config)
{
    const size_t bytes = tarn_frame_memory_bytes(config, scene);
    void *memory = malloc(bytes > 0 ? bytes : 1u);
    assert_non_null(memory);
    const tarn_status status = tarn_render_frame(scene, config, memory, bytes, NULL, NULL);
    free(memory);
    return status;
}
