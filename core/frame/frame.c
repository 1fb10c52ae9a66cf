/* frame.c: tarn_render_frame, the tile or strip loop that runs every other stage,
 * a strip pipeline's two workers (tarn_strip_pipeline_begin), and
 * tarn_visit_screen_triangles. */
#include "frame/frame_internal.h"

#include <string.h>

/* Whether water triangles can be drawn at all: over a still-water backdrop they
 * are not, and a build that links only that leaves the water pixel out. */
#define WATER_TRIANGLES (TARN_LINK_WATER && TARN_LINK_WATER_SHADING)

/* The target's pixels in its rect to the background colour and "no triangle". */
static void clear_rect(tarn_tile_target *t, uint32_t background, size_t depth_bytes)
{
    const size_t count = (size_t)(t->rect.x1 - t->rect.x0);
    for (int32_t j = t->rect.y0; j < t->rect.y1; j++) {
        const int32_t first = (j - t->origin_y) * t->stride + (t->rect.x0 - t->origin_x);
        for (size_t i = 0; i < count; i++) t->colour[(size_t)first + i] = background;
        memset((uint8_t *)t->depth + (size_t)first * depth_bytes, 0, count * depth_bytes);
    }
}

/* Copies the pixels of `to`'s rect between two targets' buffers: out of the opaque
 * buffers the water pass starts from and depth-tests against, and back. */
static void copy_pixels(const tarn_tile_target *from, const tarn_tile_target *to, size_t depth_bytes)
{
    for (int32_t j = to->rect.y0; j < to->rect.y1; j++) {
        const int32_t source = (j - from->origin_y) * from->stride + (to->rect.x0 - from->origin_x);
        const int32_t dest = (j - to->origin_y) * to->stride + (to->rect.x0 - to->origin_x);
        const size_t count = (size_t)(to->rect.x1 - to->rect.x0);
        memcpy(to->colour + dest, from->colour + source, count * 4u);
        memcpy((uint8_t *)to->depth + (size_t)dest * depth_bytes,
               (const uint8_t *)from->depth + (size_t)source * depth_bytes, count * depth_bytes);
    }
}

/* A frame being drawn: what every pass reads, and the targets they draw into. */
typedef struct {
    const tarn_scene *scene;
    const tarn_frame_config *config;
    const tarn_view *view;
    tarn_frame_layout layout;
    tarn_tile_target opaque;      /* the opaque pass's target: the tile or strip drawn */
    const tarn_tile_target *ring; /* with strips, the ring of their opaque passes the
                                     water pass reads; NULL: it reads `opaque` */
    tarn_water_pass water;
    uint32_t *water_colour;       /* the water pass's own buffers */
    void *water_depth;
    uint32_t *final;              /* the underwater pass's tile */
    tarn_cluster_bin *found_bins; /* bins this frame finds, or NULL */
    const tarn_cluster_bin *bins; /* those, or the static view's, or NULL */
    tarn_water_context water_context;
    tarn_underwater_context underwater;
} frame_state;

/* f set for a frame of `scene` (posed, as the frame draws it) seen through `view`:
 * its layout, a pipeline's ring a strip deeper (shared_ring), and its passes over
 * the buffers carved from `memory`, past the scene; nothing in them depends on the
 * tile yet. Inline: one copy in an image that draws frames one way only. */
static TARN_ALWAYS_INLINE void frame_begin(frame_state *f, const tarn_view *view, const tarn_scene *scene,
                                           const tarn_frame_config *config, void *memory, int shared_ring)
{
    f->scene = scene;
    f->config = config;
    f->view = view;
    f->layout = tarn__frame_layout_of(config, scene);
    /* the strip an opaque pass is drawn into while the water reads the others */
    if (shared_ring && f->layout.ring_strips != 0) f->layout.ring_strips++;
    const tarn_frame_buffers b = tarn__frame_carve(&f->layout, memory);
    f->water_colour = b.water_colour;
    f->water_depth = b.water_depth;
    f->final = b.final;
    f->found_bins = b.found_bins;
    f->bins = b.found_bins != NULL ? b.found_bins : f->layout.static_bins;
    f->opaque.colour = b.opaque_colour;
    f->opaque.depth = b.opaque_depth;
    f->opaque.stride = f->layout.region_width;
    f->opaque.quality = &f->config->quality;
    f->opaque.log2_span = (uint8_t)(31u - tarn_clz32(f->config->quality.perspective_span));
    f->ring = NULL; /* draw_strips points it at the ring */
    f->water.target = f->opaque;
    f->water.water = &f->water_context;
    f->water.view = f->view;
    f->water.config = f->config;
    f->water_context.blocks = b.blocks;
    f->water_context.still_blocks = b.still_blocks;
    f->water_context.object = NULL; /* set up for the frame's first water object, kept across tiles */
    f->water_context.still_walks = 0u;
    f->water_context.triangle_serial = 0u;
}

