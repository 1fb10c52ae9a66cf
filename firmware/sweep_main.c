/* sweep_main.c: one boot measures many qualities ("points") of the baked scene, for
 * a speed/accuracy sweep (`make firmware-sweep`, docs/firmware.md). The build bakes
 * with `tarn bake ... --points FILE`, whose scene.h declares scene_points[] and
 * SCENE_POINT_COUNT (host/bake/bake_points.h); firmware.mk picks this file for main.c
 * with FW_MAIN=sweep.
 *
 * For each point i, the frame at FW_TIME_1 ms, with the bake's size and
 * config.quality = scene_points[i], renders into the static buffer of
 * SCENE_MEMORY_BYTES (the largest any point needs) through a sink that adds each
 * tile to the frame checksum (core/include/tarn/tarn_checksum.h) and converts it to RGB565 twice
 * with tarn_rgb565, the panel path's conversion: without dither, then with the
 * ordered dither, a row at a time into a line buffer. The counter is read at the
 * sink's entry and exit, so the render's instructions exclude the sink's, and
 * around each conversion. One line per point on the report channel:
 *   point index=I insn_per_pixel=N frame_insn=N convert_insn_per_pixel=N
 *         dither_insn_per_pixel=N checksum=XXXXXXXX memory_bytes=N status=ok
 * (status: tarn_status_text of the render), then
 *   sweep board=B scene=S size=WxH points=N counter_check=N/2000000
 * insn_per_pixel is frame_insn over the frame's pixels, rounded to nearest; the
 * convert figures are the conversions' instructions over the pixels. The exit
 * status is 0 when every point rendered, 1 when one failed, 2 when the report
 * could not be written. */
#include <stddef.h>
#include <stdint.h>
#include "board.h"
#include "report.h"
#include "scene.h"
#include "tarn/tarn_checksum.h"
#include "tarn/tarn_panel.h"
#include "tarn/tarn_render.h"

#ifndef FW_TIME_1
#define FW_TIME_1 1000u
#endif
#ifndef SCENE_POINT_COUNT
#error "scene.h has no points: bake with --points FILE (make firmware-sweep POINTS=FILE)"
#endif

/* The renderer's working memory: the only large buffer. */
static uint32_t memory[(SCENE_MEMORY_BYTES + 3u) / 4u];
/* One row of the widest piece (tile or strip) in RGB565, as the panel path converts
 * it. Not static: nothing here reads it, and the conversions' stores must not be
 * optimised away. */
uint8_t sweep_line[2u * SCENE_PIECE_WIDTH];

typedef struct {
    uint32_t checksum;
    uint64_t sink_instructions;    /* everything between the sink's entry and exit */
    uint64_t convert_instructions; /* the RGB565 conversions without dither */
    uint64_t dither_instructions;  /* and with it */
} sweep_sink;

static void convert_tile(const tarn_tile *tile, int dither)
{
    for (uint16_t row = 0; row < tile->height; row++) {
        const uint32_t *rgb = tile->rgb + (size_t)row * tile->stride;
        for (uint16_t i = 0; i < tile->width; i++) {
            uint16_t pixel = tarn_rgb565(rgb[i], (uint16_t)(tile->x + i), (uint16_t)(tile->y + row), dither);
            sweep_line[2u * i] = (uint8_t)(pixel >> 8);
            sweep_line[2u * i + 1u] = (uint8_t)pixel;
        }
    }
}

static int sweep_tile(void *user, const tarn_tile *tile)
{
    const uint64_t entry = board_instructions();
    sweep_sink *s = user;
    s->checksum = tarn_checksum_tile(s->checksum, tile);
    const uint64_t plain = board_instructions();
    convert_tile(tile, 0);
    const uint64_t dithered = board_instructions();
    convert_tile(tile, 1);
    const uint64_t done = board_instructions();
    s->convert_instructions += dithered - plain;
    s->dither_instructions += done - dithered;
    s->sink_instructions += board_instructions() - entry;
    return 0;
}

/* One point's line; kept out of main() so that its buffer is not on the stack while
 * the frames render. Returns 0, or non-zero when the report could not be sent. */
static int __attribute__((noinline)) report_point(unsigned index, const tarn_frame_config *config,
                                                  tarn_status status, uint64_t frame_instructions,
                                                  const sweep_sink *sink)
{
    const uint32_t pixels = (uint32_t)config->width * config->height;
    report r;
    report_start(&r);
    report_text(&r, "point index=");
    report_number(&r, index);
    report_text(&r, " insn_per_pixel=");
    report_number(&r, report_per_pixel(frame_instructions, pixels));
    report_text(&r, " frame_insn=");
    report_number(&r, frame_instructions);
    report_text(&r, " convert_insn_per_pixel=");
    report_number(&r, report_per_pixel(sink->convert_instructions, pixels));
    report_text(&r, " dither_insn_per_pixel=");
    report_number(&r, report_per_pixel(sink->dither_instructions, pixels));
    report_text(&r, " checksum=");
    report_hex32(&r, sink->checksum);
    report_text(&r, " memory_bytes=");
    report_number(&r, tarn_frame_memory_bytes(config, &scene_scene));
    report_text(&r, " status=");
    report_text(&r, status == TARN_OK ? "ok" : tarn_status_text(status));
    report_text(&r, "\n");
    return report_send(&r);
}

static int __attribute__((noinline)) report_sweep(uint64_t counter)
{
    report r;
    report_start(&r);
    report_frame_header(&r, "sweep", FW_BOARD_NAME, FW_SCENE_LABEL, scene_config.width, scene_config.height);
    report_text(&r, " points=");
    report_number(&r, SCENE_POINT_COUNT);
    report_text(&r, " counter_check=");
    report_number(&r, counter);
    report_text(&r, "/");
    report_number(&r, REPORT_COUNTER_CHECK_INSTRUCTIONS);
    report_text(&r, "\n");
    return report_send(&r);
}

int main(void)
{
    int failed = 0, unsent = 0;
    if (board_init() != 0) return 2;
    for (unsigned i = 0; i < SCENE_POINT_COUNT; i++) {
        tarn_frame_config config = scene_config;
        config.quality = scene_points[i];
        config.time_ms = FW_TIME_1;
        sweep_sink sink = {0, 0, 0, 0};
        const uint64_t start = board_instructions();
        const tarn_frame_part whole = {0, 1};
        tarn_status status = tarn_render_frame_part(&scene_scene, &config, memory, sizeof memory, whole, sweep_tile, &sink);
        const uint64_t frame_instructions = board_instructions() - start - sink.sink_instructions;
        failed |= status != TARN_OK;
        unsent |= report_point(i, &config, status, frame_instructions, &sink) != 0;
    }
    unsent |= report_sweep(report_counter_check()) != 0;
    return unsent ? 2 : failed;
}
