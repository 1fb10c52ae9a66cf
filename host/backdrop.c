/* backdrop.c: see backdrop.h. */
#include "backdrop.h"

#include <stdlib.h>
#include <string.h>

/* The whole frame of the scene's opaque objects, as the core draws it. */
typedef struct {
    uint32_t *rgb;
    uint8_t *depth; /* depth_bits / 8 bytes a pixel */
    size_t depth_bytes;
    int width;
} opaque_frame;

static int keep_tile(void *user, const tarn_tile *tile)
{
    opaque_frame *f = user;
    for (int y = 0; y < tile->height; y++) {
        const size_t from = (size_t)y * tile->stride;
        const size_t to = (size_t)(tile->y + y) * (size_t)f->width + tile->x;
        memcpy(f->rgb + to, tile->rgb + from, tile->width * sizeof *f->rgb);
        memcpy(f->depth + to * f->depth_bytes, (const uint8_t *)tile->depth + from * f->depth_bytes,
               tile->width * f->depth_bytes);
    }
    return 0;
}

static int is_water(const tarn_object *o)
{
    return o->material != NULL && o->material->water != NULL;
}

/* The scene with only the objects whose water-ness is `water`, into `objects`. */
static tarn_scene scene_part(const tarn_scene *scene, int water, tarn_object *objects)
{
    tarn_scene part = *scene;
    part.objects = objects;
    part.object_count = 0;
    for (uint32_t i = 0; i < scene->object_count; i++)
        if (is_water(&scene->objects[i]) == water) objects[part.object_count++] = scene->objects[i];
    return part;
}

static void frame_free(opaque_frame *f)
{
    free(f->rgb);
    free(f->depth);
    memset(f, 0, sizeof *f);
}

/* `scene`'s frame into `f`, whose buffers it allocates (frame_free releases them,
 * whatever the outcome): 0, or -1 with `err` naming `what` it was for. */