static tarn_pixel_rect intersect(tarn_pixel_rect a, tarn_pixel_rect b)
{
    tarn_pixel_rect r = {a.x0 > b.x0 ? a.x0 : b.x0, a.y0 > b.y0 ? a.y0 : b.y0,
                         a.x1 < b.x1 ? a.x1 : b.x1, a.y1 < b.y1 ? a.y1 : b.y1};
    return r;
}

static tarn_pixel_rect around(int32_t x, int32_t y, int32_t size, int32_t apron, const tarn_pixel_rect *frame)
{
    tarn_pixel_rect r = {x - apron, y - apron, x + size + apron, y + size + apron};
    return intersect(r, *frame);
}

/* The water context reads the opaque pass's buffers as the background. */
static void begin_water(frame_state *f)
{
    tarn_water_context *c = &f->water_context;
    const tarn_tile_target *b = TARN_LINK_STRIPS && f->ring != NULL ? f->ring : &f->opaque;
    c->background = b->colour;
    c->background_depth = b->depth;
    c->depth_bits = f->config->quality.depth_bits;
    c->background_rect.x0 = b->origin_x;
    c->background_rect.y0 = b->origin_y;
    c->background_stride = b->stride;
    c->background_rows =
        TARN_LINK_STRIPS && f->layout.ring_strips != 0 ? f->layout.ring_strips * f->layout.tile : INT32_MAX;
    c->offset_limit = f->layout.refraction_apron;
    c->sample_rect = b->rect; /* binds at the frame's edges only (opaque_rect, the ring) */
    /* over an opaque backdrop (tarn__frame_layout_of draws no apron then), moved
     * samples read its picture, anywhere in the frame */
    c->flash = TARN_LINK_BACKDROP && f->layout.backdrop != NULL && !f->layout.still && f->layout.apron == 0
                   ? f->layout.backdrop
                   : NULL;
    if (c->flash != NULL) {
        c->sample_rect.x0 = 0;
        c->sample_rect.y0 = 0;
        c->sample_rect.x1 = f->config->width;
        c->sample_rect.y1 = f->config->height;
    }
}

/* The water triangles of `rect` into the water pass's target. */
static void draw_water_triangles(frame_state *f, const tarn_pixel_rect *rect)
{
    if (WATER_TRIANGLES)
        tarn__walk_triangles(f->scene, f->view, TARN_WALK_WATER, f->bins, rect, tarn__water_draw_triangle, &f->water);
}

/* The water pass over `rect` into its own buffers, whose index 0 is frame pixel
 * (origin_x, origin_y), `stride` wide: it starts from a copy of the opaque pixels. */
static void draw_water_copy(frame_state *f, const tarn_pixel_rect *rect, int32_t origin_x, int32_t origin_y,
                            int32_t stride)
{
    tarn_tile_target *w = &f->water.target;
    w->rect = *rect;
    w->origin_x = origin_x;
    w->origin_y = origin_y;
    w->stride = stride;
    w->colour = f->water_colour;
    w->depth = f->water_depth;
    f->water.mark = 0u;
    copy_pixels(&f->opaque, w, f->layout.depth_bytes);
    draw_water_triangles(f, rect);
}

/* The water pass over the tile and the underwater apron, from a copy. */
static void draw_water(frame_state *f, int32_t x, int32_t y, const tarn_pixel_rect *frame)
{
    const int32_t apron = f->layout.under_apron;
    const tarn_pixel_rect rect = around(x, y, f->layout.tile, apron, frame);
    begin_water(f);
    draw_water_copy(f, &rect, x - apron, y - apron, f->layout.water_region);
}

/* The water pass straight over the opaque buffers, as the copy would draw it as long
 * as no water pixel lands on another: each then reads the opaque pixel beneath it,
 * not yet written. Returns 0, with the tile's opaque pixels spoilt, when one did. */
