/* raster.c: one screen triangle into one tile.
 *
 * Coverage: three edge functions in 32-bit integers, exact on the snapped grid,
 * with the top-left rule as a -1 bias on edges that are neither top nor left.
 * Attributes: planes value(i, j) = anchor + step_x*(i - ia) + step_y*(j - ja), all
 * modulo 2^32, anchored at the triangle's own first pixel. Because integer
 * addition is exact, a pixel gets the same value whichever tile it falls in, and
 * wrap-around between covered pixels cancels out at the covered ones.
 * Perspective: attributes are scaled to about 2^30 ("T"), premultiplied by the
 * normalised inverse depth q, and divided back per pixel (or per span) with the
 * table-and-Newton reciprocal, using 16x16-bit partial products only. */
#include "raster_setup.h"
#include "water.h"

/* T = premultiplied * 2^30 / q, given 1/q as a Q2.30 mantissa and q's leading zeros:
 * 1/q = recip * 2^(lz - 62), so T = mul_hi(p << 1, recip) << (lz - 1). Clamped to the
 * triangle's own range, which rounding can overshoot by a few units. */
static uint32_t divide_by_q(uint32_t premultiplied, uint32_t recip, unsigned lz,
                            uint32_t t_min, uint32_t t_max)
{
    if ((int32_t)premultiplied < 0) premultiplied = 0;
    if (premultiplied > T_ONE) premultiplied = T_ONE;
    uint32_t t = tarn_mul_hi_u32(premultiplied << 1, recip);
    if (t > (t_max >> (lz - 1u))) return t_max;
    t <<= lz - 1u;
    return t < t_min ? t_min : t;
}

/* 1/q as a Q2.30 mantissa, and the leading zeros of q (1..31) that scale it. */
static uint32_t reciprocal_of_q(uint32_t q, unsigned steps, unsigned *lz)
{
    if ((int32_t)q < 1) q = 1;
    if (q > T_ONE) q = T_ONE;
    *lz = tarn_clz32(q);
    return tarn_recip_q30(q << *lz, steps);
}

/* An affine triangle's attributes along row j: value(i) = origin[k] + step_x * i,
 * modulo 2^32 as plane_at, so each pixel takes one product instead of two. */
static void affine_row_origin(const attribute_set *set, const triangle_setup *t, int32_t j,
                              uint32_t origin[ATTRIBUTES_MAX])
{
    for (int k = set->first_varying; k < set->count; k++) {
        const plane *p = &set->premultiplied[k];
        origin[k] = p->anchor + p->step_y * (uint32_t)(j - t->box.y0) - p->step_x * (uint32_t)t->box.x0;
    }
}

static void affine_t(const attribute_set *set, const uint32_t origin[ATTRIBUTES_MAX], int32_t i,
                     uint32_t out[ATTRIBUTES_MAX])
{
    for (int k = set->first_varying; k < set->count; k++) {
        uint32_t v = origin[k] + set->premultiplied[k].step_x * (uint32_t)i;
        if ((int32_t)v < (int32_t)set->t_min[k]) v = set->t_min[k];
        out[k] = v > set->t_max[k] ? set->t_max[k] : v;
    }
}

/* Exact T values of every attribute at pixel (i, j), perspective-correct. */
static void exact_t(const attribute_set *set, const triangle_setup *t, int32_t i, int32_t j,
                    unsigned steps, uint32_t out[ATTRIBUTES_MAX])
{
    uint32_t q = plane_at(&set->q, t, i, j);
    if ((int32_t)q < (int32_t)set->q_min) q = set->q_min;
    if (q > set->q_max) q = set->q_max;
    unsigned lz;
    uint32_t recip = reciprocal_of_q(q, steps, &lz);
    for (int k = set->first_varying; k < set->count; k++)
        out[k] = divide_by_q(plane_at(&set->premultiplied[k], t, i, j), recip, lz,
                             set->t_min[k], set->t_max[k]);
}

/* Linear interpolation between exact values every `span` pixels. Spans sit on a
 * grid fixed to the frame, cut to the triangle's own pixel box, so neither depends
 * on the tile. A span's ends may lie outside the triangle: there the exact values
 * are extrapolated, signed and unclamped (clamping them would bend the slope
 * between the ends); only the interpolated pixels are clamped to the triangle. */
