/* main.c: the measured run of the emulated boards. Renders the baked scene with the
 * integer core and sends every tile to an ST7789 through the panel drivers of
 * core/panel/panel.c, whose transport (stream_transport.c) writes the byte stream of
 * tarn_panel.h through the board. The real boards run display_main.c instead.
 *
 * One run: panel init, a frame at each of the FW_TIMES (ms; firmware.mk gives them:
 * 0, 1000 and 5000), all into the same panel stream, the 'E' record, then the frame
 * at the second time once more into a sink that drops the tiles (on a board of
 * FW_PARTS cores, board.mk's BOARD_CORES, then that frame again in FW_PARTS parts,
 * tarn_render_frame_part, one after the other, as the cores would draw them side by
 * side; or, on a board whose cores share one ring, FW_PIPELINE from board.mk's
 * BOARD_CORE_SPLIT, by a strip pipeline's two workers, one after the other, and
 * then, not counted, checked against the whole frame by their checksums), and one
 * line of text on the board's report channel:
 *   target board=B scene=S size=WxH insn_per_pixel=N render_insn_per_pixel=N
 *          [parts=N [split=pipeline] parts_insn_per_pixel=N] stack_peak_bytes=N
 *          frame_insn=N,N,N,N[,N] counter_check=N/2000000
 * insn_per_pixel is the streamed frames' instructions (render, RGB565 conversion and
 * the board's writes of the panel stream) over their pixels, rounded to nearest: an
 * average over the three times (until issue 21 there were two, 0 and 1000 ms, and
 * the figure was their average); render_insn_per_pixel is the core alone (the
 * fourth frame, at the second time); parts_insn_per_pixel is the slowest of its
 * parts, the core's time for the frame on the board's cores (with a pipeline, the
 * time its two workers' schedule takes, pipeline_schedule below); frame_insn gives
 * every frame's count, the streamed ones first, the parts together last;
 * counter_check is what the counter measured for a loop of exactly 2000000
 * instructions (the board's tick-to-instruction ratio, checked).
 *
 * build/firmware/BOARD/scene.h comes from `tarn bake SCENE -o scene.c --name scene`:
 * it declares scene_scene, scene_config and SCENE_MEMORY_BYTES. */
#include <stddef.h>
#include <stdint.h>
#include "board.h"
#include "frame_memory.h"
#include "panel_sink.h"
#include "report.h"
#include "scene.h"
#include "stream_transport.h"
#include "tarn/tarn_checksum.h"
#include "tarn/tarn_panel.h"
#include "tarn/tarn_render.h"

#ifndef FW_TIMES
#error "FW_TIMES: the streamed frames' times in ms, from firmware/firmware.mk"
#endif
#ifndef FW_DITHER
#define FW_DITHER 1
#endif
#ifndef FW_PARTS
#define FW_PARTS 1
#endif
/* FW_STREAM_ONLY (make profile-target): the streamed frames alone, so that a
 * profile counts each instruction of the frames it divides by */
#ifndef FW_STREAM_ONLY
#define FW_STREAM_ONLY 0
#endif
#if FW_STREAM_ONLY && FW_PARTS > 1
#error "FW_STREAM_ONLY: a run on one core (firmware.mk gives it one)"
#endif

/* The renderer's working memory: the only large buffer. */
static uint32_t memory[(FW_MEMORY_BYTES + 3u) / 4u];
/* A row of the widest piece (tile or strip) in RGB565, and at least 64 pixels: the
 * panel stream needs no more, and sends as many rows of a narrow tile as fit in one
 * write. */
#define LINE_PIXELS (SCENE_PIECE_WIDTH > TARN_TILE_SIZE_MAX ? SCENE_PIECE_WIDTH : TARN_TILE_SIZE_MAX)
static uint8_t line[2u * LINE_PIXELS];

#if !FW_STREAM_ONLY
static int drop_tile(void *user, const tarn_tile *tile)
{
    (void)user;
    (void)tile;
    return 0;
}
#endif