static int draw_water_in_place(frame_state *f, const tarn_pixel_rect *tile_rect)
{
    tarn_water_pass *w = &f->water;
    w->target = f->opaque;
    w->target.rect = *tile_rect;
    w->mark = TARN_WATER_MARK;
    w->overlap = 0u;
    begin_water(f);
    draw_water_triangles(f, tile_rect);
    tarn__water_clear_marks(&w->target);
    return w->overlap == 0u;
}

/* The water pass a strip of rows at a time, each from a copy of the opaque pixels
 * in the strip's buffers and back: the tile's image as the copy draws it, in the
 * memory of the in-place layout. */
static void draw_water_in_strips(frame_state *f, const tarn_pixel_rect *tile_rect)
{
    begin_water(f);
    for (int32_t y = tile_rect->y0; y < tile_rect->y1; y += TARN_WATER_STRIP_ROWS) {
        const tarn_pixel_rect strip = {tile_rect->x0, y, tile_rect->x1,
                                       y + TARN_WATER_STRIP_ROWS < tile_rect->y1 ? y + TARN_WATER_STRIP_ROWS : tile_rect->y1};
        draw_water_copy(f, &strip, tile_rect->x0, y, f->layout.piece_width);
        tarn_tile_target back = f->opaque;
        back.rect = strip;
        copy_pixels(&f->water.target, &back, f->layout.depth_bytes);
    }
}

static void draw_underwater(frame_state *f, const tarn_pixel_rect *tile_rect)
{
    tarn_underwater_context *u = &f->underwater;
    const tarn_tile_target *w = &f->water.target;
    u->colour = w->colour;
    u->depth = w->depth;
    u->depth_bits = f->config->quality.depth_bits;
    u->origin_x = w->origin_x;
    u->origin_y = w->origin_y;
    u->stride = w->stride;
    u->offset_limit = f->layout.under_apron;
    u->sample_rect = w->rect;
    tarn__underwater_tile(u, tile_rect, f->final, f->layout.tile);
}

static int rect_empty(const tarn_pixel_rect *r)
{
    return r->x0 >= r->x1 || r->y0 >= r->y1;
}

static tarn_pixel_rect rect_union(tarn_pixel_rect a, tarn_pixel_rect b)
{
    if (rect_empty(&a)) return b;
    if (rect_empty(&b)) return a;
    tarn_pixel_rect r = {a.x0 < b.x0 ? a.x0 : b.x0, a.y0 < b.y0 ? a.y0 : b.y0,
                         a.x1 > b.x1 ? a.x1 : b.x1, a.y1 > b.y1 ? a.y1 : b.y1};
    return r;
}

typedef struct {
    tarn_pixel_rect within; /* the tile */
    tarn_pixel_rect extent; /* pixels of it water triangles may cover; empty at first */
    unsigned subpixel_bits;
} water_extent;

static void add_water_extent(void *ctx, const tarn_screen_vertex vertex[3], const tarn_object *object)
{
    water_extent *e = ctx;
    tarn_triangle_setup t;
    if (!tarn__orient_triangle(vertex, object->material->cull, e->subpixel_bits, &t)) return;
    const tarn_pixel_box box = tarn__triangle_pixels(&t);
    const tarn_pixel_rect r = {box.x0, box.y0, box.x1 + 1, box.y1 + 1};
    e->extent = rect_union(e->extent, intersect(r, e->within));
}

/* The pixels the opaque pass must draw for a tile: the tile, and the apron only as
 * far as the tile's water can sample it. Refracted samples move at most the
 * refraction apron from their water pixel, so beyond that from every water pixel
 * nothing is read; a tile without water needs no apron at all. The image is the
 * same as with the whole apron drawn; only the cost differs. The underwater view
 * displaces every pixel, so it keeps the whole apron. */
static tarn_pixel_rect opaque_rect(const frame_state *f, const tarn_pixel_rect *tile_rect,
                                   const tarn_pixel_rect *frame, int *has_water)
{
    const tarn_pixel_rect whole = around(tile_rect->x0, tile_rect->y0, f->layout.tile, f->layout.apron, frame);
    *has_water = f->layout.water;
    if (!f->layout.water || f->layout.underwater) return whole;
    water_extent e = {*tile_rect, {0, 0, 0, 0}, f->config->quality.subpixel_bits};
    tarn__walk_triangles(f->scene, f->view, TARN_WALK_WATER, f->bins, tile_rect, add_water_extent, &e);
    *has_water = !rect_empty(&e.extent);
    if (!*has_water) return *tile_rect;
    const int32_t a = f->layout.refraction_apron;
    const tarn_pixel_rect reach = {e.extent.x0 - a, e.extent.y0 - a, e.extent.x1 + a, e.extent.y1 + a};
    return rect_union(*tile_rect, intersect(reach, whole));
}

