/* test_gif.c: `tarn render --frames N -o NAME.gif` writes one animation that giflib's
 * own reader decodes to the frames the PNG sequence holds, within the palette's
 * error; it loops, keeps the sequence's clock, and stays small. --rgb565 gives the
 * panel's colours. Runs the real binary ($TARN_BIN). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <gif_lib.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli_run.h"
#include "png_io.h"

#define TIMEOUT_S 120
#define SCENE "scenes/pond.json"
#define FRAMES 12
/* a power of two, so that the PNG frames read back as textures */
#define SIZE 128

/* tarn render SCENE --size SIZExSIZE --frames FRAMES -o `out` [extra]. */
static void render(const char *out, const char *extra)
{
    char size[32], frames[16];
    snprintf(size, sizeof size, "%dx%d", SIZE, SIZE);
    snprintf(frames, sizeof frames, "%d", FRAMES);
    char *argv[] = {(char *)cli_tarn(), "render", SCENE, "--size", size, "--frames", frames, "-o", (char *)out,
                    (char *)extra, NULL};
    static cli_result r;
    cli_run(argv, -1, -1, TIMEOUT_S, &r);
    if (r.status != 0) fail_msg("tarn render ... -o %s %s: exit %d, %s", out, extra ? extra : "", r.status, r.err);
}

/* The GIF's frames as a viewer shows them: each drawn over the one before, its
 * transparent pixels keeping what was there. */
static uint8_t *decode(const char *path, int *frame_count, int *total_delay, int *loops, GifColorType *palette,
                       int *palette_size)
{
    int error = 0;
    GifFileType *gif = DGifOpenFileName(path, &error);
    if (gif == NULL || DGifSlurp(gif) != GIF_OK) fail_msg("giflib cannot read %s: %s", path, GifErrorString(error));
    const int width = gif->SWidth, height = gif->SHeight;
    assert_int_equal(width, SIZE);
    assert_int_equal(height, SIZE);
    uint8_t *frames = calloc((size_t)gif->ImageCount, 3u * SIZE * SIZE);
    assert_non_null(frames);
    uint8_t canvas[3 * SIZE * SIZE] = {0};
    *total_delay = 0;
    *loops = 0;
    for (int k = 0; k < gif->ImageCount; k++) {
        const SavedImage *image = &gif->SavedImages[k];
        GraphicsControlBlock control = {DISPOSAL_UNSPECIFIED, false, 0, NO_TRANSPARENT_COLOR};
        DGifSavedExtensionToGCB(gif, k, &control);
        *total_delay += control.DelayTime;
        for (int e = 0; e < image->ExtensionBlockCount; e++)
            *loops |= image->ExtensionBlocks[e].Function == APPLICATION_EXT_FUNC_CODE &&
                      image->ExtensionBlocks[e].ByteCount == 11 &&
                      memcmp(image->ExtensionBlocks[e].Bytes, "NETSCAPE2.0", 11) == 0;
        const ColorMapObject *map = image->ImageDesc.ColorMap ? image->ImageDesc.ColorMap : gif->SColorMap;
        const GifImageDesc *d = &image->ImageDesc;
        for (int y = 0; y < d->Height; y++)
            for (int x = 0; x < d->Width; x++) {
                const int index = image->RasterBits[y * d->Width + x];
                if (index == control.TransparentColor) continue;
                uint8_t *pixel = &canvas[3 * ((d->Top + y) * SIZE + d->Left + x)];
                pixel[0] = map->Colors[index].Red;
                pixel[1] = map->Colors[index].Green;
                pixel[2] = map->Colors[index].Blue;
            }
        memcpy(frames + (size_t)k * sizeof canvas, canvas, sizeof canvas);
    }
    *frame_count = gif->ImageCount;
    assert_non_null(gif->SColorMap);
    *palette_size = gif->SColorMap->ColorCount;
    memcpy(palette, gif->SColorMap->Colors, (size_t)*palette_size * sizeof *palette);
    DGifCloseFile(gif, &error);
    return frames;
}

static long distance(const uint8_t *rgb, const GifColorType *c)
{
    const long dr = (long)rgb[0] - c->Red, dg = (long)rgb[1] - c->Green, db = (long)rgb[2] - c->Blue;
    return dr * dr + dg * dg + db * db;
}

/* Pixels of `shown` that are not the palette colour nearest their `png` colour
 * (all but the transparent index 255 are candidates): the count, and the first. */
