/* fuzz_obj_load.c: any bytes as an OBJ mesh: a mesh within the renderer's limits,
 * or one line saying what is wrong. */
#include <stdlib.h>
#include <string.h>

#include "fuzz_input.h"
#include "mesh_gen.h"
#include "obj_load.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write_file("mesh.obj", data, size);
    tarn_mesh_buffer mesh;
    tarn_error err;
    if (tarn_obj_load(path, NULL, &mesh, &err) != 0) {
        if (!fuzz_error_is_one_line(&err)) abort();
        return 0;
    }
    const tarn_mesh *m = &mesh.mesh;
    for (uint32_t i = 0; i < 3u * m->triangle_count; i++)
        if (m->indices[i] >= m->vertex_count) abort(); /* an index past the vertices got through */
    tarn_mesh_buffer_free(&mesh);
    return 0;
}
