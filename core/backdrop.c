/* backdrop.c: a tile's opaque pass read from the scene's backdrop (tarn_scene.h)
 * instead of drawn: palette colours at every pixel, and depth where the backdrop
 * keeps it, which is wherever water draws or samples. */
#include "pipeline.h"

#include <string.h>

/* The quality settings that shape the opaque pass's pixels. The others (tile size,
 * apron, bins, the water's own) change only the water or the cost. */
static int same_opaque_quality(const tarn_backdrop *b, const tarn_quality *q)
{
    return b->recip_newton_steps == q->recip_newton_steps && b->perspective == q->perspective &&
           b->perspective_span == q->perspective_span && b->depth_bits == q->depth_bits &&
           b->depth_interpolation == q->depth_interpolation;
}

const tarn_backdrop *tarn_backdrop_for(const tarn_scene *scene, const tarn_frame_config *config)
{
    if (!TARN_LINK_BACKDROP || !TARN_LINK_STATIC_VERTICES || scene == NULL || scene->static_view == NULL)
        return NULL;
    const tarn_backdrop *b = scene->static_view->backdrop;
    return b != NULL && tarn_static_screen_applies(scene, config) && same_opaque_quality(b, &config->quality)
        ? b
        : NULL;
}

static int rows_valid(const tarn_backdrop *b, uint16_t width, uint16_t height)
{
    for (uint32_t j = 0; j < height; j++) {
        const tarn_backdrop_row *r = &b->rows[j];
        if (r->x0 > r->x1 || r->x1 > width || r->first > b->depth_count ||
            (uint32_t)(r->x1 - r->x0) > b->depth_count - r->first)
            return 0;
    }
    return 1;
}

/* Colours with nothing above 0xRRGGBB: the water pass marks the pixels it writes
 * in the bits above. */
static int palette_valid(const tarn_backdrop *b)
{
    for (uint32_t k = 0; k < b->palette_count; k++)
        if (b->palette[k] > 0xFFFFFFu) return 0;
    return 1;
}

/* A palette of 2^index_bits colours holds every index the bits can spell, so no
 * pixel's index needs checking: checked, they would cost each frame as much again
 * as reading them. */
int tarn_backdrop_valid(const tarn_backdrop *b, const tarn_static_view *view)
{
    if (b->palette == NULL || b->colour == NULL || b->rows == NULL || b->index_bits < 1u ||
        b->index_bits > 16u || b->palette_count != (1u << b->index_bits) ||
        (b->depth_bits != 16 && b->depth_bits != 32) || (b->depth_count > 0u && b->depth == NULL))
        return 0;
    return palette_valid(b) && rows_valid(b, view->width, view->height);
}

/* A depth every water pixel lies behind: all ones, in either form. */
#define IN_FRONT_OF_ALL 0xFF

/* The depth of row j's pixels [x0, x1) into `to`: the kept ones copied, the rest in
 * front of all water, which drew nowhere there. */
static void fill_depth_row(const tarn_backdrop *b, int32_t j, int32_t x0, int32_t x1, uint8_t *to, size_t bytes)
{
    const tarn_backdrop_row *r = &b->rows[j];
    const int32_t kept0 = r->x0 > x0 ? r->x0 : x0;
    const int32_t kept1 = r->x1 < x1 ? r->x1 : x1;
    if (kept0 >= kept1) {
        memset(to, IN_FRONT_OF_ALL, (size_t)(x1 - x0) * bytes);
        return;
    }
    memset(to, IN_FRONT_OF_ALL, (size_t)(kept0 - x0) * bytes);
    const uint8_t *kept = (const uint8_t *)b->depth + (r->first + (uint32_t)(kept0 - r->x0)) * bytes;
    memcpy(to + (size_t)(kept0 - x0) * bytes, kept, (size_t)(kept1 - kept0) * bytes);
    memset(to + (size_t)(kept1 - x0) * bytes, IN_FRONT_OF_ALL, (size_t)(x1 - kept1) * bytes);
}

/* Row j's colours over [x0, x1) into `to`. */
static void fill_colour_row(const tarn_backdrop *b, uint16_t frame_width, int32_t j, int32_t x0, int32_t x1,
                            uint32_t *to)
{
    const unsigned bits = b->index_bits;
    const uint32_t mask = (1u << bits) - 1u;
    const uint32_t first = ((uint32_t)j * frame_width + (uint32_t)x0) * bits;
    const uint16_t *next = b->colour + (first >> 4);
    /* the row's bits, read a word at a time: `window` holds `held` of them, the
     * next index lowest (bits <= 16, so one word always tops it up) */
    uint32_t window = (uint32_t)*next++ >> (first & 15u);
    unsigned held = 16u - (first & 15u);
    for (int32_t i = x0; i < x1; i++) {
        if (held < bits) {
            window |= (uint32_t)*next++ << held;
            held += 16u;
        }
        *to++ = b->palette[window & mask];
        window >>= bits;
        held -= bits;
    }
}

void tarn_backdrop_fill(const tarn_backdrop *b, uint16_t frame_width, tarn_tile_target *t, size_t depth_bytes)
{
    for (int32_t j = t->rect.y0; j < t->rect.y1; j++) {
        const int32_t first = (j - t->origin_y) * t->stride - t->origin_x + t->rect.x0;
        fill_colour_row(b, frame_width, j, t->rect.x0, t->rect.x1, t->colour + first);
        fill_depth_row(b, j, t->rect.x0, t->rect.x1, (uint8_t *)t->depth + (size_t)first * depth_bytes, depth_bytes);
    }
}