/* The opaque pass over the target's rect, drawn or read from the backdrop. */
static void draw_opaque(frame_state *f)
{
    tarn_tile_target *o = &f->opaque;
    if (TARN_LINK_BACKDROP && f->layout.backdrop != NULL) {
        tarn__backdrop_fill(f->layout.backdrop, f->config->width, o, f->layout.depth_bytes);
        return;
    }
    clear_rect(o, f->scene->background_rgb & 0xFFFFFFu, f->layout.depth_bytes);
    if (TARN_LINK_OPAQUE_OBJECTS)
        tarn__walk_triangles(f->scene, f->view, TARN_WALK_OPAQUE, f->bins, &o->rect, tarn__raster_triangle, o);
}

/* The water pass in place over the tile, or, where a water pixel landed on another,
 * the tile drawn again with the water in strips. */
static void draw_water_over_opaque(frame_state *f, const tarn_pixel_rect *tile_rect)
{
    if (draw_water_in_place(f, tile_rect)) return;
    draw_opaque(f);
    draw_water_in_strips(f, tile_rect);
}

/* The still water's moving terms over the tile's pixels, each water object's in
 * turn: no triangle is drawn, and every mark the backdrop set is consumed, since
 * the scene check lets object marks name water objects only. */
static void draw_still_water(frame_state *f)
{
    const tarn_backdrop *b = f->layout.backdrop;
    tarn_water_context *c = &f->water_context;
    begin_water(f);
    /* refracted samples read the backdrop's picture, anywhere in the frame */
    const tarn_pixel_rect frame = {0, 0, f->config->width, f->config->height};
    c->sample_rect = frame;
    for (uint32_t k = 0; k < f->scene->object_count && k < TARN_BACKDROP_STILL_OBJECTS_MAX; k++) {
        const tarn_object *object = &f->scene->objects[k];
        if (object->material->water == NULL) continue;
        if (c->object != object) tarn__water_context_setup(c, f->view, f->config, object);
        tarn__water_still_tile(c, b, k, &f->opaque);
    }
}

/* The pixels of the tile at (x, y) into the opaque target's buffers, or, with
 * water drawn from a copy, the water target's: the target the sink reads. */
static const tarn_tile_target *draw_tile_pixels(frame_state *f, int32_t x, int32_t y, const tarn_pixel_rect *tile_rect)
{
    const tarn_pixel_rect frame = {0, 0, f->config->width, f->config->height};
    tarn_tile_target *o = &f->opaque;
    o->origin_x = x - f->layout.apron;
    o->origin_y = y - f->layout.apron;
    if (TARN_LINK_STILL_WATER && f->layout.still) {
        o->rect = *tile_rect;
        draw_opaque(f);
        draw_still_water(f);
        return o;
    }
    int has_water;
    o->rect = opaque_rect(f, tile_rect, &frame, &has_water);
    draw_opaque(f);
    if (!(TARN_LINK_WATER || TARN_LINK_UNDERWATER) || !has_water) return o;
    if (f->layout.in_place) {
        draw_water_over_opaque(f, tile_rect);
        return o;
    }
    draw_water(f, x, y, &frame);
    return &f->water.target;
}

static tarn_tile tile_of(const frame_state *f, const tarn_tile_target *out, const tarn_pixel_rect *rect)
{
    const int32_t first = (rect->y0 - out->origin_y) * out->stride + (rect->x0 - out->origin_x);
    tarn_tile tile = {(uint16_t)rect->x0, (uint16_t)rect->y0, (uint16_t)(rect->x1 - rect->x0),
                      (uint16_t)(rect->y1 - rect->y0), out->colour + first,
                      (const uint8_t *)out->depth + (size_t)first * f->layout.depth_bytes, (uint16_t)out->stride,
                      f->config->quality.depth_bits};
    if (TARN_LINK_BACKDROP && f->layout.backdrop != NULL) tile.depth = NULL; /* kept under water only */
    return tile;
}