typedef struct {
    unsigned log2_span;
    int32_t limit;     /* the pixel after the cached span's grid cell; INT32_MIN before the first */
    int32_t start;     /* the cached span's first pixel */
    int32_t end;       /* and its far end, where the next span starts */
    int32_t t0[ATTRIBUTES_MAX], dt[ATTRIBUTES_MAX];
    int32_t t_end[ATTRIBUTES_MAX]; /* the exact values at `end` */
    int32_t length;                /* end - start of the last span filled, -1 before */
    uint32_t inverse_length;       /* 2^32 / length, tarn_recip_u32's */
} span_cache;

#define SPAN_END_MIN (-(1 << 28))
#define SPAN_END_MAX ((1 << 30) + (1 << 28)) /* ends this far apart still fit a step */

/* T = p * 2^30 / q for a signed, extrapolated p, saturated to the span end range. */
static int32_t span_end_t(int32_t premultiplied, uint32_t recip, unsigned lz)
{
    int32_t p = tarn_clamp_i32(premultiplied, -(1 << 30) + 1, (1 << 30) - 1);
    const int32_t t = tarn_mul_hi_s32_u32(p * 2, recip); /* |t| <= 2^30 */
    /* t * 2^(lz - 1), saturated: compared before the shift, so it stays in 32 bits */
    const unsigned up = lz - 1u; /* 0..30 */
    if (t >= 0) return (uint32_t)t > ((uint32_t)SPAN_END_MAX >> up) ? SPAN_END_MAX : t * (1 << up);
    return (uint32_t)-t > ((uint32_t)-SPAN_END_MIN >> up) ? SPAN_END_MIN : -(-t * (1 << up));
}

static void span_end(const attribute_set *set, const triangle_setup *t, int32_t i, int32_t j,
                     unsigned steps, int32_t out[ATTRIBUTES_MAX])
{
    int32_t q = (int32_t)plane_at(&set->q, t, i, j);
    int32_t q_floor = (int32_t)(set->q_min / 2u) > 1 ? (int32_t)(set->q_min / 2u) : 1;
    unsigned lz;
    uint32_t recip = reciprocal_of_q((uint32_t)tarn_clamp_i32(q, q_floor, (int32_t)T_ONE), steps, &lz);
    for (int k = set->first_varying; k < set->count; k++)
        out[k] = span_end_t((int32_t)plane_at(&set->premultiplied[k], t, i, j), recip, lz);
}

/* The span of pixel i: its exact ends, and the step between them. The far end of
 * one span is the near end of the next, so its values are kept, not taken again. */
static void span_fill(const attribute_set *set, const triangle_setup *t, unsigned steps, int32_t i,
                      int32_t j, span_cache *cache)
{
    const int32_t span = (int32_t)1 << cache->log2_span;
    const int32_t grid = (int32_t)((uint32_t)tarn_floor_shift(i, cache->log2_span) << cache->log2_span);
    const int32_t start = grid > t->box.x0 ? grid : t->box.x0;
    const int32_t end = grid + span < t->box.x1 ? grid + span : t->box.x1;
    if (cache->limit != INT32_MIN && start == cache->end) {
        for (int k = set->first_varying; k < set->count; k++) cache->t0[k] = cache->t_end[k];
    } else {
        span_end(set, t, start, j, steps, cache->t0);
    }
    span_end(set, t, end, j, steps, cache->t_end);
    /* per span, not per pixel: 1/length from the reciprocal, not a division, and
     * taken again only when the length changes (inside a row it rarely does) */
    if (end - start != cache->length) {
        cache->length = end - start;
        cache->inverse_length = cache->length > 0 ? tarn_recip_u32((uint32_t)cache->length, 2) : 0u;
    }
    for (int k = set->first_varying; k < set->count; k++)
        cache->dt[k] = tarn_mul_hi_s32_u32(cache->t_end[k] - cache->t0[k], cache->inverse_length);
    cache->start = start;
    cache->end = end;
    cache->limit = grid + span;
}

static void span_t(const attribute_set *set, const triangle_setup *t, unsigned steps, int32_t i, int32_t j,
                   span_cache *cache, uint32_t out[ATTRIBUTES_MAX])
{
    if (i >= cache->limit) span_fill(set, t, steps, i, j, cache);
    for (int k = set->first_varying; k < set->count; k++) {
        int32_t value = cache->t0[k] + cache->dt[k] * (i - cache->start);
        out[k] = (uint32_t)tarn_clamp_i32(value, (int32_t)set->t_min[k], (int32_t)set->t_max[k]);
    }
}

