/* backdrop_read.c: a tile's opaque pass read from the scene's backdrop (tarn_scene.h)
 * instead of drawn: palette colours at every pixel, and depth where the backdrop
 * keeps it, which is wherever water draws or samples; and over still water, the
 * colour at any pixel, where a refracted sample lands, and the depth of water or
 * place in the foam band it keeps instead of depth. backdrop_check.c says which backdrop
 * applies and whether it is well formed. */
#include "tile/tile_internal.h"

#include <string.h>

/* A depth every water pixel lies behind: all ones, in either form. */
#define IN_FRONT_OF_ALL 0xFF

/* The depth of row j's pixels [x0, x1) into `to`: the kept ones copied, the rest in
 * front of all water, which drew nowhere there. */
static void fill_depth_row(const tarn_backdrop *b, int32_t j, int32_t x0, int32_t x1, uint8_t *to, size_t bytes)
{
    int32_t filled = x0; /* the pixels before it are */
    for (uint32_t k = b->row_spans[j]; k < b->row_spans[j + 1] && b->spans[k].x0 < x1; k++) {
        const tarn_backdrop_span *s = &b->spans[k];
        const int32_t kept0 = s->x0 > filled ? s->x0 : filled;
        const int32_t kept1 = s->x1 < x1 ? s->x1 : x1;
        if (kept0 >= kept1) continue;
        memset(to + (size_t)(filled - x0) * bytes, IN_FRONT_OF_ALL, (size_t)(kept0 - filled) * bytes);
        memcpy(to + (size_t)(kept0 - x0) * bytes, (const uint8_t *)b->depth + (s->first + (uint32_t)(kept0 - s->x0)) * bytes,
               (size_t)(kept1 - kept0) * bytes);
        filled = kept1;
    }
    memset(to + (size_t)(filled - x0) * bytes, IN_FRONT_OF_ALL, (size_t)(x1 - filled) * bytes);
}

/* An index the palette holds: one past its end reads its last colour. tarn bake
 * writes no such index, and a palette unpadded to 2^index_bits saves the flash of
 * the colours it does not use (a quarter of the pond's 8,192) for a compare a pixel;
 * the clamp keeps any other picture's reads inside the palette. */
static inline uint32_t palette_index(const tarn_backdrop *b, uint32_t index)
{
    return index < b->palette_count ? index : b->palette_count - 1u;
}

uint32_t tarn__backdrop_colour_at(const tarn_backdrop *b, uint16_t frame_width, int32_t i, int32_t j)
{
    const uint32_t first = ((uint32_t)j * frame_width + (uint32_t)i) * b->index_bits;
    const uint16_t *word = b->colour + (first >> 4);
    /* an index of at most 16 bits spans two words at most; the second is read only
     * when it does, so no read passes the picture's last word */
    uint32_t bits = (uint32_t)word[0] >> (first & 15u);
    if ((first & 15u) + b->index_bits > 16u) bits |= (uint32_t)word[1] << (16u - (first & 15u));
    return b->palette[palette_index(b, bits & ((1u << b->index_bits) - 1u))];
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
        *to++ = b->palette[palette_index(b, window & mask)];
        window >>= bits;
        held -= bits;
    }
}

void tarn__backdrop_fill(const tarn_backdrop *b, uint16_t frame_width, tarn_tile_target *t, size_t depth_bytes)
{
    for (int32_t j = t->rect.y0; j < t->rect.y1; j++) {
        const int32_t first = (j - t->origin_y) * t->stride - t->origin_x + t->rect.x0;
        fill_colour_row(b, frame_width, j, t->rect.x0, t->rect.x1, t->colour + first);
        if (depth_bytes != 0u)
            fill_depth_row(b, j, t->rect.x0, t->rect.x1, (uint8_t *)t->depth + (size_t)first * depth_bytes, depth_bytes);
    }
}

/* Where pixel (i, j)'s kept depth lies in the backdrop's depth array; 0 when it
 * keeps none there. */
static int kept_at(const tarn_backdrop *b, int32_t i, int32_t j, uint32_t *index)
{
    for (uint32_t k = b->row_spans[j]; k < b->row_spans[j + 1] && i >= b->spans[k].x0; k++)
        if (i < b->spans[k].x1) {
            *index = b->spans[k].first + (uint32_t)(i - b->spans[k].x0);
            return 1;
        }
    return 0;
}

uint32_t tarn__backdrop_kept(const tarn_backdrop *b, int32_t i, int32_t j)
{
    uint32_t index;
    return kept_at(b, i, j, &index) ? ((const uint16_t *)b->depth)[index] : 65536u;
}

uint32_t tarn__backdrop_depth_q30(const tarn_backdrop *b, int32_t i, int32_t j)
{
    uint32_t index;
    const int kept = kept_at(b, i, j, &index);
    if (tarn__depth_is_16_bits(b->depth_bits))
        return tarn_depth16_decode(kept ? ((const uint16_t *)b->depth)[index] : 0xFFFFu);
    return kept ? ((const uint32_t *)b->depth)[index] : 0xFFFFFFFFu;
}