static int draw_tile(frame_state *f, int32_t x, int32_t y, tarn_tile_sink sink, void *user)
{
    const int32_t size = f->layout.tile;
    const tarn_pixel_rect frame = {0, 0, f->config->width, f->config->height};
    const tarn_pixel_rect tile_rect = around(x, y, size, 0, &frame);
    const tarn_tile_target *out = draw_tile_pixels(f, x, y, &tile_rect);
    tarn_tile tile = tile_of(f, out, &tile_rect);
    if (TARN_LINK_UNDERWATER && f->layout.underwater) {
        draw_underwater(f, &tile_rect);
        tile.rgb = f->final;
        tile.stride = (uint16_t)size;
        tile.depth = NULL; /* the displaced image has no single depth per pixel */
    }
    return sink != NULL ? sink(user, &tile) : 0;
}

/* ---- strips ---------------------------------------------------------------------
 * A frame drawn in strips (TARN_FRAME_STRIPS), tile_size rows of the
 * whole width, top to bottom.
 *
 * A tile draws the opaque scene around itself as far as its water's refracted
 * samples reach, and its neighbours draw the same pixels again: at the exact
 * preset that is about four times the frame's opaque pixels. Here each strip's
 * opaque pass is drawn once, into a ring of layout.ring_strips strips, and the
 * opaque pass runs as many strips ahead of the water pass as the apron reaches:
 * when strip k's water is drawn, the strips from k - a to k + a are in the ring,
 * every pixel a refracted sample of strip k can land on. The water pass draws into
 * its own strip buffer from a copy (the ring keeps the opaque pixels the next
 * strips' water reads), or in place when no sample moves. Each pixel is found as
 * a tile finds it, so the image is the same byte for byte. */

/* Strip s's slot in the ring, as a target over the strip's rows; `slot` is
 * s modulo the ring's strips. */
static tarn_tile_target ring_slot(const frame_state *f, const tarn_tile_target *ring, int32_t s, int32_t slot)
{
    const tarn_frame_layout *l = &f->layout;
    tarn_tile_target t = *ring;
    const size_t first = (size_t)slot * (size_t)l->tile * (size_t)l->piece_width;
    t.colour += first;
    t.depth = (uint8_t *)t.depth + first * l->depth_bytes;
    t.origin_x = 0;
    t.origin_y = s * l->tile;
    t.rect.x0 = 0;
    t.rect.y0 = t.origin_y;
    t.rect.x1 = f->config->width;
    t.rect.y1 = t.origin_y + l->tile < f->config->height ? t.origin_y + l->tile : f->config->height;
    return t;
}

/* The ring as the water pass of strip k reads it: frame row y at ring row
 * (y - origin_y), less the ring's rows past its end, over the strips held. */
static void hold_ring_for(const frame_state *f, tarn_tile_target *ring, int32_t k, int32_t strips)
{
    const tarn_frame_layout *l = &f->layout;
    const int32_t reach = (l->ring_strips - 1) / 2;
    const int32_t first = k - reach > 0 ? k - reach : 0;
    const int32_t last = k + reach < strips - 1 ? k + reach : strips - 1;
    ring->origin_x = 0;
    ring->origin_y = (first - first % l->ring_strips) * l->tile; /* the ring's row 0 */
    ring->rect.x0 = 0;
    ring->rect.y0 = first * l->tile;
    ring->rect.x1 = f->config->width;
    ring->rect.y1 = (last + 1) * l->tile < f->config->height ? (last + 1) * l->tile : f->config->height;
}

/* Strip k's water over its opaque pass in the ring; the target the sink reads. */
static const tarn_tile_target *draw_strip_water(frame_state *f, tarn_tile_target *ring, int32_t k,
                                                int32_t strips, const tarn_tile_target *slot)
{
    hold_ring_for(f, ring, k, strips);
    f->opaque = *slot;
    if (f->layout.in_place) {
        draw_water_over_opaque(f, &slot->rect);
        return &f->opaque;
    }
    begin_water(f);
    draw_water_copy(f, &slot->rect, 0, slot->origin_y, f->layout.piece_width);
    return &f->water.target;
}

/* The first of `count` things that part `part` of `parts` takes when they are shared
 * out in order, as evenly as they go: ceil(count * part / parts), found without a
 * division (count is a frame's strips, at most a few hundred). */
