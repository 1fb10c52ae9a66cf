/* fuzz_png_texture.c: any bytes as a PNG, read both as a texture and as a
 * heightfield: an image within the limits each states, or one line. */
#include <stdlib.h>
#include <string.h>

#include "fuzz_input.h"
#include "png_io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void read_as(int (*read)(const char *, tarn_image *, tarn_error *), const char *path)
{
    tarn_image image;
    tarn_error err;
    if (read(path, &image, &err) != 0) {
        if (!fuzz_error_is_one_line(&err)) abort();
        return;
    }
    if (image.width == 0 || image.height == 0) abort();
    tarn_image_free(&image);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write_file("texture.png", data, size);
    read_as(tarn_png_read_texture, path);
    read_as(tarn_png_read_heightfield, path);
    return 0;
}