static size_t pixels_off_palette(const uint8_t *shown, const uint8_t *png, const GifColorType *palette,
                                 int entries, size_t *first)
{
    size_t off = 0;
    for (size_t p = 0; p < (size_t)SIZE * SIZE; p++) {
        long nearest = -1;
        for (int k = 0; k < entries && k < 255; k++) {
            const long d = distance(&png[3 * p], &palette[k]);
            nearest = nearest < 0 || d < nearest ? d : nearest;
        }
        const GifColorType got = {shown[3 * p], shown[3 * p + 1], shown[3 * p + 2]};
        if (distance(&png[3 * p], &got) != nearest && off++ == 0) *first = p;
    }
    return off;
}

/* The GIF of `extra` against the PNG sequence of the same: every pixel of every
 * frame the palette colour nearest the PNG's. */
static void check_gif_against_pngs(const char *extra)
{
    render(cli_in_folder("pond.gif"), extra);
    render(cli_in_folder("pond.png"), extra);
    int count, delay, loops, entries;
    GifColorType palette[256];
    uint8_t *frames = decode(cli_in_folder("pond.gif"), &count, &delay, &loops, palette, &entries);
    if (count != FRAMES) fail_msg("the GIF holds %d frames, not %d", count, FRAMES);
    if (!loops) fail_msg("the GIF does not loop");
    /* 30 frames a second (the default): 12 frames show for 40 hundredths in all */
    if (delay != 100 * FRAMES / 30) fail_msg("the GIF's delays add up to %d hundredths, not %d", delay, 100 * FRAMES / 30);
    for (int k = 0; k < FRAMES; k++) {
        char name[32];
        snprintf(name, sizeof name, "pond-%04d.png", k);
        tarn_image png;
        tarn_error err;
        if (tarn_png_read_texture(cli_in_folder(name), &png, &err) != 0) fail_msg("%s", err.message);
        size_t first = 0;
        const size_t off = pixels_off_palette(frames + (size_t)k * 3u * SIZE * SIZE, png.pixels, palette, entries,
                                              &first);
        if (off)
            fail_msg("%s: frame %d has %zu pixels that are not the palette colour nearest the PNG's, the first "
                     "at (%zu, %zu)", extra ? extra : "", k, off, first % SIZE, first / SIZE);
        tarn_image_free(&png);
    }
    free(frames);
}

static void test_gif_decodes_to_the_png_frames(void **state)
{
    (void)state;
    check_gif_against_pngs(NULL);
}

/* As the panel shows it: each frame's colours are RGB565 widened back to 8 bits. */
static void test_gif_of_the_panel_look(void **state)
{
    (void)state;
    check_gif_against_pngs("--rgb565");
    tarn_image png;
    tarn_error err;
    if (tarn_png_read_texture(cli_in_folder("pond-0000.png"), &png, &err) != 0) fail_msg("%s", err.message);
    for (size_t i = 0; i < (size_t)SIZE * SIZE; i++) {
        const uint8_t *p = &png.pixels[3 * i];
        if (p[0] != ((p[0] >> 3) << 3 | p[0] >> 5) || p[1] != ((p[1] >> 2) << 2 | p[1] >> 6) ||
            p[2] != ((p[2] >> 3) << 3 | p[2] >> 5))
            fail_msg("--rgb565: pixel %zu is %d,%d,%d, no RGB565 colour widened", i, p[0], p[1], p[2]);
    }
    tarn_image_free(&png);
}

/* The bar: three seconds of the pond at 240x240, 30 frames a second. */
static void test_three_seconds_of_the_pond_stay_small(void **state)
{
    (void)state;
    char *argv[] = {(char *)cli_tarn(), "render", SCENE, "--frames", "90", "--fps", "30", "-o",
                    (char *)cli_in_folder("three.gif"), NULL};
    static cli_result r;
    cli_run(argv, -1, -1, TIMEOUT_S, &r);
    if (r.status != 0) fail_msg("tarn render --frames 90 -o three.gif: exit %d, %s", r.status, r.err);
    struct stat info;
    assert_int_equal(stat(cli_in_folder("three.gif"), &info), 0);
    print_message("3 s of the pond at 240x240, 30 fps: %lld bytes\n", (long long)info.st_size);
    if (info.st_size >= 2 * 1024 * 1024) fail_msg("3 s of the pond take %lld bytes, over 2 MB", (long long)info.st_size);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_gif_decodes_to_the_png_frames, cli_make_folder, cli_remove_folder),
        cmocka_unit_test_setup_teardown(test_gif_of_the_panel_look, cli_make_folder, cli_remove_folder),
        cmocka_unit_test_setup_teardown(test_three_seconds_of_the_pond_stay_small, cli_make_folder, cli_remove_folder),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