static uint32_t shade_pixel(const attribute_set *set, const tarn_texture *texture,
                            const uint32_t t[ATTRIBUTES_MAX])
{
    uint32_t rgb = 0;
    if (texture == NULL) {
        for (int c = 0; c < 3; c++) rgb = (rgb << 8) | (((t[c] >> set->t_shift[c]) + 128u) >> 8);
        return rgb;
    }
    const uint32_t tx = (t[ATTRIBUTE_U] >> set->texel_shift[0]) & set->texel_mask[0];
    const uint32_t ty = (t[ATTRIBUTE_V] >> set->texel_shift[1]) & set->texel_mask[1];
    const uint8_t *texel = &texture->rgb[3u * ((ty << set->log2_width) + tx)];
    if (set->lit_full) /* the product below is then the texel itself */
        return ((uint32_t)texel[0] << 16) | ((uint32_t)texel[1] << 8) | texel[2];
    for (int c = 0; c < 3; c++) {
        const uint32_t product = texel[c] * (t[c] >> set->t_shift[c]); /* lit Q8.8; / (255 * 256), to nearest */
        rgb = (rgb << 8) | ((product + (product >> 8) + 32768u) >> 16);
    }
    return rgb;
}

/* The pixel's depth as the buffer holds it (a tarn_depth16 code or Q1.30), or 0
 * when it is not closer than the stored one. Both forms are at least 1. */
static uint32_t closer_depth(const void *depth, int depth_bits, int32_t offset, uint32_t inv_depth)
{
    if ((int32_t)inv_depth < 1) inv_depth = 1;
    if (inv_depth > T_ONE) inv_depth = T_ONE;
    if (depth_bits == 16) {
        const uint16_t value = tarn_depth16_encode(inv_depth);
        return value > ((const uint16_t *)depth)[offset] ? value : 0u;
    }
    return inv_depth > ((const uint32_t *)depth)[offset] ? inv_depth : 0u;
}

/* Stored after the pixel is shaded: a water pass drawing in place reads the depth
 * beneath it first. */
static void store_depth(void *depth, int depth_bits, int32_t offset, uint32_t value)
{
    if (depth_bits == 16)
        ((uint16_t *)depth)[offset] = (uint16_t)value;
    else
        ((uint32_t *)depth)[offset] = value;
}

/* A water pass in place (water_mark set) marks each pixel it writes; writing a
 * marked one again means this pixel read the other water pixel as its background,
 * not the opaque pass's, and the frame draws the tile's water again from a copy. */
static void write_water_pixel(tarn_tile_target *tile, int32_t offset, uint32_t rgb)
{
    tile->water_overlap |= tile->colour[offset] & tile->water_mark;
    tile->colour[offset] = rgb | tile->water_mark;
}

/* T / 2^shift rounded to nearest: the water's panned maps multiply u and v by
 * their scale, which would multiply a truncation's bias too. */
static uint32_t rounded_shift(uint32_t t, unsigned shift)
{
    return shift == 0u ? t : (t + (1u << (shift - 1u))) >> shift;
}

/* The water pixel's inputs from the interpolated attributes. */
static tarn_water_input water_input(const attribute_set *set, const uint32_t values[ATTRIBUTES_MAX],
                                    uint32_t inv_depth)
{
    tarn_water_input in;
    in.inv_depth = inv_depth;
    for (int c = 0; c < 3; c++) in.lit[c] = values[c] >> set->t_shift[c];
    in.u = rounded_shift(values[ATTRIBUTE_U], set->t_shift[ATTRIBUTE_U]) + set->u_base;
    in.v = rounded_shift(values[ATTRIBUTE_V], set->t_shift[ATTRIBUTE_V]) + set->v_base;
    in.fresnel = set->count > ATTRIBUTE_FRESNEL ? values[ATTRIBUTE_FRESNEL] >> set->t_shift[ATTRIBUTE_FRESNEL] : 0u;
    return in;
}

/* Whether a pixel's background (near/d, Q1.30) lies as deep as its block's. */
static int as_deep_as(uint32_t depth_q30, const tarn_water_block *block)
{
    const uint32_t apart = depth_q30 > block->depth_q30 ? depth_q30 - block->depth_q30 : block->depth_q30 - depth_q30;
    return apart <= block->depth_q30 >> TARN_WATER_BLOCK_DEPTH_SHIFT;
}

