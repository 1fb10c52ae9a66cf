/* fuzz_bake.c: any bytes as a scene file, baked: three files, or one line and no
 * file at all. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bake.h"
#include "fuzz_input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int exists(const char *name)
{
    return access(fuzz_path(name), F_OK) == 0;
}

static void remove_outputs(void)
{
    static const char *const names[] = {"s/baked.c", "s/baked.h", "s/baked_link.h"};
    for (size_t i = 0; i < 3; i++) unlink(fuzz_path(names[i]));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write_file("s/scene.json", data, size);
    tarn_loaded_scene scene;
    tarn_error err;
    if (tarn_scene_load(path, &scene, &err) != 0) return 0;
    char output[4096];
    strncpy(output, fuzz_path("s/baked.c"), sizeof output - 1);
    output[sizeof output - 1] = '\0';
    tarn_bake_options options = {"scene.json", output, NULL, {scene.width, scene.height, tarn_quality_default(), 0},
                                 0, NULL};
    tarn_bake_result result;
    const int status = tarn_bake(&scene, &options, &result, &err);
    const int written = exists("s/baked.c") + exists("s/baked.h") + exists("s/baked_link.h");
    if (status == 0 ? written != 3 : (written != 0 || err.message[0] == '\0' || strchr(err.message, '\n')))
        abort(); /* all or nothing, and a failure says why in one line */
    remove_outputs();
    tarn_scene_free(&scene);
    return 0;
}