static int32_t share_start(int32_t count, uint32_t part, uint32_t parts)
{
    int32_t k = 0;
    while ((uint32_t)k * parts < (uint32_t)count * part) k++;
    return k;
}

/* Strip d's opaque pass into its slot of the ring. */
static void draw_strip_opaque(frame_state *f, const tarn_tile_target *ring, int32_t d)
{
    f->opaque = ring_slot(f, ring, d, d % f->layout.ring_strips);
    draw_opaque(f);
}

/* Strip k's water over the ring, and the strip to the sink; non-zero when the sink
 * stopped. */
static int send_strip(frame_state *f, tarn_tile_target *ring, int32_t k, int32_t strips, tarn_tile_sink sink,
                      void *user)
{
    const tarn_tile_target slot = ring_slot(f, ring, k, k % f->layout.ring_strips);
    const tarn_tile_target *out = &slot;
    if (f->layout.water) out = draw_strip_water(f, ring, k, strips, &slot);
    const tarn_tile tile = tile_of(f, out, &slot.rect);
    return sink != NULL && sink(user, &tile) != 0;
}

/* The frame's strips, top to bottom. */
static int32_t strip_count(const frame_state *f)
{
    return (f->config->height + f->layout.tile - 1) / f->layout.tile;
}

/* Strips below its own that a strip's water reads: the opaque pass runs that far ahead. */
static int32_t strips_ahead(const tarn_frame_layout *l)
{
    return (l->ring_strips - 1) / 2; /* a pipeline's spare strip rounds away */
}

/* The part's run of strips, shared out in order as evenly as they go. Its ring
 * starts with the opaque passes of the strips above its first one that the first
 * one's refracted samples reach, as a whole frame's ring holds them then. */
static tarn_status draw_strips(frame_state *f, tarn_frame_part part, tarn_tile_sink sink, void *user)
{
    tarn_tile_target ring = f->opaque; /* the frame's opaque buffers: the ring */
    f->ring = &ring;
    const int32_t strips = strip_count(f);
    const int32_t first = share_start(strips, part.index, part.count);
    const int32_t end = share_start(strips, part.index + 1u, part.count);
    const int32_t ahead = strips_ahead(&f->layout);
    int32_t drawn = first > ahead ? first - ahead : 0; /* the next strip whose opaque pass the ring takes */
    for (int32_t k = first; k < end; k++) {
        for (; drawn < strips && drawn <= k + ahead; drawn++) draw_strip_opaque(f, &ring, drawn);
        if (send_strip(f, &ring, k, strips, sink, user)) return TARN_ERR_SINK;
    }
    return TARN_OK;
}

/* The part's tiles: every count-th, from its own index on (counted round, not
 * divided: the Cortex-M0 has no divider). */
static tarn_status draw_tiles(frame_state *f, tarn_frame_part part, tarn_tile_sink sink, void *user)
{
    uint16_t turn = 0; /* the tile's number modulo the count; 0 without TARN_LINK_PARTS */
    for (int32_t y = 0; y < f->config->height; y += f->layout.tile)
        for (int32_t x = 0; x < f->config->width; x += f->layout.tile) {
            if ((!TARN_LINK_PARTS || turn == part.index) && draw_tile(f, x, y, sink, user) != 0) return TARN_ERR_SINK;
            if (TARN_LINK_PARTS) turn = turn + 1u == part.count ? 0u : (uint16_t)(turn + 1u);
        }
    return TARN_OK;
}

/* The checks, then the frame's own work in `memory`: the scene it draws (posed, its
 * vertices found), the view, f over the buffers past the scene, the cluster bins,
 * the underwater view's constants. A pipeline checks its deeper ring's bytes before. */
static TARN_ALWAYS_INLINE tarn_status frame_prepare(frame_state *f, tarn_view *view, const tarn_scene *scene,
                                                    const tarn_frame_config *config, void *memory,
                                                    size_t memory_bytes, int shared_ring)
{
    if (tarn__config_check(config) != TARN_OK) return TARN_ERR_CONFIG;
    tarn_status status = tarn__scene_check(scene);
    if (status != TARN_OK) return status;
    if (memory == NULL || memory_bytes < tarn_frame_memory_bytes(config, scene)) return TARN_ERR_MEMORY;
    scene = tarn__frame_scene(scene, config, &memory);
    status = tarn__scene_check_reach(scene, config);
    if (status != TARN_OK) return status;
    tarn__view_setup(scene, config, view);
    frame_begin(f, view, scene, config, memory, shared_ring);
    if (TARN_LINK_FOUND_BINS && f->found_bins != NULL) tarn__bin_clusters(scene, view, f->found_bins);
    if (TARN_LINK_UNDERWATER && f->layout.underwater) tarn__underwater_setup(&f->underwater, view, config, scene->underwater);
    return TARN_OK;
}

