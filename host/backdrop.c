/* backdrop.c: see backdrop.h. */
#include "backdrop.h"
#include "water.h"

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

/* A copy of a scene's objects whose water objects draw with materials of their
 * own, which an edit changes. */
typedef struct {
    tarn_scene scene;
    tarn_object *objects;
    tarn_material *materials; /* per object; a water object's only */
    tarn_water *waters;
} water_edit;

typedef void (*water_change)(tarn_water *water, const void *arg);

static void water_edit_free(water_edit *e)
{
    free(e->objects);
    free(e->materials);
    free(e->waters);
    memset(e, 0, sizeof *e);
}

/* `scene` with each water object's material copied and its water changed. */
static int water_edit_make(const tarn_scene *scene, water_change change, const void *arg, water_edit *e,
                           tarn_error *err)
{
    const size_t count = scene->object_count > 0 ? scene->object_count : 1u;
    e->objects = malloc(count * sizeof *e->objects);
    e->materials = malloc(count * sizeof *e->materials);
    e->waters = malloc(count * sizeof *e->waters);
    if (e->objects == NULL || e->materials == NULL || e->waters == NULL) {
        water_edit_free(e);
        return tarn_fail(err, "backdrop: out of memory copying the water's materials");
    }
    e->scene = *scene;
    e->scene.objects = e->objects;
    for (uint32_t i = 0; i < scene->object_count; i++) {
        e->objects[i] = scene->objects[i];
        if (!is_water(&scene->objects[i])) continue;
        e->waters[i] = *scene->objects[i].material->water;
        change(&e->waters[i], arg);
        e->materials[i] = *scene->objects[i].material;
        e->materials[i].water = &e->waters[i];
        e->objects[i].material = &e->materials[i];
    }
    return 0;
}

/* Features cut to the uint32_t mask `arg`. */
static void keep_features(tarn_water *water, const void *arg)
{
    water->features &= *(const uint32_t *)arg;
}

/* The water object a still-water mark names: the mark-th of the scene's water
 * objects. */