/* The streamed frames' times, in ms. */
static const uint32_t times[] = {FW_TIMES};
#define STREAMED_FRAMES (sizeof times / sizeof times[0])
/* the time of the frames after the streamed ones: the second, or the only one */
#define SECOND_TIME (times[STREAMED_FRAMES > 1u ? 1u : 0u])
#define CORE_FRAME STREAMED_FRAMES        /* the core alone, in one part */
#define PARTS_FRAME (STREAMED_FRAMES + 1u) /* and in FW_PARTS, their sum */
#define FRAMES (FW_STREAM_ONLY ? STREAMED_FRAMES : FW_PARTS > 1 ? STREAMED_FRAMES + 2u : STREAMED_FRAMES + 1u)
#if FW_PARTS < 1
#error "FW_PARTS: the board's cores (BOARD_CORES), at least 1"
#endif

/* What the run measured: every frame's instructions, and the slowest part's. Static:
 * off the stack the frames render on. */
static uint64_t frame_instructions[FRAMES];
#if !FW_STREAM_ONLY
static uint64_t slowest_part;
#endif

/* The report line, from every frame's instructions (`frames`); kept out of main() so
 * that its buffer is not on the stack while the frames render. Returns main's exit
 * status. */
static int __attribute__((noinline)) report_run(tarn_status status, const uint64_t *frames, uint64_t counter)
{
    report r;
    report_start(&r);
    if (status != TARN_OK) {
        report_text(&r, "error board=");
        report_text(&r, FW_BOARD_NAME);
        report_text(&r, " status=");
        report_text(&r, tarn_status_text(status));
        report_text(&r, "\n");
        (void)report_send(&r);
        return 1;
    }
    uint64_t pixels = (uint64_t)scene_config.width * scene_config.height;
    report_frame_header(&r, "target", FW_BOARD_NAME, FW_SCENE_LABEL, scene_config.width, scene_config.height);
    uint64_t streamed = 0;
    for (unsigned i = 0; i < STREAMED_FRAMES; i++) streamed += frames[i];
    report_text(&r, " insn_per_pixel=");
    report_number(&r, report_per_pixel(streamed, STREAMED_FRAMES * pixels));
#if !FW_STREAM_ONLY
    report_text(&r, " render_insn_per_pixel=");
    report_number(&r, report_per_pixel(frames[CORE_FRAME], pixels));
    if (FW_PARTS > 1) {
        report_text(&r, " parts=");
        report_number(&r, FW_PARTS);
        if (FW_PIPELINE) report_text(&r, " split=pipeline");
        report_text(&r, " parts_insn_per_pixel=");
        report_number(&r, report_per_pixel(slowest_part, pixels));
    }
#endif
    report_text(&r, " stack_peak_bytes=");
    report_number(&r, board_stack_peak());
    report_text(&r, " frame_insn=");
    for (unsigned i = 0; i < FRAMES; i++) {
        if (i > 0) report_text(&r, ",");
        report_number(&r, frames[i]);
    }
    report_text(&r, " counter_check=");
    report_number(&r, counter);
    report_text(&r, "/");
    report_number(&r, REPORT_COUNTER_CHECK_INSTRUCTIONS);
    report_text(&r, "\n");
    return report_send(&r) != 0 ? 2 : 0;
}

#if FW_PIPELINE
#if FW_PARTS != 2
#error "FW_PIPELINE: a strip pipeline has two workers, on a board of two cores"
#endif
/* Each step's instructions in the measured pipeline frame, and when each ends in
 * the two workers' schedule. Static: off the stack the frame renders on. */
#define PIPELINE_STRIPS_MAX 256
static uint64_t opaque_insn[PIPELINE_STRIPS_MAX], water_insn[PIPELINE_STRIPS_MAX];
static uint64_t opaque_end[PIPELINE_STRIPS_MAX], water_end[PIPELINE_STRIPS_MAX];

/* A time no step reaches: the step it waits for is not taken yet. */
#define NEVER UINT64_MAX

/* When the first `count` steps of a kind, ending at `ends`, are all done, of which
 * the first `taken` are taken; NEVER while one of them is not taken. */