/* The slot of the block of water pixel (i, j), in a frame with water blocks. */
static tarn_water_block *block_slot(const tarn_tile_target *tile, int32_t i)
{
    return &tile->water->blocks[(i - tile->rect.x0) >> tile->water->block_shift];
}

/* Whether pixel (i, j), its background at depth_q30, takes its block's effects:
 * this triangle found them at the block's top-left pixel over as deep a
 * background (tarn_water_block). Which pixels share depends on the triangles
 * alone: even tiles hold whole blocks. */
static int shares_block(const tarn_water_context *w, const tarn_water_block *block, int32_t j, uint32_t depth_q30)
{
    return block->serial == w->triangle_serial && block->row == (j >> w->block_shift << w->block_shift) &&
           as_deep_as(depth_q30, block);
}

/* The effects of a pixel that does not share its block's: its own, kept in the
 * block's slot when it is the block's top-left pixel, unless they refract: a
 * refracted sample moves with each pixel's own normal, and shared it would move
 * the block's other pixels by the top-left pixel's. */
static const tarn_water_effects *own_effects(const tarn_tile_target *tile, int32_t i, int32_t j,
                                             const tarn_water_input *in, uint32_t depth_q30,
                                             tarn_water_effects *own)
{
    tarn_water_context *w = tile->water;
    tarn_water_block *block = block_slot(tile, i);
    const int top_left = ((i | j) & ((1 << w->block_shift) - 1)) == 0;
    tarn_water_effects *e = top_left ? &block->effects : own;
    tarn_water_effects_at(w, i, j, in, e);
    if (top_left) {
        const int refracts = TARN_LINK_APRON && (e->offset[0] | e->offset[1]) != 0;
        block->serial = refracts ? 0u : w->triangle_serial;
        block->row = j;
        block->depth_q30 = depth_q30;
    }
    return e;
}

/* What one row keeps for its pixels' attributes, by the triangle's perspective
 * mode: the affine origin, or the span cache. */
typedef union {
    uint32_t affine_origin[ATTRIBUTES_MAX];
    span_cache span;
} row_attributes;

static void row_attributes_start(row_attributes *row, const tarn_tile_target *tile, const attribute_set *set,
                                 const triangle_setup *t, int32_t j)
{
    if (set->perspective == TARN_PERSPECTIVE_AFFINE) {
        affine_row_origin(set, t, j, row->affine_origin);
    } else if (TARN_LINK_PERSPECTIVE_SPAN && set->perspective == TARN_PERSPECTIVE_SPAN) {
        row->span.limit = INT32_MIN;
        row->span.length = -1;
        row->span.log2_span = tile->log2_span;
    }
}

/* The T values of every attribute at pixel (i, j) of the row. */
static void row_attributes_at(row_attributes *row, const tarn_quality *quality, const attribute_set *set,
                              const triangle_setup *t, int32_t i, int32_t j, uint32_t out[ATTRIBUTES_MAX])
{
    if (set->perspective == TARN_PERSPECTIVE_AFFINE)
        affine_t(set, row->affine_origin, i, out);
    else if (TARN_LINK_PERSPECTIVE_SPAN && set->perspective == TARN_PERSPECTIVE_SPAN)
        span_t(set, t, quality->recip_newton_steps, i, j, &row->span, out);
    else
        exact_t(set, t, i, j, quality->recip_newton_steps, out);
}

/* How a water pixel gets its effects: its block's, when it shares them, or its own. */
typedef struct {
    tarn_water_block *block; /* NULL without water blocks */
    uint32_t depth_q30;      /* the background's near/d, with blocks */
    int shares;
} water_choice;

static water_choice water_choice_at(const tarn_tile_target *tile, int32_t i, int32_t j)
{
    water_choice c = {NULL, 0u, 0};
    const tarn_water_context *w = tile->water;
    if (!TARN_LINK_WATER_BLOCKS || w->blocks == NULL) return c;
    c.block = block_slot(tile, i);
    c.depth_q30 = tarn_water_background_q30(w, i, j);
    c.shares = shares_block(w, c.block, j, c.depth_q30);
    return c;
}

/* Whether a water pixel needs inputs of its own: all but one that shares its
 * block's effects where no sharp feature can show, which needs no attributes. */
static int water_needs_inputs(const tarn_water_context *w, const water_choice *c)
{
    return !c->shares || tarn_water_sharp_possible(w, &c->block->effects);
}

/* The colour of water pixel (i, j) from its attributes `values` (found only where
 * water_needs_inputs). */
