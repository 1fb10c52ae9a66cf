#include "gif_io.h"

#include <gif_lib.h>
#include <stdlib.h>
#include <string.h>

#include "atomic_file.h"

#define PALETTE_COLOURS 255  /* the 256th index is transparent */
#define TRANSPARENT_INDEX 255

/* The frames' palette indices, every frame one after the other, and the palette. */
typedef struct {
    GifByteType *indices;
    GifColorType palette[256];
    int colours;
} quantized;

/* A frame's rectangle of changed indices. */
typedef struct {
    int left, top, width, height;
} gif_rect;

static int write_to_file(GifFileType *gif, const GifByteType *bytes, int length)
{
    FILE *file = gif->UserData;
    return (int)fwrite(bytes, 1, (size_t)length, file);
}

/* The palette entry nearest `rgb` (squared distance). */
static GifByteType nearest_entry(const quantized *q, const uint8_t *rgb)
{
    long best = -1;
    GifByteType index = 0;
    for (int k = 0; k < q->colours; k++) {
        const long dr = (long)rgb[0] - q->palette[k].Red, dg = (long)rgb[1] - q->palette[k].Green,
                   db = (long)rgb[2] - q->palette[k].Blue;
        const long distance = dr * dr + dg * dg + db * db;
        if (best < 0 || distance < best) {
            best = distance;
            index = (GifByteType)k;
        }
    }
    return index;
}

/* Every pixel to its nearest palette entry: the median cut places pixels by their
 * 5-bit cell, which costs up to 4 levels a channel more than the palette must.
 * Each colour is looked up once (an animation holds far fewer colours than
 * pixels): `known` marks the 24-bit colours already found. */
static int remap_to_nearest(const tarn_gif_animation *a, quantized *q, tarn_error *err)
{
    const size_t pixels = (size_t)a->width * a->height * a->frame_count;
    GifByteType *entry = malloc((size_t)1 << 24);
    uint8_t *known = calloc((size_t)1 << 21, 1);
    if (entry == NULL || known == NULL) {
        free(entry);
        free(known);
        return tarn_fail(err, "out of memory matching %u frames to their palette", a->frame_count);
    }
    for (size_t p = 0; p < pixels; p++) {
        const uint8_t *rgb = &a->rgb[3 * p];
        const uint32_t colour = (uint32_t)rgb[0] << 16 | (uint32_t)rgb[1] << 8 | rgb[2];
        if (!(known[colour >> 3] & (1u << (colour & 7)))) {
            entry[colour] = nearest_entry(q, rgb);
            known[colour >> 3] |= (uint8_t)(1u << (colour & 7));
        }
        q->indices[p] = entry[colour];
    }
    free(entry);
    free(known);
    return 0;
}

/* One palette for every frame: giflib's median cut over all their pixels at once. */
static int quantize(const tarn_gif_animation *a, quantized *q, tarn_error *err)
{
    const size_t pixels = (size_t)a->width * a->height * a->frame_count;
    GifByteType *channels = malloc(3 * pixels);
    q->indices = malloc(pixels);
    int failed = channels == NULL || q->indices == NULL;
    for (size_t p = 0; !failed && p < pixels; p++)
        for (int c = 0; c < 3; c++) channels[(size_t)c * pixels + p] = a->rgb[3 * p + (size_t)c];
    q->colours = PALETTE_COLOURS;
    memset(q->palette, 0, sizeof q->palette);
    if (!failed)
        failed = GifQuantizeBuffer(a->width, (unsigned)(a->height * a->frame_count), &q->colours, channels,
                                   channels + pixels, channels + 2 * pixels, q->indices, q->palette) != GIF_OK;
    free(channels);
    if (failed) return tarn_fail(err, "out of memory choosing the palette of %u frames", a->frame_count);
    return remap_to_nearest(a, q, err);
}

/* The smallest rectangle holding every index of `now` that differs from `before`
 * (1x1 at the corner when none does: a frame must still hold its time). */
static gif_rect changed_rect(const GifByteType *before, const GifByteType *now, int width, int height)
{
    int left = width, right = -1, top = height, bottom = -1;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            if (before[(size_t)y * width + x] == now[(size_t)y * width + x]) continue;
            left = x < left ? x : left;
            right = x > right ? x : right;
            top = y < top ? y : top;
            bottom = y > bottom ? y : bottom;
        }
    if (right < 0) return (gif_rect){0, 0, 1, 1};
    return (gif_rect){left, top, right - left + 1, bottom - top + 1};
}

/* Hundredths of a second frame k shows for: the differences of its start times, so
 * that the rounding never adds up. */
