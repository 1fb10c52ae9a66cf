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
 * Where the cores share one ring of strips instead (FW_PIPELINE, from board.mk's
 * BOARD_CORE_SPLIT := pipeline), core 0 begins each frame (tarn_strip_pipeline_begin)
 * and sends core 1 its strips and how far ahead they reach; core 1 draws the opaque
 * strips, core 0 the water over them and sends each strip to the panel, drawing the
 * next opaque strip itself rather than wait for one. A core takes a strip under a
 * hardware spinlock and marks what it has done in words of SRAM the other reads, as
 * tarn_render.h orders them; core 1 tells core 0 when the frame's memory is free
 * again. A frame that cannot be drawn in strips is drawn by core 0 alone.
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
#ifndef FW_PIPELINE
#define FW_PIPELINE 0
#endif

/* Before the panel is reset again after a failed frame: long enough not to flood a
 * panel that came loose, short enough not to be noticed otherwise. */
#define RETRY_DELAY_MS 500u

#define TILE_BUFFER_BYTES (2u * SCENE_PIECE_WIDTH * SCENE_PIECE_ROWS)

#if FW_PIPELINE
#if FW_PARTS != 2
#error "FW_PIPELINE: a strip pipeline's two workers, on a board of two cores"
#endif
#if SCENE_PIPELINE_MEMORY_BYTES > SCENE_MEMORY_BYTES
#define MEMORY_BYTES SCENE_PIPELINE_MEMORY_BYTES
#else
#define MEMORY_BYTES SCENE_MEMORY_BYTES
#endif
/* The cores' one frame memory, and core 0's tile buffers and sink. */
static uint32_t memory[1][(MEMORY_BYTES + 3u) / 4u];
static uint8_t tile_rgb565[1][2][TILE_BUFFER_BYTES];
static panel_sink sinks[1];
static uint64_t second_stack[FW_STACK_BYTES / 8u];
/* What each core has done this frame, which the other reads: the next strip no core
 * has taken, each strip's opaque pass drawn, the strips core 0 has sent. */
#define PIPELINE_STRIPS_MAX 256
static volatile int32_t next_opaque, water_sent;
static volatile uint8_t opaque_drawn[PIPELINE_STRIPS_MAX];

/* The next strip no core has taken, now taken, if the ring has room for it; -1
 * otherwise. */
static int32_t take_strip(const tarn_strip_pipeline *p)
{
    board_strips_lock();
    int32_t d = next_opaque;
    if (d < p->strips && water_sent >= tarn_strip_pipeline_sent_before_opaque(p, d))
        next_opaque = d + 1;
    else
        d = -1;
    board_strips_unlock();
    return d;
}

/* Strip d's opaque pass by `worker`, then marked drawn for the other core. */
static void draw_opaque_strip(tarn_pipeline_worker worker, int32_t d)
{
    tarn_strip_pipeline_opaque(memory[0], worker, d);
    board_cores_order();
    opaque_drawn[d] = 1u;
}

/* Core 1: the opaque strips of each frame core 0 begins, as the ring has room for
 * them, then a word that the memory is free again. */
static void second_core_main(void)
{
    for (;;) {
        tarn_strip_pipeline p;
        p.strips = (int32_t)board_core_receive();
        p.ahead = (int32_t)board_core_receive();
        while (next_opaque < p.strips) {
            const int32_t d = take_strip(&p);
            if (d >= 0) draw_opaque_strip(TARN_OPAQUE_WORKER, d);
        }
        board_core_send(0u);
    }
}

/* Core 0: the water strips, each to the panel once the opaque strips it reads are
 * drawn, taking the next opaque strip itself rather than wait; a strip the sink
 * refused lets core 1 run to the end. */
static tarn_status send_strips(const tarn_strip_pipeline *p)
{
    tarn_status status = TARN_OK;
    int32_t drawn = 0; /* strips 0 .. drawn - 1 are drawn */
    for (int32_t k = 0; k < p->strips && status == TARN_OK; k++) {
        while (drawn < tarn_strip_pipeline_drawn_before_water(p, k)) {
            if (opaque_drawn[drawn]) {
                drawn++;
                continue;
            }
            const int32_t d = take_strip(p);
            if (d >= 0) draw_opaque_strip(TARN_WATER_WORKER, d);
        }
        board_cores_order();
        status = tarn_strip_pipeline_water(memory[0], k, panel_sink_send_tile, &sinks[0]);
        water_sent = status == TARN_OK ? k + 1 : INT32_MAX;
    }
    return status;
}

static tarn_status show_frame(void)
{
    tarn_frame_config config = scene_config;
    config.time_ms = board_milliseconds();
    tarn_strip_pipeline p;
    tarn_status status = tarn_strip_pipeline_begin(&scene_scene, &config, memory[0], sizeof memory[0], &p);
    if (status == TARN_OK && (p.strips == 0 || p.strips > PIPELINE_STRIPS_MAX)) /* in tiles, on core 0 */
        status = tarn_render_frame(&scene_scene, &config, memory[0], sizeof memory[0], panel_sink_send_tile, &sinks[0]);
    else if (status == TARN_OK) {
        next_opaque = 0;
        water_sent = 0;
        for (int32_t d = 0; d < p.strips; d++) opaque_drawn[d] = 0u;
        board_cores_order();
        board_core_send((uint32_t)p.strips);
        board_core_send((uint32_t)p.ahead);
        status = send_strips(&p);
        (void)board_core_receive(); /* core 1 is done with the frame's memory */
    }
    return panel_sink_frame_status(&sinks[0], status);
}
#else
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
#endif

int main(void)
{
    if (board_init() != 0) return 2;
    const tarn_panel_transport *transport = board_panel_transport();
    const tarn_panel panel = tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0);
    for (uint16_t part = 0; part < sizeof sinks / sizeof sinks[0]; part++)
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