static int draw_frame(const tarn_scene *scene, const tarn_frame_config *config, opaque_frame *f, const char *what,
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

/* The scene without its water and its underwater view, drawn. */
static int draw_opaque_frame(const tarn_scene *scene, const tarn_frame_config *config, opaque_frame *f,
                             tarn_error *err)
{
    tarn_object *objects = malloc((scene->object_count > 0 ? scene->object_count : 1u) * sizeof *objects);
    if (objects == NULL) return tarn_fail(err, "backdrop: out of memory drawing the opaque objects");
    tarn_scene opaque = scene_part(scene, 0, objects);
    opaque.underwater = NULL;
    opaque.static_view = NULL;
    const int failed = draw_frame(&opaque, config, f, "drawing the opaque objects", err);
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

/* The frame's distinct colours, sorted and padded with black to a power of two
 * (every index the bits can spell names one), and each pixel's index among them,
 * packed (tarn_backdrop.colour). */
static int index_colours(const uint32_t *rgb, size_t pixels, tarn_backdrop_image *b, tarn_error *err)
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
        return tarn_fail(err, "backdrop: the opaque objects draw %zu colours, at most %u fit its 16-bit indices",
                         count, TARN_BACKDROP_COLOURS_MAX);
    const unsigned bits = index_bits_for(count);
    b->colour_words = (pixels * bits + 15u) / 16u;
    b->colour = calloc(b->colour_words, sizeof *b->colour);
    if (b->colour == NULL) return tarn_fail(err, "out of memory indexing the backdrop");
    for (size_t k = 0; k < pixels; k++) {
        const uint32_t *found = bsearch(&rgb[k], b->palette, count, sizeof *b->palette, compare_u32);
        pack_index(b->colour, k, bits, (uint32_t)(found - b->palette));
    }
    for (size_t k = count; k < ((size_t)1 << bits); k++) b->palette[k] = 0u;
    b->colours = (uint32_t)count;
    b->backdrop.index_bits = (uint8_t)bits;
    b->backdrop.palette = b->palette;
    b->backdrop.palette_count = 1u << bits;
    b->backdrop.colour = b->colour;
    return 0;
}

/* The frame's pixels where water draws: the depth the whole scene leaves there is
 * the water's, which a pixel takes only when it lies closer than the opaque one. */
static int find_water(const tarn_scene *scene, const tarn_frame_config *config, const opaque_frame *opaque,
                      uint8_t *water, tarn_error *err)
{
    opaque_frame whole = {NULL, NULL, 0, 0};
    const int failed = draw_frame(scene, config, &whole, "finding the water", err);
    for (size_t k = 0; !failed && k < (size_t)config->width * config->height; k++)
        water[k] = memcmp(whole.depth + k * whole.depth_bytes, opaque->depth + k * opaque->depth_bytes,
                          whole.depth_bytes) != 0;
    frame_free(&whole);
    return failed;
}

/* Each row's pixels the water reads: from the first water pixel within `reach`
 * rows to the last, `reach` pixels wider on each side. */
static void rows_around_water(const uint8_t *water, int32_t width, int32_t height, int32_t reach,
                              tarn_backdrop_row *rows)
{
    for (int32_t j = 0; j < height; j++) {
        int32_t x0 = width, x1 = 0;
        for (int32_t y = j - reach < 0 ? 0 : j - reach; y <= j + reach && y < height; y++)
            for (int32_t i = 0; i < width; i++) {
                if (!water[(size_t)y * (size_t)width + (size_t)i]) continue;
                if (i < x0) x0 = i;
                if (i + 1 > x1) x1 = i + 1;
            }
        rows[j].x0 = (uint16_t)(x0 < x1 ? (x0 - reach < 0 ? 0 : x0 - reach) : 0);
        rows[j].x1 = (uint16_t)(x0 < x1 ? (x1 + reach > width ? width : x1 + reach) : 0);
    }
}

/* Each row's span of kept depth, and where the frame's water draws (`*water`,
 * width * height flags, or NULL under the underwater view, which keeps every
 * pixel's depth). */
static int find_depth_rows(const tarn_scene *scene, const tarn_frame_config *config, const opaque_frame *opaque,
                           tarn_backdrop_image *b, uint8_t **water, tarn_error *err)
{
    *water = NULL;
    b->rows = calloc(config->height, sizeof *b->rows);
    if (b->rows == NULL) return tarn_fail(err, "out of memory finding the backdrop's water");
    if (scene->underwater != NULL) { /* the underwater view displaces every pixel */
        for (uint32_t j = 0; j < config->height; j++) b->rows[j].x1 = config->width;
        return 0;
    }
    *water = malloc((size_t)config->width * config->height);
    if (*water == NULL) return tarn_fail(err, "out of memory finding the backdrop's water");
    if (find_water(scene, config, opaque, *water, err) != 0) return -1;
    rows_around_water(*water, config->width, config->height, tarn_frame_apron_pixels(scene, config), b->rows);
    return 0;
}

/* The kept pixels' depth, each row's after the last. */
static int keep_depth(const opaque_frame *f, tarn_backdrop_image *b, uint32_t height, tarn_error *err)
{
    uint32_t kept = 0;
    for (uint32_t j = 0; j < height; j++) {
        b->rows[j].first = kept;
        kept += (uint32_t)(b->rows[j].x1 - b->rows[j].x0);
    }
    b->depth = malloc((kept > 0 ? kept : 1u) * f->depth_bytes);
    if (b->depth == NULL) return tarn_fail(err, "out of memory keeping the backdrop's depth");
    for (uint32_t j = 0; j < height; j++) {
        const tarn_backdrop_row *r = &b->rows[j];
        memcpy((uint8_t *)b->depth + (size_t)r->first * f->depth_bytes,
               f->depth + ((size_t)j * (size_t)f->width + r->x0) * f->depth_bytes,
               (size_t)(r->x1 - r->x0) * f->depth_bytes);
    }
    b->backdrop.rows = b->rows;
    b->backdrop.depth = b->depth;
    b->backdrop.depth_count = kept;
    return 0;
}

static void image_free(tarn_backdrop_image *b)
{
    free(b->palette);
    free(b->colour);
    free(b->rows);
    free(b->depth);
    memset(b, 0, sizeof *b);
}

/* The backdrop, and where the frame's water draws (find_depth_rows). */
static int image_make(const tarn_scene *scene, const tarn_frame_config *config, tarn_backdrop_image *b,
                      uint8_t **water, tarn_error *err)
{
    const tarn_quality *q = &config->quality;
    b->backdrop.recip_newton_steps = q->recip_newton_steps;
    b->backdrop.perspective = q->perspective;
    b->backdrop.perspective_span = q->perspective_span;
    b->backdrop.depth_bits = q->depth_bits;
    b->backdrop.depth_interpolation = q->depth_interpolation;
    *water = NULL;
    opaque_frame f = {NULL, NULL, 0, 0};
    const int failed = draw_opaque_frame(scene, config, &f, err) ||
                       index_colours(f.rgb, (size_t)config->width * config->height, b, err) ||
                       find_depth_rows(scene, config, &f, b, water, err) || keep_depth(&f, b, config->height, err);
    frame_free(&f);
    if (failed) {
        image_free(b);
        free(*water);
        *water = NULL;
    }
    return failed ? -1 : 0;
}

int tarn_backdrop_scene_make(const tarn_scene *scene, const tarn_frame_config *config, int keep_positions,
                             tarn_backdrop_scene *out, tarn_error *err)
{
    memset(out, 0, sizeof *out);
    uint8_t *drawn = NULL;
    if (image_make(scene, config, &out->image, &drawn, err) != 0) return -1;
    out->water_objects = malloc((scene->object_count > 0 ? scene->object_count : 1u) * sizeof *out->water_objects);
    int failed = out->water_objects == NULL ? tarn_fail(err, "out of memory making the backdrop's scene") : 0;
    tarn_scene water;
    if (!failed) water = scene_part(scene, 1, out->water_objects);
    if (!failed && drawn != NULL)
        failed = tarn_water_cull_make(&water, out->water_objects, config, drawn, &out->cull, err);
    free(drawn);
    failed = failed || tarn_static_scene_make(&water, config, keep_positions, &out->water, err);
    if (failed) {
        tarn_backdrop_scene_free(out);
        return -1;
    }
    out->water.vertices.view.backdrop = &out->image.backdrop;
    return 0;
}

void tarn_backdrop_scene_free(tarn_backdrop_scene *s)
{
    image_free(&s->image);
    tarn_water_cull_free(&s->cull);
    free(s->water_objects);
    tarn_static_scene_free(&s->water);
    memset(s, 0, sizeof *s);
}
