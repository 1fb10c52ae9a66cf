/* display_main.c: the firmware of the real boards. Renders the baked scene on an
 * ST7789 240x240 forever, each frame at the board's millisecond clock, so the
 * water moves as it would on the host at that time.
 *
 * The tiles alternate between two RGB565 buffers, each large enough for the largest
 * tile, and the transport (dma_transport.c) sends each tile by DMA while the core
 * renders the next one (panel_sink.h). A frame that fails (a transfer timed out, the
 * DMA reported an error) ends early; the panel is then reset and initialised again,
 * and the frames go on. There is no report channel: the figures of a board come from
 * its build (size, stack bound) and from the emulated boards' measured runs.
 *
 * build/firmware/BOARD/scene.h comes from `tarn bake SCENE -o scene.c --name scene`:
 * it declares scene_scene, scene_config and SCENE_MEMORY_BYTES. */
#include <stddef.h>
#include <stdint.h>
#include "board.h"
#include "panel_sink.h"
#include "scene.h"
#include "tarn/tarn_panel.h"
#include "tarn/tarn_render.h"

#ifndef FW_DITHER
#define FW_DITHER 1
#endif

/* Before the panel is reset again after a failed frame: long enough not to flood a
 * panel that came loose, short enough not to be noticed otherwise. */
#define RETRY_DELAY_MS 500u

#define TILE_BUFFER_BYTES (2u * SCENE_PIECE_WIDTH * SCENE_PIECE_ROWS)

/* The renderer's working memory, and the two tile buffers the DMA sends from. */
static uint32_t memory[(SCENE_MEMORY_BYTES + 3u) / 4u];
static uint8_t tile_rgb565[2][TILE_BUFFER_BYTES];

static tarn_status show_frame(panel_sink *sink)
{
    tarn_frame_config config = scene_config;
    config.time_ms = board_milliseconds();
    tarn_status status = tarn_render_frame(&scene_scene, &config, memory, sizeof memory,
                                           panel_sink_send_tile, sink);
    return panel_sink_frame_status(sink, status);
}

int main(void)
{
    static panel_sink sink;
    if (board_init() != 0) return 2;
    const tarn_panel_transport *transport = board_panel_transport();
    panel_sink_init(&sink, tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0), transport,
                    tile_rgb565[0], tile_rgb565[1], TILE_BUFFER_BYTES, FW_DITHER);
    for (;;) {
        tarn_status status = tarn_panel_init(&sink.panel, transport);
        while (status == TARN_OK) status = show_frame(&sink);
        (void)transport->delay_ms(transport->user, RETRY_DELAY_MS);
    }
}
