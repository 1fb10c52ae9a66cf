/* fuzz_bake.c: any bytes as a scene file, baked: three files, or one line and no
 * file at all. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bake.h"
#include "fuzz_input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const char *const outputs[] = {"s/baked.c", "s/baked.h", "s/baked_link.h"};

/* How many of the three outputs exist; all are removed for the next input. */
static int outputs_written_then_removed(void)
{
    int written = 0;
    for (size_t i = 0; i < 3; i++) {
        written += access(fuzz_path(outputs[i]), F_OK) == 0;
        unlink(fuzz_path(outputs[i]));
    }
    return written;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write_file("s/scene.json", data, size);
    tarn_loaded_scene scene;
    tarn_error err;
    if (tarn_scene_load(path, &scene, &err) != 0) return 0;
    char output[4096];
    strncpy(output, fuzz_path(outputs[0]), sizeof output - 1);
    output[sizeof output - 1] = '\0';
    const int backdrop = (int)(size % 3u); /* each kind of backdrop, by the input's length */
    tarn_bake_options options = {"scene.json", output, NULL, NULL, 1, tarn_backdrop_of((tarn_backdrop_kind)backdrop),
                                 {scene.width, scene.height, tarn_quality_default(), 0}, 0, NULL, 1};
    tarn_bake_result result;
    const int status = tarn_bake(&scene, &options, &result, &err);
    const int written = outputs_written_then_removed();
    if (status == 0 ? written != 3 : (written != 0 || !fuzz_error_is_one_line(&err)))
        abort(); /* all or nothing, and a failure says why in one line */
    tarn_scene_free(&scene);
    return 0;
}