static uint64_t done_at(const uint64_t *ends, int32_t count, int32_t taken)
{
    if (taken < count) return NEVER;
    uint64_t at = 0;
    for (int32_t i = 0; i < count; i++)
        if (ends[i] > at) at = ends[i];
    return at;
}

/* When the frame ends with two cores, from the steps' counts: the begin on one core,
 * then each core, as soon as it is free, takes the next step tarn_render.h lets it
 * (the next water strip whose opaque passes are drawn, or else the next opaque strip
 * the ring has room for) or waits for the first of them. The cores' signals to each
 * other are not counted (a lock taken and a word written a step). */
static uint64_t pipeline_schedule(const tarn_strip_pipeline *p, uint64_t begin)
{
    uint64_t free_at[2] = {begin, begin}, end = begin;
    int32_t next_opaque = 0, next_water = 0;
    while (next_water < p->strips) {
        const unsigned core = free_at[1] < free_at[0];
        const uint64_t now = free_at[core];
        const uint64_t water_at =
            done_at(opaque_end, tarn_strip_pipeline_drawn_before_water(p, next_water), next_opaque);
        const uint64_t opaque_at = next_opaque < p->strips
            ? done_at(water_end, tarn_strip_pipeline_sent_before_opaque(p, next_opaque), next_water)
            : NEVER;
        if (water_at <= now) {
            water_end[next_water] = free_at[core] = now + water_insn[next_water];
            if (free_at[core] > end) end = free_at[core];
            next_water++;
        } else if (opaque_at <= now) {
            opaque_end[next_opaque] = free_at[core] = now + opaque_insn[next_opaque];
            next_opaque++;
        } else if (water_at < NEVER || opaque_at < NEVER) {
            free_at[core] = water_at < opaque_at ? water_at : opaque_at;
        } else {
            return NEVER; /* nothing either core could wait for: not an order tarn_render.h gives */
        }
    }
    return end;
}

/* The frame at `time_ms` by a strip pipeline into `sink`, its steps one after the
 * other on this core, each counted, each by worker 0 or, with `alternate`, by the
 * worker of its strip's parity: their sum into *sum, the two cores' time into
 * *two_cores. */
static tarn_status pipeline_frame(uint32_t time_ms, tarn_tile_sink sink, int alternate, uint64_t *sum,
                                  uint64_t *two_cores)
{
    tarn_frame_config config = scene_config;
    config.time_ms = time_ms;
    tarn_strip_pipeline p;
    const uint64_t start = board_instructions();
    tarn_status status = tarn_strip_pipeline_begin(&scene_scene, &config, memory, sizeof memory, &p);
    const uint64_t begin = board_instructions() - start;
    if (status == TARN_OK && (p.strips == 0 || p.strips > PIPELINE_STRIPS_MAX)) status = TARN_ERR_CONFIG;
    int32_t drawn = 0;
    for (int32_t k = 0; k < p.strips && status == TARN_OK; k++) {
        for (; drawn < tarn_strip_pipeline_drawn_before_water(&p, k); drawn++) {
            const uint64_t at = board_instructions();
            tarn_strip_pipeline_opaque(memory, alternate ? (unsigned)drawn % 2u : 0u, drawn);
            opaque_insn[drawn] = board_instructions() - at;
        }
        const uint64_t at = board_instructions();
        status = tarn_strip_pipeline_water(memory, alternate ? (unsigned)k % 2u : 0u, k, sink, 0);
        water_insn[k] = board_instructions() - at;
    }
    *sum = board_instructions() - start;
    *two_cores = status == TARN_OK ? pipeline_schedule(&p, begin) : 0u;
    return status;
}

/* The checksum (tarn_checksum.h) of the tiles a frame gave sum_tile. */
static uint32_t frame_sum;

static int sum_tile(void *user, const tarn_tile *tile)
{
    (void)user;
    frame_sum = tarn_checksum_tile(frame_sum, tile);
    return 0;
}

