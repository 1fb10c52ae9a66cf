/* backdrop_frames.c: what both backdrops' makers share (backdrop_frames.h). */
#include "backdrop_frames.h"

#include <stdlib.h>
#include <string.h>

static int keep_tile(void *user, const tarn_tile *tile)
{
    tarn_drawn_frame *f = user;
    for (int y = 0; y < tile->height; y++) {
        const size_t from = (size_t)y * tile->stride;
        const size_t to = (size_t)(tile->y + y) * (size_t)f->width + tile->x;
        memcpy(f->rgb + to, tile->rgb + from, tile->width * sizeof *f->rgb);
        memcpy(f->depth + to * f->depth_bytes, (const uint8_t *)tile->depth + from * f->depth_bytes,
               tile->width * f->depth_bytes);
    }
    return 0;
}

int tarn_object_is_water(const tarn_object *o)
{
    return o->material != NULL && o->material->water != NULL;
}

tarn_scene tarn_scene_part(const tarn_scene *scene, int water, tarn_object *objects)
{
    tarn_scene part = *scene;
    part.objects = objects;
    part.object_count = 0;
    for (uint32_t i = 0; i < scene->object_count; i++)
        if (tarn_object_is_water(&scene->objects[i]) == water) objects[part.object_count++] = scene->objects[i];
    return part;
}

void tarn_drawn_free(tarn_drawn_frame *f)
{
    free(f->rgb);
    free(f->depth);
    memset(f, 0, sizeof *f);
}

int tarn_backdrop_draw(const tarn_scene *scene, const tarn_frame_config *config, tarn_drawn_frame *f, const char *what,
                      tarn_error *err)
{
    const size_t pixels = (size_t)config->width * config->height, bytes = tarn_frame_memory_bytes(config, scene);
    f->rgb = malloc(pixels * sizeof *f->rgb);
    f->depth = malloc(pixels * 4u);
    f->depth_bytes = config->quality.depth_bits / 8u;
    f->width = config->width;
    void *memory = malloc(bytes > 0 ? bytes : 1u);
    tarn_status status = f->rgb != NULL && f->depth != NULL && memory != NULL
        ? tarn_render_frame(scene, config, memory, bytes, keep_tile, f)
        : TARN_ERR_MEMORY;
    free(memory);
    if (status == TARN_ERR_MEMORY) return tarn_fail(err, "backdrop: out of memory %s", what);
    if (status != TARN_OK) return tarn_fail(err, "backdrop: %s failed: %s", what, tarn_status_text(status));
    return 0;
}

int tarn_backdrop_draw_part(const tarn_scene *scene, int water, const tarn_frame_config *config, tarn_drawn_frame *f,
                     const char *what, tarn_error *err)
{
    tarn_object *objects = malloc((scene->object_count > 0 ? scene->object_count : 1u) * sizeof *objects);
    if (objects == NULL) return tarn_fail(err, "backdrop: out of memory %s", what);
    tarn_scene part = tarn_scene_part(scene, water, objects);
    part.underwater = NULL;
    part.static_view = NULL;
    const int failed = tarn_backdrop_draw(&part, config, f, what, err);
    free(objects);
    return failed;
}