static const tarn_object *water_object(const tarn_scene *scene, uint32_t mark)
{
    for (uint32_t k = 0; k < scene->object_count; k++)
        if (is_water(&scene->objects[k]) && --mark == 0u) return &scene->objects[k];
    return NULL;
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

/* The frame's distinct colours, sorted and padded with the last to a power of two
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
    for (size_t k = count; k < ((size_t)1 << bits); k++) b->palette[k] = b->palette[count - 1u];
    b->colours = (uint32_t)count;
    b->backdrop.index_bits = (uint8_t)bits;
    b->backdrop.palette = b->palette;
    b->backdrop.palette_count = 1u << bits;
    b->backdrop.colour = b->colour;
    return 0;
}

/* Whether pixel k's depth differs between two frames of one quality. */
static int depth_differs(const opaque_frame *a, const opaque_frame *b, size_t k)
{
    return memcmp(a->depth + k * a->depth_bytes, b->depth + k * b->depth_bytes, a->depth_bytes) != 0;
}

/* The frame's pixels where water draws: the depth the whole scene leaves there is
 * the water's, which a pixel takes only when it lies closer than the opaque one. */
static int find_water(const tarn_scene *scene, const tarn_frame_config *config, const opaque_frame *opaque,
                      uint8_t *water, tarn_error *err)
{
    opaque_frame whole = {NULL, NULL, 0, 0};
    const int failed = draw_frame(scene, config, &whole, "finding the water", err);
    for (size_t k = 0; !failed && k < (size_t)config->width * config->height; k++)
        water[k] = depth_differs(&whole, opaque, k);
    frame_free(&whole);
    return failed;
}

/* Each row's pixels the water reads (1 in `kept`): from the first water pixel within
 * `reach` rows to the last, `reach` pixels wider on each side. */
static void rows_around_water(const uint8_t *water, int32_t width, int32_t height, int32_t reach, uint8_t *kept)
{
    for (int32_t j = 0; j < height; j++) {
        int32_t x0 = width, x1 = 0;
        for (int32_t y = j - reach < 0 ? 0 : j - reach; y <= j + reach && y < height; y++)
            for (int32_t i = 0; i < width; i++) {
                if (!water[(size_t)y * (size_t)width + (size_t)i]) continue;
                if (i < x0) x0 = i;
                if (i + 1 > x1) x1 = i + 1;
            }
        x0 = x0 - reach < 0 ? 0 : x0 - reach;
        x1 = x1 + reach > width ? width : x1 + reach;
        for (int32_t i = 0; i < width; i++) kept[(size_t)j * (size_t)width + (size_t)i] = i >= x0 && i < x1;
    }
}

/* The pixels whose depth the backdrop keeps (`kept`), and where the frame's water
 * draws (`*water`, width * height flags, or NULL under the underwater view, which
 * keeps every pixel's depth). */
static int find_kept_depth(const tarn_scene *scene, const tarn_frame_config *config, const opaque_frame *opaque,
                           uint8_t *kept, uint8_t **water, tarn_error *err)
{
    const size_t pixels = (size_t)config->width * config->height;
    *water = NULL;
    if (scene->underwater != NULL) { /* the underwater view displaces every pixel */
        memset(kept, 1, pixels);
        return 0;
    }
    *water = malloc(pixels);
    if (*water == NULL) return tarn_fail(err, "out of memory finding the backdrop's water");
    if (find_water(scene, config, opaque, *water, err) != 0) return -1;
    rows_around_water(*water, config->width, config->height, tarn_frame_apron_pixels(scene, config), kept);
    return 0;
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
    const opaque_frame *f;
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
static int keep_depth(const opaque_frame *f, const uint8_t *kept, uint32_t height, tarn_backdrop_image *b,
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

static void image_free(tarn_backdrop_image *b)
{
    free(b->palette);
    free(b->colour);
    free(b->planes);
    free(b->row_spans);
    free(b->spans);
    free(b->depth);
    memset(b, 0, sizeof *b);
}

static void set_quality(tarn_backdrop *b, const tarn_quality *q, int still_water)
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

/* The backdrop of the opaque objects, and where the frame's water draws
 * (find_kept_depth). */
static int opaque_image_make(const tarn_scene *scene, const tarn_frame_config *config, tarn_backdrop_image *b,
                             uint8_t **water, tarn_error *err)
{
    set_quality(&b->backdrop, &config->quality, 0);
    opaque_frame f = {NULL, NULL, 0, 0};
    uint8_t *kept = malloc((size_t)config->width * config->height);
    const int failed = kept == NULL ? tarn_fail(err, "out of memory finding the backdrop's water")
                                    : draw_opaque_frame(scene, config, &f, err) ||
                                          index_colours(f.rgb, (size_t)config->width * config->height, b, err) ||
                                          find_kept_depth(scene, config, &f, kept, water, err) ||
                                          keep_depth(&f, kept, config->height, b, err);
    frame_free(&f);
    free(kept);
    return failed;
}

/* ---- still water ------------------------------------------------------------------ */

/* What keeps still water from applying, refused before anything is drawn; and
 * the water objects' planes. */
static int still_water_planes(const tarn_scene *scene, const tarn_frame_config *config, tarn_backdrop_image *b,
                              tarn_error *err)
{
    if (scene->underwater != NULL)
        return tarn_fail(err, "--backdrop still: the scene's underwater view moves every pixel with the clock; "
                              "use --backdrop on");
    const int32_t apron = tarn_frame_apron_pixels(scene, config);
    if (apron > 0)
        return tarn_fail(err, "--backdrop still: the water refracts up to %d pixels at this quality, and a "
                              "refracted sample moves with the clock; use --apron off (as --quality fast does) "
                              "or --backdrop on", (int)apron);
    uint32_t water_objects = 0;
    for (uint32_t i = 0; i < scene->object_count; i++) water_objects += (uint32_t)is_water(&scene->objects[i]);
    if (water_objects > TARN_BACKDROP_STILL_OBJECTS_MAX)
        return tarn_fail(err, "--backdrop still: the scene has %u water objects, at most %u can be told apart",
                         water_objects, TARN_BACKDROP_STILL_OBJECTS_MAX);
    b->planes = calloc(water_objects > 0 ? water_objects : 1u, sizeof *b->planes);
    if (b->planes == NULL) return tarn_fail(err, "backdrop: out of memory finding the water's planes");
    b->backdrop.planes = b->planes;
    return tarn_still_planes_make(scene, config, b->planes, err);
}

/* Marks each water pixel of `still` with its water object's number (1 + its index
 * among the water objects): the first whose frame over the opaque objects alone
 * leaves the still frame's depth there. */
static int mark_objects(const tarn_scene *scene, const tarn_frame_config *config, opaque_frame *still,
                        const uint8_t *water, tarn_error *err)
{
    const size_t pixels = (size_t)config->width * config->height;
    tarn_object *objects = malloc((scene->object_count > 0 ? scene->object_count : 1u) * sizeof *objects);
    uint8_t *marked = calloc(pixels, 1);
    int failed = objects == NULL || marked == NULL ? tarn_fail(err, "backdrop: out of memory marking the water") : 0;
    uint32_t number = 0;
    for (uint32_t i = 0; !failed && i < scene->object_count; i++) {
        if (!is_water(&scene->objects[i])) continue;
        number++;
        tarn_scene alone = scene_part(scene, 0, objects);
        objects[alone.object_count++] = scene->objects[i];
        opaque_frame f = {NULL, NULL, 0, 0};
        failed = draw_frame(&alone, config, &f, "marking the water", err);
        for (size_t k = 0; !failed && k < pixels; k++) {
            if (!water[k] || marked[k] || depth_differs(&f, still, k)) continue;
            marked[k] = 1;
            still->rgb[k] |= number << TARN_BACKDROP_STILL_SHIFT;
        }
        frame_free(&f);
    }
    free(objects);
    free(marked);
    return failed;
}

/* The water objects of `scene` alone, as drawn with exact (32-bit) depth. */
static int draw_water_alone(const tarn_scene *scene, const tarn_frame_config *config, opaque_frame *surface,
                            tarn_error *err)
{
    tarn_object *objects = malloc((scene->object_count > 0 ? scene->object_count : 1u) * sizeof *objects);
    if (objects == NULL) return tarn_fail(err, "backdrop: out of memory finding the foam band");
    tarn_scene water = scene_part(scene, 1, objects);
    water.underwater = NULL;
    water.static_view = NULL;
    tarn_frame_config exact = *config;
    exact.quality.depth_bits = 32;
    const int failed = draw_frame(&water, &exact, surface, "finding the foam band", err);
    free(objects);
    return failed;
}

/* near/d (Q1.30) at pixel k of a frame's depth. */
static uint32_t depth_q30(const opaque_frame *f, size_t k)
{
    if (f->depth_bytes == 2u) {
        uint16_t code;
        memcpy(&code, f->depth + 2u * k, sizeof code);
        return tarn_depth16_decode(code);
    }
    uint32_t q30;
    memcpy(&q30, f->depth + 4u * k, sizeof q30);
    return q30;
}

/* Each water pixel's place in its object's foam band (step 9's f, Q0.16) as the
 * scene drawn whole finds it with a pixel's own effects, by the core's own steps:
 * from the opaque depth beneath and the water's own near/d. Where it is in the band
 * (f < 1), `band` is 1 and the pixel's colour takes TARN_BACKDROP_STILL_FOAM. */
static int find_foam_places(const tarn_scene *scene, const tarn_frame_config *config, const opaque_frame *opaque,
                            opaque_frame *still, const uint8_t *water, uint16_t *places, uint8_t *band,
                            tarn_error *err)
{
    opaque_frame surface = {NULL, NULL, 0, 0};
    if (draw_water_alone(scene, config, &surface, err) != 0) return -1;
    tarn_view view;
    tarn_view_setup(scene, config, &view);
    tarn_water_context context;
    memset(&context, 0, sizeof context);
    for (size_t k = 0; k < (size_t)config->width * config->height; k++) {
        places[k] = 0xFFFFu;
        band[k] = 0;
        if (!water[k]) continue;
        const tarn_object *object = water_object(scene, (still->rgb[k] & TARN_BACKDROP_STILL_OBJECT) >> TARN_BACKDROP_STILL_SHIFT);
        if (context.object != object) tarn_water_context_setup(&context, &view, config, object);
        if (!tarn_water_uses(&context, TARN_WATER_FOAM)) continue;
        const uint32_t below = tarn_water_linear_depth(depth_q30(opaque, k), context.near, context.far, context.recip_steps);
        const uint32_t at = tarn_water_linear_depth(depth_q30(&surface, k), context.near, context.far, context.recip_steps);
        const uint32_t f = tarn_water_foam_band(&context, below > at ? below - at : 0u);
        if (f >= 65536u) continue;
        places[k] = (uint16_t)f;
        band[k] = 1;
        still->rgb[k] |= TARN_BACKDROP_STILL_FOAM;
    }
    frame_free(&surface);
    return 0;
}

/* The opaque frame, the still one with its water marked with its object, and
 * where the water draws (`water`). */
static int draw_still_frames(const tarn_scene *scene, const tarn_frame_config *config, opaque_frame *opaque,
                             opaque_frame *still, uint8_t *water, tarn_error *err)
{
    const uint32_t still_features = ~(uint32_t)(TARN_WATER_MOVING | TARN_WATER_REFRACTION);
    water_edit edit = {{0}, NULL, NULL, NULL};
    int failed = draw_opaque_frame(scene, config, opaque, err) ||
                 water_edit_make(scene, keep_features, &still_features, &edit, err) ||
                 draw_frame(&edit.scene, config, still, "drawing the still water", err);
    for (size_t k = 0; !failed && k < (size_t)config->width * config->height; k++)
        water[k] = depth_differs(still, opaque, k);
    failed = failed || mark_objects(&edit.scene, config, still, water, err);
    water_edit_free(&edit);
    return failed;
}

/* The still-water backdrop, and where the frame's water draws. */
static int still_image_make(const tarn_scene *scene, const tarn_frame_config *config, tarn_backdrop_image *b,
                            uint8_t **water, tarn_error *err)
{
    if (still_water_planes(scene, config, b, err) != 0) return -1;
    set_quality(&b->backdrop, &config->quality, 1);
    const size_t pixels = (size_t)config->width * config->height;
    *water = malloc(pixels);
    uint8_t *band = malloc(pixels);
    uint16_t *places = malloc(pixels * sizeof *places);
    opaque_frame opaque = {NULL, NULL, 0, 0}, still = {NULL, NULL, 0, 0};
    /* the places in the band are kept as a frame's depth is */
    const opaque_frame kept = {NULL, (uint8_t *)places, sizeof *places, config->width};
    const int failed = *water == NULL || band == NULL || places == NULL
        ? tarn_fail(err, "backdrop: out of memory drawing the still water")
        : draw_still_frames(scene, config, &opaque, &still, *water, err) ||
              find_foam_places(scene, config, &opaque, &still, *water, places, band, err) ||
              index_colours(still.rgb, pixels, b, err) || keep_depth(&kept, band, config->height, b, err);
    frame_free(&opaque);
    frame_free(&still);
    free(band);
    free(places);
    return failed;
}

/* The backdrop of `kind`, and where the frame's water draws (NULL under the
 * underwater view). */
static int image_make(const tarn_scene *scene, const tarn_frame_config *config, tarn_backdrop_kind kind,
                      tarn_backdrop_image *b, uint8_t **water, tarn_error *err)
{
    *water = NULL;
    const int failed = kind == TARN_BACKDROP_STILL ? still_image_make(scene, config, b, water, err)
                                                   : opaque_image_make(scene, config, b, water, err);
    if (failed) {
        image_free(b);
        free(*water);
        *water = NULL;
    }
    return failed ? -1 : 0;
}

int tarn_backdrop_scene_make(const tarn_scene *scene, const tarn_frame_config *config, tarn_backdrop_kind kind,
                             int keep_positions, tarn_backdrop_scene *out, tarn_error *err)
{
    memset(out, 0, sizeof *out);
    uint8_t *drawn = NULL;
    if (image_make(scene, config, kind, &out->image, &drawn, err) != 0) return -1;
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