static uint32_t water_colour(const tarn_tile_target *tile, const water_choice *c, const attribute_set *set,
                             const uint32_t values[ATTRIBUTES_MAX], uint32_t inv_depth, int32_t i, int32_t j)
{
    tarn_water_context *w = tile->water;
    if (c->shares) {
        const tarn_water_effects *shared = &c->block->effects;
        if (!tarn_water_sharp_possible(w, shared)) return tarn_water_apply(w, shared, 0u, i, j);
        const tarn_water_input in = water_input(set, values, inv_depth);
        return tarn_water_apply(w, shared, tarn_water_sharp_features(w, &in, shared), i, j);
    }
    const tarn_water_input in = water_input(set, values, inv_depth);
    if (c->block == NULL) return tarn_water_shade(w, i, j, &in);
    tarn_water_effects own;
    const tarn_water_effects *e = own_effects(tile, i, j, &in, c->depth_q30, &own);
    return tarn_water_apply(w, e, e->sharp, i, j);
}

/* One covered pixel: its attributes, its colour (or water), its depth. `values`
 * holds the triangle's constant attributes already (tarn_setup_attributes). */
static void draw_pixel(tarn_tile_target *tile, const triangle_setup *t, const attribute_set *set,
                       const tarn_texture *texture, int32_t i, int32_t j, uint32_t inv_depth,
                       row_attributes *row, int32_t offset, uint32_t values[ATTRIBUTES_MAX])
{
    const tarn_quality *quality = tile->quality;
    const uint32_t closer = closer_depth(tile->depth, quality->depth_bits, offset, inv_depth);
    if (closer == 0u) return;
    /* a frame over still water draws no water triangle (water_still.c) */
    const int water = TARN_LINK_WATER && TARN_LINK_WATER_SHADING && tile->water != NULL;
    water_choice choice = {NULL, 0u, 0};
    if (water) choice = water_choice_at(tile, i, j);
    /* skipping a pixel's attributes is safe in every perspective mode: a span is
     * filled for whichever pixel first reaches it */
    if (!water || water_needs_inputs(tile->water, &choice)) row_attributes_at(row, quality, set, t, i, j, values);
    if (water)
        write_water_pixel(tile, offset, water_colour(tile, &choice, set, values, inv_depth, i, j));
    else
        tile->colour[offset] = shade_pixel(set, texture, values);
    store_depth(tile->depth, quality->depth_bits, offset, closer);
}

/* The three edge values at the first pixel of a row, with their steps along a row
 * and down to the next: a row starts from the row above's values by adds, not from
 * products. */
typedef struct {
    int32_t at[3];
    int32_t step_x[3], step_y[3];
} row_edges;

static row_edges row_edges_at(const triangle_setup *t, int32_t i, int32_t j)
{
    const unsigned s = t->subpixel_bits;
    row_edges r;
    for (int k = 0; k < 3; k++) {
        r.at[k] = edge_at(&t->edges[k], pixel_centre(i, s), pixel_centre(j, s));
        r.step_x[k] = (int32_t)((uint32_t)t->edges[k].a << s);
        r.step_y[k] = (int32_t)((uint32_t)t->edges[k].b << s);
    }
    return r;
}

/* The edges one row down, stepped modulo 2^32: after the last row they may leave
 * the range that rows inside the triangle's box keep to. */
static void row_edges_down(row_edges *r)
{
    for (int k = 0; k < 3; k++) r->at[k] = (int32_t)((uint32_t)r->at[k] + (uint32_t)r->step_y[k]);
}

static void raster_row(tarn_tile_target *tile, const triangle_setup *t, const attribute_set *set,
                       const tarn_texture *texture, int32_t j, int32_t i0, int32_t i1,
                       exact_value depth, const row_edges *edges, uint32_t values[ATTRIBUTES_MAX])
{
    int32_t e0 = edges->at[0], e1 = edges->at[1], e2 = edges->at[2];
    const int32_t step0 = edges->step_x[0], step1 = edges->step_x[1], step2 = edges->step_x[2];
    const int exact_depth = set->depth.exact;
    int32_t i = i0;
    /* up to the covered run: only the edges and the depth move */
    for (; i <= i1 && (e0 | e1 | e2) < 0; i++) {
        e0 += step0;
        e1 += step1;
        e2 += step2;
        step_depth(&depth, &set->depth.step_x, exact_depth);
    }
    if (i > i1) return;
    row_attributes row;
    row_attributes_start(&row, tile, set, t, j);
    const int32_t offset = (j - tile->origin_y) * tile->stride - tile->origin_x;
    /* each edge is linear along the row, so the covered pixels are one run: after
     * it, nothing more is covered */
    for (; i <= i1 && (e0 | e1 | e2) >= 0; i++) {
        draw_pixel(tile, t, set, texture, i, j, depth.quotient, &row, offset + i, values);
        e0 += step0;
        e1 += step1;
        e2 += step2;
        step_depth(&depth, &set->depth.step_x, exact_depth);
    }
}