/* Out of line: tarn_render_frame calls it too, and an image that links both should
 * hold the frame once (on the Cortex-M0 it is about 1.2 KB of code). */
TARN_NOINLINE tarn_status tarn_render_frame_part(const tarn_scene *scene, const tarn_frame_config *config,
                                                 void *memory, size_t memory_bytes, tarn_frame_part part,
                                                 tarn_tile_sink sink, void *user)
{
    if (TARN_LINK_PARTS ? part.count == 0u || part.index >= part.count : part.count != 1u || part.index != 0u)
        return TARN_ERR_CONFIG;
    tarn_view view;
    frame_state f;
    const tarn_status status = frame_prepare(&f, &view, scene, config, memory, memory_bytes, 0);
    if (status != TARN_OK) return status;
    return TARN_LINK_STRIPS && f.layout.ring_strips != 0 ? draw_strips(&f, part, sink, user)
                                                        : draw_tiles(&f, part, sink, user);
}

tarn_status tarn_render_frame(const tarn_scene *scene, const tarn_frame_config *config,
                              void *memory, size_t memory_bytes, tarn_tile_sink sink, void *user)
{
    const tarn_frame_part whole = {0u, 1u};
    return tarn_render_frame_part(scene, config, memory, memory_bytes, whole, sink, user);
}

/* ---- a strip pipeline ------------------------------------------------------------
 * Two workers over one ring (tarn_strip_pipeline_begin): each has a frame_state of
 * its own, over the same ring, and a ring target of its own, which its water moves
 * down the frame; worker 1's water buffers and blocks' slots (as large as the frame
 * in strips has them) lie between the state and the frame's memory. */
typedef struct {
    tarn_view view;
    frame_state worker[TARN_STRIP_PIPELINE_WORKERS];
    tarn_tile_target ring[TARN_STRIP_PIPELINE_WORKERS];
    int32_t strips; /* 0: the frame is not drawn in strips */
} strip_pipeline_state;

/* The state's bytes, with room to align it for its pointers (the memory is only
 * 4-byte aligned). */
#define PIPELINE_STATE_BYTES ((sizeof(strip_pipeline_state) + sizeof(void *) + 3u) & ~(size_t)3u)

static strip_pipeline_state *pipeline_state(void *memory)
{
    uint8_t *start = memory;
    return (strip_pipeline_state *)(void *)(start + ((0u - (uintptr_t)start) & (sizeof(void *) - 1u)));
}

/* A water pass's own buffers and blocks' slots in a layout: their bytes. */
static size_t water_buffer_bytes(const tarn_frame_layout *l)
{
    return tarn__frame_water_pixels(l) * (4u + l->depth_bytes) + (size_t)l->blocks * l->block_bytes;
}

/* Worker 1's water buffers and blocks' slots, at `memory`, the slots cleared. */
static void carve_second_water(frame_state *f, uint8_t *memory)
{
    const size_t pixels = tarn__frame_water_pixels(&f->layout);
    f->water_colour = (uint32_t *)(void *)memory;
    f->water_depth = memory + pixels * 4u;
    uint8_t *blocks = memory + pixels * (4u + f->layout.depth_bytes);
    f->water_context.blocks = f->layout.blocks != 0u ? (tarn_water_block *)(void *)blocks : NULL;
    memset(blocks, 0, (size_t)f->layout.blocks * f->layout.block_bytes);
}

size_t tarn_strip_pipeline_memory_bytes(const tarn_frame_config *config, const tarn_scene *scene)
{
    const size_t frame = tarn_frame_memory_bytes(config, scene);
    if (frame == 0u) return 0u;
    /* beyond the frame's: the ring's spare strip and worker 1's water buffers */
    const tarn_frame_layout l = tarn__frame_strips_layout(config, scene);
    const size_t spare = l.ring_strips != 0 ? (size_t)l.region_width * (size_t)l.tile * (4u + l.depth_bytes) : 0u;
    return PIPELINE_STATE_BYTES + water_buffer_bytes(&l) + frame + spare;
}

