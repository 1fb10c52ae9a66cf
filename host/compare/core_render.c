#include "core_render.h"

#include <stdlib.h>

typedef struct {
    uint8_t *rgb, *covered;
    int frame_width;
} frame_sink;

static int tile_covered(const tarn_tile *tile, size_t offset)
{
    if (tile->depth == NULL) return 1; /* the underwater view covers every pixel */
    if (tile->depth_bits == 16) return ((const uint16_t *)tile->depth)[offset] != 0;
    return ((const uint32_t *)tile->depth)[offset] != 0;
}

static int copy_tile(void *user, const tarn_tile *tile)
{
    frame_sink *frame = user;
    for (int y = 0; y < tile->height; y++) {
        for (int x = 0; x < tile->width; x++) {
            size_t from = (size_t)y * tile->stride + (size_t)x;
            size_t to = (size_t)(tile->y + y) * (size_t)frame->frame_width + (size_t)(tile->x + x);
            uint32_t pixel = tile->rgb[from];
            frame->rgb[3 * to] = (uint8_t)(pixel >> 16);
            frame->rgb[3 * to + 1] = (uint8_t)(pixel >> 8);
            frame->rgb[3 * to + 2] = (uint8_t)pixel;
            if (frame->covered) frame->covered[to] = (uint8_t)tile_covered(tile, from);
        }
    }
    return 0;
}

int tarn_core_render(const tarn_scene *scene, const tarn_frame_config *config, uint8_t *rgb,
                     uint8_t *covered, tarn_error *err)
{
    size_t bytes = tarn_frame_memory_bytes(config, scene);
    if (bytes == 0)
        return tarn_fail(err, "frame %ux%u with these quality settings: %s (a frame this large needs fewer subpixel bits)",
                         config->width, config->height, tarn_status_text(TARN_ERR_CONFIG));
    void *memory = malloc(bytes);
    if (memory == NULL) return tarn_fail(err, "out of memory for %zu bytes of tile buffers", bytes);
    frame_sink sink = {rgb, covered, config->width};
    tarn_status status = tarn_render_frame(scene, config, memory, bytes, copy_tile, &sink);
    free(memory);
    if (status != TARN_OK) return tarn_fail(err, "render failed: %s", tarn_status_text(status));
    return 0;
}
