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
 * On a board of two cores (FW_PARTS 2, from board.mk's BOARD_CORES) core 1 draws
 * half of every frame (tarn_render_frame_part's part 1) with memory, tile buffers
 * and a stack of its own: core 0 sends it the frame's time, draws part 0, and
 * takes core 1's status back. Each core sends its own tiles, under the panel's
 * lock; the transport waits for the transfer before, whichever core started it, so
 * a core reuses a tile buffer only once its pixels have left.
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
#ifndef FW_PARTS
#define FW_PARTS 1
#endif

/* Before the panel is reset again after a failed frame: long enough not to flood a
 * panel that came loose, short enough not to be noticed otherwise. */
#define RETRY_DELAY_MS 500u

#define TILE_BUFFER_BYTES (2u * SCENE_PIECE_WIDTH * SCENE_PIECE_ROWS)

/* The renderer's working memory, and the two tile buffers the DMA sends from. */
static uint32_t memory[(SCENE_MEMORY_BYTES + 3u) / 4u];
static uint8_t tile_rgb565[2][TILE_BUFFER_BYTES];

#if FW_PARTS == 1
static tarn_status show_frame(panel_sink *sink)
{
    tarn_frame_config config = scene_config;
    config.time_ms = board_milliseconds();
    const tarn_frame_part whole = {0, 1};
    tarn_status status = tarn_render_frame_part(&scene_scene, &config, memory, sizeof memory, whole,
                                                panel_sink_send_tile, sink);
    return panel_sink_frame_status(sink, status);
}
#elif FW_PARTS == 2
/* Core 1's own: memory, tile buffers, sink and stack. */
static uint32_t second_memory[(SCENE_MEMORY_BYTES + 3u) / 4u];
static uint8_t second_tile_rgb565[2][TILE_BUFFER_BYTES];
static panel_sink second_sink;
static uint64_t second_stack[FW_STACK_BYTES / 8u];

/* A tile to the panel while holding its lock. */
static int send_tile_locked(void *user, const tarn_tile *tile)
{
    board_panel_lock();
    const int stop = panel_sink_send_tile(user, tile);
    board_panel_unlock();
    return stop;
}

/* The part `part` of the frame at `time_ms` through `sink`, and the frame's status. */
static tarn_status show_part(uint32_t time_ms, uint32_t *part_memory, uint16_t part, panel_sink *sink)
{
    tarn_frame_config config = scene_config;
    config.time_ms = time_ms;
    const tarn_frame_part half = {part, 2};
    const tarn_status status = tarn_render_frame_part(&scene_scene, &config, part_memory, sizeof memory, half,
                                                      send_tile_locked, sink);
    return panel_sink_frame_status(sink, status);
}

/* Core 1: part 1 of each frame whose time core 0 sends, its status sent back. */
static void second_core_main(void)
{
    for (;;) {
        const uint32_t time_ms = board_core_receive();
        board_core_send((uint32_t)show_part(time_ms, second_memory, 1, &second_sink));
    }
}

static tarn_status show_frame(panel_sink *sink)
{
    const uint32_t time_ms = board_milliseconds();
    board_core_send(time_ms);
    const tarn_status own = show_part(time_ms, memory, 0, sink);
    const tarn_status second = (tarn_status)board_core_receive();
    return own != TARN_OK ? own : second;
}
#else
#error "FW_PARTS: display_main.c draws a frame on one core or two"
#endif

int main(void)
{
    static panel_sink sink;
    if (board_init() != 0) return 2;
    const tarn_panel_transport *transport = board_panel_transport();
    const tarn_panel panel = tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0);
    panel_sink_init(&sink, panel, transport, tile_rgb565[0], tile_rgb565[1], TILE_BUFFER_BYTES, FW_DITHER);
#if FW_PARTS == 2
    panel_sink_init(&second_sink, panel, transport, second_tile_rgb565[0], second_tile_rgb565[1], TILE_BUFFER_BYTES,
                    FW_DITHER);
    if (board_second_core_start(second_core_main, (uint32_t *)(second_stack + sizeof second_stack / 8u)) != 0)
        return 2;
#endif
    for (;;) {
        tarn_status status = tarn_panel_init(&sink.panel, transport);
        while (status == TARN_OK) status = show_frame(&sink);
        (void)transport->delay_ms(transport->user, RETRY_DELAY_MS);
    }
}
