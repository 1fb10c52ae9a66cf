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
 * and wakes core 1; then each core takes the frame's steps (a strip's opaque pass, or
 * a strip's water and the strip to the panel) as tarn_render.h orders them, under a
 * hardware spinlock, and marks each step done in SRAM the other reads; core 1 sends
 * back its status when no step is left. A frame that cannot be drawn in strips is
 * drawn by core 0 alone.
 *
 * build/firmware/BOARD/scene.h comes from `tarn bake SCENE -o scene.c --name scene`:
 * it declares scene_scene, scene_config and SCENE_MEMORY_BYTES. */
#include <stddef.h>
#include <stdint.h>
#include "board.h"
#include "frame_memory.h"
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

#if FW_PIPELINE && FW_PARTS != 2
#error "FW_PIPELINE: a strip pipeline's two workers, on a board of two cores"
#endif
#if FW_PARTS != 1 && FW_PARTS != 2
#error "FW_PARTS: display_main.c draws a frame on one core or two"
#endif

/* The renderer's working memory: each core's own, or with a strip pipeline one for
 * both. */
#define MEMORIES (FW_PIPELINE ? 1 : FW_PARTS)
static uint32_t memory[MEMORIES][(FW_MEMORY_BYTES + 3u) / 4u];
/* Each core's two tile buffers the DMA sends from, and the sink that fills them. */
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

#if !FW_PIPELINE
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
#endif

#if FW_PIPELINE
/* The frame both cores draw, and what they have done, which both read: the next
 * strip whose opaque pass, and whose water, no core has taken, each strip's steps
 * done, and whether a step failed. */
#define PIPELINE_STRIPS_MAX 256
static tarn_strip_pipeline pipeline;
static volatile int32_t next_opaque, next_water, failed;
static volatile uint8_t opaque_drawn[PIPELINE_STRIPS_MAX], water_sent[PIPELINE_STRIPS_MAX];

/* Whether the first `count` flags are set. */
static int all_set(const volatile uint8_t *flags, int32_t count)
{
    for (int32_t d = 0; d < count; d++)
        if (!flags[d]) return 0;
    return 1;
}

/* The step this core takes next, as tarn_render.h orders them, under the strips'
 * lock: the next water strip if the opaque passes it reads are drawn, or else the
 * next opaque strip if the water over its slot is sent; *water says which. -1: none
 * now. */
static int32_t take_step(int *water)
{
    const tarn_strip_pipeline *p = &pipeline;
    int32_t step = -1;
    board_strips_lock();
    *water = next_water < p->strips && all_set(opaque_drawn, tarn_strip_pipeline_drawn_before_water(p, next_water));
    if (*water)
        step = next_water++;
    else if (next_opaque < p->strips && all_set(water_sent, tarn_strip_pipeline_sent_before_opaque(p, next_opaque)))
        step = next_opaque++;
    board_strips_unlock();
    return step;
}

/* Core `worker`'s share of the pipeline's frame: steps until every one is taken or
 * one failed (a strip the sink refused); its status. */
static tarn_status draw_share(unsigned worker)
{
    tarn_status status = TARN_OK;
    while (!failed && (next_water < pipeline.strips || next_opaque < pipeline.strips)) {
        int water;
        const int32_t step = take_step(&water);
        if (step < 0) continue; /* the other core's step first */
        if (water)
            status = tarn_strip_pipeline_water(memory[0], worker, step, SEND_TILE, &sinks[worker]);
        else
            tarn_strip_pipeline_opaque(memory[0], worker, step);
        board_cores_order();
        (water ? water_sent : opaque_drawn)[step] = 1u;
        if (status != TARN_OK) failed = 1;
    }
    return panel_sink_frame_status(&sinks[worker], status);
}

/* Core 1's share of the frame core 0 began, for core 0's word. */
static tarn_status second_share(uint32_t word)
{
    (void)word;
    return draw_share(1);
}

/* Core 0 begins the frame at `time_ms` (the scene posed, the bins), then both draw
 * it; a frame that cannot be drawn in strips core 0 draws alone. Returns 0 when core
 * 1 draws with it, with *status then core 0's share's. */
static int begin_frame(uint32_t time_ms, tarn_status *status)
{
    tarn_frame_config config = scene_config;
    config.time_ms = time_ms;
    *status = tarn_strip_pipeline_begin(&scene_scene, &config, memory[0], sizeof memory[0], &pipeline);
    if (*status == TARN_OK && (pipeline.strips == 0 || pipeline.strips > PIPELINE_STRIPS_MAX)) {
        /* in tiles, on core 0 alone */
        *status = tarn_render_frame(&scene_scene, &config, memory[0], sizeof memory[0], SEND_TILE, &sinks[0]);
        *status = panel_sink_frame_status(&sinks[0], *status);
        return 1;
    }
    if (*status != TARN_OK) return 1;
    next_opaque = next_water = failed = 0;
    for (int32_t d = 0; d < pipeline.strips; d++) opaque_drawn[d] = water_sent[d] = 0u;
    board_cores_order();
    return 0;
}
#elif FW_PARTS == 2
/* Core 1's share: part 1 of the frame at the time core 0 sends. */
static tarn_status second_share(uint32_t time_ms)
{
    return show_part(time_ms, 1);
}
#endif

#if FW_PARTS == 1
static tarn_status show_frame(void)
{
    return show_part(board_milliseconds(), 0);
}
#else
/* Core 1's stack, in a section of its own that a board's link.ld may place apart
 * (the RP2040's in SRAM4-5); cortex_m_sections.ld's .bss takes it otherwise. */
static uint64_t second_stack[FW_STACK_BYTES / 8u] __attribute__((section(".bss.second_stack")));

/* Core 1: its share of each frame core 0 sends it a word for, its status sent back. */
static void second_core_main(void)
{
    for (;;) board_core_send((uint32_t)second_share(board_core_receive()));
}

static tarn_status show_frame(void)
{
    const uint32_t time_ms = board_milliseconds();
#if FW_PIPELINE
    tarn_status own;
    if (begin_frame(time_ms, &own) != 0) return own;
    board_core_send(time_ms);
    own = draw_share(0);
#else
    board_core_send(time_ms);
    const tarn_status own = show_part(time_ms, 0);
#endif
    const tarn_status second = (tarn_status)board_core_receive();
    return own != TARN_OK ? own : second;
}
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