/* Span mode interpolates between exact ends a span apart; on a triangle narrower
 * than a span those ends would be extrapolated outside it, and over so few pixels
 * affine interpolation is both cheaper and closer. The choice depends on the
 * triangle alone, so the image still does not depend on the tile size. */
static uint8_t perspective_mode(const tarn_quality *quality, const pixel_box *box)
{
    if (quality->perspective == TARN_PERSPECTIVE_SPAN && box->x1 - box->x0 < quality->perspective_span)
        return TARN_PERSPECTIVE_AFFINE;
    return quality->perspective;
}

/* What the triangle interpolates, and for water, the context for its object. */
static attribute_request request_for(tarn_tile_target *tile, const tarn_object *object)
{
    const tarn_material *material = object->material;
    attribute_request request = {NULL, 0, 0};
    if (TARN_LINK_WATER && material->water != NULL) {
        if (tile->water->object != object)
            tarn_water_context_setup(tile->water, tile->view, tile->config, object);
        request.uv = 1;
        request.fresnel = (material->water->features & TARN_WATER_FRESNEL) != 0;
    } else if (material->texture != NULL && object->mesh->uvs != NULL) {
        request.texture = material->texture;
        request.uv = 1;
    }
    return request;
}

/* 1 when some edge is negative at every pixel centre of the box, so no pixel of it
 * is covered: an edge is linear, so its largest value over the box is at the
 * corner its coefficients point to. Three edge values instead of the whole
 * attribute setup for the triangles whose bounds reach into a tile that their
 * area does not. */
static int box_outside_an_edge(const triangle_setup *t, const pixel_box *box)
{
    const unsigned s = t->subpixel_bits;
    for (int k = 0; k < 3; k++) {
        const edge *e = &t->edges[k];
        const int32_t px = pixel_centre(e->a > 0 ? box->x1 : box->x0, s);
        const int32_t py = pixel_centre(e->b > 0 ? box->y1 : box->y0, s);
        if (edge_at(e, px, py) < 0) return 1;
    }
    return 0;
}

void tarn_raster_triangle(tarn_tile_target *tile, const tarn_screen_vertex vertex[3],
                          const tarn_object *object)
{
    triangle_setup t;
    if (!tarn_orient_triangle(vertex, object->material->cull, tile->quality->subpixel_bits, &t)) return;
    t.box = tarn_triangle_pixels(&t);
    pixel_box draw = t.box;
    if (draw.x0 < tile->rect.x0) draw.x0 = tile->rect.x0;
    if (draw.y0 < tile->rect.y0) draw.y0 = tile->rect.y0;
    if (draw.x1 > tile->rect.x1 - 1) draw.x1 = tile->rect.x1 - 1;
    if (draw.y1 > tile->rect.y1 - 1) draw.y1 = tile->rect.y1 - 1;
    if (draw.x0 > draw.x1 || draw.y0 > draw.y1 || box_outside_an_edge(&t, &draw)) return;
    const attribute_request request = request_for(tile, object);
    if (TARN_LINK_WATER && tile->water != NULL) tile->water->triangle_serial++;
    attribute_set set;
    tarn_setup_attributes(&t, &request, perspective_mode(tile->quality, &t.box), tile->quality->depth_interpolation,
                          &set);
    uint32_t values[ATTRIBUTES_MAX];
    for (int k = 0; k < set.first_varying; k++) values[k] = set.t_min[k]; /* = t_max: constant */
    exact_value depth = tarn_depth_at(&t, &set.depth, draw.x0, draw.y0);
    row_edges edges = row_edges_at(&t, draw.x0, draw.y0);
    for (int32_t j = draw.y0; j <= draw.y1; j++) {
        raster_row(tile, &t, &set, request.texture, j, draw.x0, draw.x1, depth, &edges, values);
        step_depth(&depth, &set.depth.step_y, set.depth.exact);
        row_edges_down(&edges);
    }
}