static int compare_u32(const void *a, const void *b)
{
    const uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* The fewest bits that number `count` colours: 1..16. */
static unsigned index_bits_for(size_t count)
{
    unsigned bits = 1;
    while (((size_t)1 << bits) < count) bits++;
    return bits;
}

/* Index k's `bits` bits at bit k * bits of the words, low bits first. */
static void pack_index(uint16_t *words, size_t k, unsigned bits, uint32_t index)
{
    for (unsigned b = 0; b < bits; b++) {
        const size_t bit = k * bits + b;
        if (index >> b & 1u) words[bit / 16] |= (uint16_t)(1u << (bit % 16));
    }
}

/* The frame's distinct colours, sorted, and each pixel's index among them, packed
 * (tarn_backdrop.colour). */
int tarn_backdrop_index_colours(const uint32_t *rgb, size_t pixels, tarn_backdrop_image *b, tarn_error *err)
{
    b->palette = calloc(pixels > TARN_BACKDROP_COLOURS_MAX ? pixels : TARN_BACKDROP_COLOURS_MAX,
                        sizeof *b->palette);
    if (b->palette == NULL) return tarn_fail(err, "out of memory indexing the backdrop");
    memcpy(b->palette, rgb, pixels * sizeof *rgb);
    qsort(b->palette, pixels, sizeof *b->palette, compare_u32);
    size_t count = 0;
    for (size_t k = 0; k < pixels; k++)
        if (count == 0 || b->palette[count - 1] != b->palette[k]) b->palette[count++] = b->palette[k];
    if (count > TARN_BACKDROP_COLOURS_MAX)
        return tarn_fail(err, "backdrop: its pixels take %zu colours, at most %u fit its 16-bit indices",
                         count, TARN_BACKDROP_COLOURS_MAX);
    const unsigned bits = index_bits_for(count);
    b->colour_words = (pixels * bits + 15u) / 16u;
    b->colour = calloc(b->colour_words, sizeof *b->colour);
    if (b->colour == NULL) return tarn_fail(err, "out of memory indexing the backdrop");
    for (size_t k = 0; k < pixels; k++) {
        const uint32_t *found = bsearch(&rgb[k], b->palette, count, sizeof *b->palette, compare_u32);
        pack_index(b->colour, k, bits, (uint32_t)(found - b->palette));
    }
    b->backdrop.index_bits = (uint8_t)bits;
    b->backdrop.palette = b->palette;
    b->backdrop.palette_count = (uint32_t)count;
    b->backdrop.colour = b->colour;
    return 0;
}

int tarn_drawn_depth_differs(const tarn_drawn_frame *a, const tarn_drawn_frame *b, size_t k)
{
    return memcmp(a->depth + k * a->depth_bytes, b->depth + k * b->depth_bytes, a->depth_bytes) != 0;
}

/* Kept pixels fewer than this apart in a row share a span, the depth between them
 * all ones: a span costs as much as four 16-bit depths. */
#define SPAN_GAP_MIN 4

/* Row j's spans over `kept` (pixels of the row), each passed to `add` with its
 * first pixel and its end; returns how many. */
static uint32_t row_spans(const uint8_t *kept, int32_t width, void (*add)(void *, int32_t, int32_t), void *user)
{
    uint32_t count = 0;
    for (int32_t i = 0; i < width;) {
        if (!kept[i]) {
            i++;
            continue;
        }
        int32_t end = i + 1, gap = 0;
        for (int32_t x = end; x < width && gap < SPAN_GAP_MIN; x++) {
            gap = kept[x] ? 0 : gap + 1;
            if (kept[x]) end = x + 1;
        }
        if (add != NULL) add(user, i, end);
        count++;
        i = end;
    }
    return count;
}

typedef struct {
    const tarn_drawn_frame *f;
    const uint8_t *kept; /* the row's */
    int32_t j;
    tarn_backdrop_image *b;
} span_writer;

/* A span and its depth, all ones at the pixels between kept ones. */
static void write_span(void *user, int32_t x0, int32_t x1)
{
    span_writer *w = user;
    tarn_backdrop *b = &w->b->backdrop;
    const size_t bytes = w->f->depth_bytes;
    tarn_backdrop_span *s = &w->b->spans[b->span_count++];
    s->x0 = (uint16_t)x0;
    s->x1 = (uint16_t)x1;
    s->first = b->depth_count;
    for (int32_t i = x0; i < x1; i++, b->depth_count++) {
        uint8_t *to = (uint8_t *)w->b->depth + (size_t)b->depth_count * bytes;
        if (w->kept[i]) memcpy(to, w->f->depth + ((size_t)w->j * (size_t)w->f->width + (size_t)i) * bytes, bytes);
        else memset(to, 0xFF, bytes);
    }
}

/* The kept pixels' depth in spans, row by row. */
int tarn_backdrop_keep_depth(const tarn_drawn_frame *f, const uint8_t *kept, uint32_t height, tarn_backdrop_image *b,
                      tarn_error *err)
{
    const int32_t width = f->width;
    size_t spans = 0, pixels = 0;
    for (uint32_t j = 0; j < height; j++) spans += row_spans(kept + (size_t)j * (size_t)width, width, NULL, NULL);
    if (spans > UINT16_MAX)
        return tarn_fail(err, "backdrop: its depth takes %zu spans, at most %u fit its 16-bit row index", spans,
                         (unsigned)UINT16_MAX);
    for (size_t k = 0; k < (size_t)width * height; k++) pixels += kept[k];
    b->row_spans = malloc((height + 1u) * sizeof *b->row_spans);
    b->spans = malloc((spans > 0 ? spans : 1u) * sizeof *b->spans);
    /* at most SPAN_GAP_MIN - 1 pixels between kept ones in a span */
    b->depth = malloc((pixels * SPAN_GAP_MIN + 1u) * f->depth_bytes);
    if (b->row_spans == NULL || b->spans == NULL || b->depth == NULL)
        return tarn_fail(err, "out of memory keeping the backdrop's depth");
    b->backdrop.span_count = 0;
    b->backdrop.depth_count = 0;
    for (uint32_t j = 0; j < height; j++) {
        span_writer w = {f, kept + (size_t)j * (size_t)width, (int32_t)j, b};
        b->row_spans[j] = (uint16_t)b->backdrop.span_count;
        row_spans(w.kept, width, write_span, &w);
    }
    b->row_spans[height] = (uint16_t)b->backdrop.span_count;
    b->backdrop.row_spans = b->row_spans;
    b->backdrop.spans = b->spans;
    b->backdrop.depth = b->depth;
    return 0;
}

void tarn_backdrop_set_quality(tarn_backdrop *b, const tarn_quality *q, int still_water)
{
    b->recip_newton_steps = q->recip_newton_steps;
    b->perspective = q->perspective;
    b->perspective_span = q->perspective_span;
    b->depth_bits = q->depth_bits;
    b->depth_interpolation = q->depth_interpolation;
    b->still_water = (uint8_t)still_water;
    b->water_block = still_water ? q->water_block : 0u;
    b->fog_argument_bits = still_water ? q->fog_argument_bits : 0u;
    b->exp2_entries = still_water ? q->exp2.entries : 0u;
    b->exp2_interpolate = still_water ? q->exp2.interpolate : 0u;
}