tarn_status tarn_strip_pipeline_begin(const tarn_scene *scene, const tarn_frame_config *config, void *memory,
                                      size_t memory_bytes, tarn_strip_pipeline *pipeline)
{
    pipeline->strips = 0;
    pipeline->ahead = 0;
    if (config == NULL || config->quality.frame_shape != TARN_FRAME_STRIPS) return TARN_ERR_CONFIG;
    const size_t needed = tarn_strip_pipeline_memory_bytes(config, scene);
    if (needed == 0u) return TARN_ERR_CONFIG;
    if (memory == NULL || memory_bytes < needed) return TARN_ERR_MEMORY;
    strip_pipeline_state *s = pipeline_state(memory);
    uint8_t *second_water = (uint8_t *)memory + PIPELINE_STATE_BYTES;
    const tarn_frame_layout strips = tarn__frame_strips_layout(config, scene);
    const size_t before_frame = PIPELINE_STATE_BYTES + water_buffer_bytes(&strips);
    s->strips = 0;
    const tarn_status status = frame_prepare(&s->worker[0], &s->view, scene, config, (uint8_t *)memory + before_frame,
                                             memory_bytes - before_frame, 1);
    if (status != TARN_OK || !TARN_LINK_STRIPS || s->worker[0].layout.ring_strips == 0) return status;
    /* worker 1's state is worker 0's but for its water buffers and the one pointer
       into itself */
    s->worker[1] = s->worker[0];
    s->worker[1].water.water = &s->worker[1].water_context;
    carve_second_water(&s->worker[1], second_water);
    for (unsigned w = 0; w < TARN_STRIP_PIPELINE_WORKERS; w++) {
        s->ring[w] = s->worker[0].opaque; /* the frame's opaque buffers: the ring */
        s->worker[w].ring = &s->ring[w];
    }
    s->strips = strip_count(&s->worker[0]);
    pipeline->strips = s->strips;
    pipeline->ahead = strips_ahead(&s->worker[0].layout);
    return TARN_OK;
}

void tarn_strip_pipeline_opaque(void *memory, unsigned worker, int32_t strip)
{
    strip_pipeline_state *s = pipeline_state(memory);
    if (TARN_LINK_STRIPS && worker < TARN_STRIP_PIPELINE_WORKERS && strip >= 0 && strip < s->strips)
        draw_strip_opaque(&s->worker[worker], &s->ring[worker], strip);
}

tarn_status tarn_strip_pipeline_water(void *memory, unsigned worker, int32_t strip, tarn_tile_sink sink, void *user)
{
    strip_pipeline_state *s = pipeline_state(memory);
    if (!TARN_LINK_STRIPS || worker >= TARN_STRIP_PIPELINE_WORKERS || strip < 0 || strip >= s->strips)
        return TARN_ERR_CONFIG;
    return send_strip(&s->worker[worker], &s->ring[worker], strip, s->strips, sink, user) ? TARN_ERR_SINK : TARN_OK;
}

typedef struct {
    tarn_triangle_visitor visit;
    void *user;
} visit_context;

static void forward_to_visitor(void *ctx, const tarn_screen_vertex vertex[3], const tarn_object *object)
{
    const visit_context *v = ctx;
    v->visit(v->user, vertex, object);
}

tarn_status tarn_visit_screen_triangles(const tarn_scene *scene, const tarn_frame_config *config,
                                        tarn_triangle_visitor visit, void *user)
{
    if (tarn__config_check(config) != TARN_OK) return TARN_ERR_CONFIG;
    tarn_status status = tarn__scene_check(scene);
    if (status != TARN_OK) return status;
    if (tarn_scene_moves(scene)) return TARN_ERR_SCENE; /* tarn_scene_pose it first */
    tarn_view view;
    tarn__view_setup(scene, config, &view);
    visit_context ctx = {visit, user};
    tarn__walk_triangles(scene, &view, TARN_WALK_OPAQUE, NULL, NULL, forward_to_visitor, &ctx);
    tarn__walk_triangles(scene, &view, TARN_WALK_WATER, NULL, NULL, forward_to_visitor, &ctx);
    return TARN_OK;
}
