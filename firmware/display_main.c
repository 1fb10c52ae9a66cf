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

/* Each core's own: the renderer's working memory, the two tile buffers the DMA
 * sends from, and the sink that fills them. */
static uint32_t memory[FW_PARTS][(SCENE_MEMORY_BYTES + 3u) / 4u];
static uint8_t tile_rgb565[FW_PARTS][2][TILE_BUFFER_BYTES];
static panel_sink sinks[FW_PARTS];

#if FW_PARTS == 1
#define SEND_TILE panel_sink_send_tile
#else
/* A tile to the panel while holding its lock. */
static int send_tile_locked(void *user, const tarn_tile *tile)
{
    board_panel_lock();
    const int stop = panel_sink_send_tile(user, tile);
    board_panel_unlock();
    return stop;
}
#define SEND_TILE send_tile_locked
#endif

/* Part `part` of the frame at `time_ms`, in that part's memory and through its sink;
 * the frame's status. */
static tarn_status show_part(uint32_t time_ms, uint16_t part)
{
    tarn_frame_config config = scene_config;
    config.time_ms = time_ms;
    const tarn_frame_part share = {part, FW_PARTS};
    const tarn_status status = tarn_render_frame_part(&scene_scene, &config, memory[part], sizeof memory[part], share,
                                                      SEND_TILE, &sinks[part]);
    return panel_sink_frame_status(&sinks[part], status);
}

#if FW_PARTS == 1
static tarn_status show_frame(void)
{
    return show_part(board_milliseconds(), 0);
}
#elif FW_PARTS == 2
static uint64_t second_stack[FW_STACK_BYTES / 8u];

/* Core 1: part 1 of each frame whose time core 0 sends, its status sent back. */
static void second_core_main(void)
{
    for (;;) {
        const uint32_t time_ms = board_core_receive();
        board_core_send((uint32_t)show_part(time_ms, 1));
    }
}

static tarn_status show_frame(void)
{
    const uint32_t time_ms = board_milliseconds();
    board_core_send(time_ms);
    const tarn_status own = show_part(time_ms, 0);
    const tarn_status second = (tarn_status)board_core_receive();
    return own != TARN_OK ? own : second;
}
#else
#error "FW_PARTS: display_main.c draws a frame on one core or two"
#endif

int main(void)
{
    if (board_init() != 0) return 2;
    const tarn_panel_transport *transport = board_panel_transport();
    const tarn_panel panel = tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0);
    for (uint16_t part = 0; part < FW_PARTS; part++)
        panel_sink_init(&sinks[part], panel, transport, tile_rgb565[part][0], tile_rgb565[part][1], TILE_BUFFER_BYTES,
                        FW_DITHER);
#if FW_PARTS == 2
    if (board_second_core_start(second_core_main, (uint32_t *)(second_stack + sizeof second_stack / 8u)) != 0)
        return 2;
#endif
    for (;;) {
        tarn_status status = tarn_panel_init(&panel, transport);
        while (status == TARN_OK) status = show_frame();
        (void)transport->delay_ms(transport->user, RETRY_DELAY_MS);
    }
}