/* Whether the pipeline's frame at `time_ms`, both workers taking steps, is the one
 * frame tarn_render_frame draws (their checksums, after the measured frames: summing
 * costs instructions). */
static int pipeline_draws_the_frame(uint32_t time_ms)
{
    tarn_frame_config config = scene_config;
    config.time_ms = time_ms;
    frame_sum = 0u;
    if (tarn_render_frame(&scene_scene, &config, memory, sizeof memory, sum_tile, 0) != TARN_OK) return 0;
    const uint32_t whole = frame_sum;
    uint64_t unused[2];
    frame_sum = 0u;
    return pipeline_frame(time_ms, sum_tile, 1, &unused[0], &unused[1]) == TARN_OK && frame_sum == whole;
}

/* The run's report when the pipeline's frame is not the frame. */
static int report_pipeline_differs(void)
{
    report r;
    report_start(&r);
    report_text(&r, "error board=");
    report_text(&r, FW_BOARD_NAME);
    report_text(&r, " status=the strip pipeline's frame differs from tarn_render_frame's\n");
    (void)report_send(&r);
    return 1;
}
#endif

int main(void)
{
    static panel_sink sink;
    const tarn_frame_part whole_frame = {0, 1};
    tarn_status status;

    if (board_init() != 0) return 2;
    const tarn_panel_transport *transport = board_panel_transport();
    panel_sink_init(&sink, tarn_panel_preset(TARN_PANEL_ST7789_240X240, 0), transport, line, 0,
                    sizeof line, FW_DITHER);

    status = tarn_panel_init(&sink.panel, transport);
    for (unsigned i = 0; i < STREAMED_FRAMES && status == TARN_OK; i++) {
        tarn_frame_config config = scene_config;
        config.time_ms = times[i];
        uint64_t start = board_instructions();
        status = tarn_render_frame_part(&scene_scene, &config, memory, sizeof memory, whole_frame,
                                        panel_sink_send_tile, &sink);
        frame_instructions[i] = board_instructions() - start;
        status = panel_sink_frame_status(&sink, status);
    }
    if (stream_transport_end((uint8_t)status) != 0) return 2;
#if !FW_STREAM_ONLY
    /* The core alone: the same frame, tiles dropped (rendered here, not in a helper: a
     * frame more on the chain would overrun the 16 KB boards' stack reserve). */
    if (status == TARN_OK) {
        tarn_frame_config config = scene_config;
        config.time_ms = SECOND_TIME;
        uint64_t start = board_instructions();
        status = tarn_render_frame_part(&scene_scene, &config, memory, sizeof memory, whole_frame, drop_tile, 0);
        frame_instructions[CORE_FRAME] = board_instructions() - start;
    }
#if FW_PIPELINE
    /* and on a board whose two cores share one ring the frame by a strip pipeline */
    if (status == TARN_OK)
        status = pipeline_frame(SECOND_TIME, drop_tile, 0, &frame_instructions[PARTS_FRAME], &slowest_part);
    if (status == TARN_OK && !pipeline_draws_the_frame(SECOND_TIME)) return report_pipeline_differs();
#elif FW_PARTS > 1
    /* and on a board of several cores the frame in FW_PARTS parts, one after the other
     * (a loop of their own: one loop over the whole frame and the parts takes the
     * 16 KB boards' images past their code budget by 28 bytes) */
    for (uint16_t part = 0; part < FW_PARTS && status == TARN_OK; part++) {
        tarn_frame_config config = scene_config;
        config.time_ms = SECOND_TIME;
        const uint64_t start = board_instructions();
        const tarn_frame_part one_of = {part, FW_PARTS};
        status = tarn_render_frame_part(&scene_scene, &config, memory, sizeof memory, one_of, drop_tile, 0);
        const uint64_t counted = board_instructions() - start;
        frame_instructions[PARTS_FRAME] += counted;
        if (counted > slowest_part) slowest_part = counted;
    }
#endif
#endif /* !FW_STREAM_ONLY */
    return report_run(status, frame_instructions, report_counter_check());
}