static int frame_delay(unsigned k, unsigned fps)
{
    return (int)((100u * (k + 1u)) / fps - (100u * k) / fps);
}

static int put_loop_forever(GifFileType *gif)
{
    static GifByteType netscape[] = "NETSCAPE2.0";
    static GifByteType repeat[] = {1, 0, 0}; /* sub-block 1, loop count 0: for ever */
    return EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE) == GIF_OK &&
                   EGifPutExtensionBlock(gif, 11, netscape) == GIF_OK &&
                   EGifPutExtensionBlock(gif, 3, repeat) == GIF_OK && EGifPutExtensionTrailer(gif) == GIF_OK
               ? GIF_OK
               : GIF_ERROR;
}

/* Frame k's rectangle: its indices, or transparent where the frame before shows
 * the same. */
static int put_frame(GifFileType *gif, const tarn_gif_animation *a, const quantized *q, unsigned k,
                     GifByteType *line)
{
    const size_t frame_pixels = (size_t)a->width * a->height;
    const GifByteType *now = q->indices + k * frame_pixels;
    const GifByteType *before = k > 0 ? now - frame_pixels : NULL;
    const gif_rect r = before ? changed_rect(before, now, a->width, a->height)
                              : (gif_rect){0, 0, a->width, a->height};
    GraphicsControlBlock control = {DISPOSE_DO_NOT, false, frame_delay(k, a->fps),
                                    before ? TRANSPARENT_INDEX : NO_TRANSPARENT_COLOR};
    GifByteType extension[4];
    const size_t length = EGifGCBToExtension(&control, extension);
    if (EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, (int)length, extension) != GIF_OK ||
        EGifPutImageDesc(gif, r.left, r.top, r.width, r.height, false, NULL) != GIF_OK)
        return GIF_ERROR;
    for (int y = r.top; y < r.top + r.height; y++) {
        for (int x = 0; x < r.width; x++) {
            const size_t i = (size_t)y * a->width + (size_t)(r.left + x);
            line[x] = before && before[i] == now[i] ? TRANSPARENT_INDEX : now[i];
        }
        if (EGifPutLine(gif, line, r.width) != GIF_OK) return GIF_ERROR;
    }
    return GIF_OK;
}

static int put_animation(GifFileType *gif, const tarn_gif_animation *a, const quantized *q)
{
    ColorMapObject *map = GifMakeMapObject(256, q->palette);
    GifByteType *line = malloc(a->width);
    int status = map != NULL && line != NULL ? GIF_OK : GIF_ERROR;
    EGifSetGifVersion(gif, true);
    if (status == GIF_OK) status = EGifPutScreenDesc(gif, a->width, a->height, 8, 0, map);
    if (status == GIF_OK) status = put_loop_forever(gif);
    for (unsigned k = 0; status == GIF_OK && k < a->frame_count; k++) status = put_frame(gif, a, q, k, line);
    GifFreeMapObject(map);
    free(line);
    return status;
}

static int encode(FILE *file, const tarn_gif_animation *a, const quantized *q, const char *path, tarn_error *err)
{
    int error = 0;
    GifFileType *gif = EGifOpen(file, write_to_file, &error);
    if (gif == NULL) return tarn_fail(err, "%s: cannot start the GIF: %s", path, GifErrorString(error));
    const int status = put_animation(gif, a, q);
    const int reason = gif->Error;
    int close_error = 0;
    const int closed = EGifCloseFile(gif, &close_error);
    if (status != GIF_OK || closed != GIF_OK)
        return tarn_fail(err, "%s: cannot write the GIF: %s", path,
                         GifErrorString(status != GIF_OK ? reason : close_error));
    return 0;
}

int tarn_gif_write(const char *path, const tarn_gif_animation *a, tarn_error *err)
{
    quantized q = {NULL, {{0, 0, 0}}, 0};
    tarn_atomic_file out;
    if (a->frame_count == 0 || a->width == 0 || a->height == 0 || a->fps == 0 || a->fps > TARN_GIF_FPS_MAX)
        return tarn_fail(err, "%s: a GIF needs frames of at least 1x1 at 1..%u a second", path, TARN_GIF_FPS_MAX);
    int failed = quantize(a, &q, err) || tarn_atomic_open(&out, path, err);
    if (!failed) {
        failed = encode(out.file, a, &q, path, err);
        if (failed) tarn_atomic_abandon(&out);
        else failed = tarn_atomic_commit(&out, err);
    }
    free(q.indices);
    return failed ? -1 : 0;
}
