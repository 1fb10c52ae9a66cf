/* fuzz_scene_load.c: any bytes as a scene file. Loading either succeeds, and the
 * scene renders a small frame through the core, or fails with one non-empty line;
 * never a crash, a leak, undefined behaviour or a hang. */
#include <stdlib.h>
#include <string.h>

#include "core_render.h"
#include "fuzz_input.h"
#include "scene_load.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write_file("s/scene.json", data, size);
    tarn_loaded_scene scene;
    tarn_error err;
    if (tarn_scene_load(path, &scene, &err) != 0) {
        if (!fuzz_error_is_one_line(&err)) abort();
        return 0;
    }
    tarn_frame_config config = {32, 24, tarn_quality_default(), 1234};
    config.quality.tile_size = 16;
    uint8_t rgb[32 * 24 * 3], covered[32 * 24];
    if (tarn_core_render(&scene.scene, &config, rgb, covered, &err) != 0 && !fuzz_error_is_one_line(&err)) abort();
    tarn_scene_free(&scene);
    return 0;
}
