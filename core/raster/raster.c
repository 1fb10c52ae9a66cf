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
#include "raster/raster_internal.h"

/* The largest premultiplied value a pixel divides: p << 1 then stays within
 * tarn_mul_hi_u32_small's range. A covered pixel's p is a plane's value inside the
 * triangle through vertex values of at most 2^30, its rounding a few units over, so
 * it never reaches this; the cap keeps any other p's product exact on every core. */
#define PREMULTIPLIED_MAX ((1u << 30) + (1u << 15) - 1u)

/* T = premultiplied * 2^30 / q, given 1/q as a Q2.30 mantissa and q's leading zeros:
 * 1/q = recip * 2^(lz - 62), so T = mul_hi(p << 1, recip) << (lz - 1). Clamped to the
 * triangle's own range, which rounding can overshoot by a few units. A plane's
 * rounding can take p a few units below 0, where it would wrap, or above 2^30,
 * where the clamp to t_max catches the quotient. */
static TARN_ALWAYS_INLINE uint32_t divide_by_q(uint32_t premultiplied, uint32_t recip, unsigned lz,
                            uint32_t t_min, uint32_t t_max)
{
    if (premultiplied >> 30 != 0u) /* rarely: 2^30 and over, or below 0; one test where two would be */
        premultiplied = (int32_t)premultiplied < 0 ? 0u
                                                   : (premultiplied < PREMULTIPLIED_MAX ? premultiplied : PREMULTIPLIED_MAX);
    uint32_t t = tarn_mul_hi_u32_small(premultiplied << 1, recip); /* recip < 2^31: tarn_recip_q30 */
    if (t > (t_max >> (lz - 1u))) return t_max;
    t <<= lz - 1u;
    return t < t_min ? t_min : t;
}

/* 1/q as a Q2.30 mantissa, and the leading zeros of q (1..31) that scale it, for
 * q in [1, 2^30]: each caller has clamped q to a range within it (a triangle's
 * q_min and q_max are its vertices' near/d, normalised, each in that range). */
static TARN_ALWAYS_INLINE uint32_t reciprocal_of_q(uint32_t q, unsigned steps, unsigned *lz)
{
    *lz = tarn_clz32(q);
    return tarn_recip_q30(q << *lz, steps);
}

/* Row j's origins of the planes a pixel reads, each plane's value at pixel (0, j):
 * the attributes', and q's in pixel perspective; stepped down from the row above
 * where that row's are held, else found by products with the steps along the row. */
static void row_origins(const tarn_attribute_set *set, const tarn_triangle_setup *t, int32_t j,
                        tarn_row_origin *origin)
{
    const int pixel = set->perspective == TARN_PERSPECTIVE_PIXEL;
    if (origin->row == j - 1) {
        if (pixel) origin->q += origin->q_step_y;
        for (int k = set->first_varying; k < set->count; k++) origin->attributes[k] += origin->step_y[k];
    } else {
        if (pixel) {
            origin->q = tarn__plane_at(&set->q, t, 0, j);
            origin->q_step_y = set->q.step_y;
        }
        for (int k = set->first_varying; k < set->count; k++) {
            origin->attributes[k] = tarn__plane_at(&set->premultiplied[k], t, 0, j);
            origin->step_x[k] = set->premultiplied[k].step_x;
            origin->step_y[k] = set->premultiplied[k].step_y;
        }
    }
    origin->row = j;
}

static TARN_ALWAYS_INLINE uint32_t plane_along_row(uint32_t origin, uint32_t step_x, int32_t i)
{
    return origin + step_x * (uint32_t)i;
}

static TARN_ALWAYS_INLINE void affine_t(const tarn_attribute_set *set, const tarn_row_origin *origin, int32_t i,
                     uint32_t out[TARN_ATTRIBUTES_MAX])
{
    for (int k = set->first_varying; k < set->count; k++) {
        uint32_t v = plane_along_row(origin->attributes[k], origin->step_x[k], i);
        if ((int32_t)v < (int32_t)set->t_min[k]) v = set->t_min[k];
        out[k] = v > set->t_max[k] ? set->t_max[k] : v;
    }
}

/* Exact T values of every attribute at pixel i of the row, perspective-correct,
 * and the pixel's near/d by the reciprocal they divide by. */
static TARN_ALWAYS_INLINE void exact_t(const tarn_attribute_set *set, const tarn_row_origin *origin, int32_t i,
                    unsigned steps, uint32_t out[TARN_ATTRIBUTES_MAX], tarn_depth_reciprocal *depth)
{
    uint32_t q = plane_along_row(origin->q, set->q.step_x, i);
    if ((int32_t)q < (int32_t)set->q_min) q = set->q_min;
    if (q > set->q_max) q = set->q_max;
    unsigned lz;
    uint32_t recip = reciprocal_of_q(q, steps, &lz);
    depth->recip = recip; /* q = near/d * 2^q_shift */
    depth->lz = lz + set->q_shift;
    for (int k = set->first_varying; k < set->count; k++)
        out[k] = divide_by_q(plane_along_row(origin->attributes[k], origin->step_x[k], i), recip, lz,
                             set->t_min[k], set->t_max[k]);
}

/* Linear interpolation between exact values every `span` pixels. Spans sit on a
 * grid fixed to the frame, cut to the triangle's own pixel box, so neither depends
 * on the tile. A span's ends may lie outside the triangle: there the exact values
 * are extrapolated, signed and unclamped (clamping them would bend the slope
 * between the ends); only the interpolated pixels are clamped to the triangle. */

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

static void span_end(const tarn_attribute_set *set, const tarn_triangle_setup *t, int32_t i, int32_t j,
                     unsigned steps, int32_t out[TARN_ATTRIBUTES_MAX])
{
    int32_t q = (int32_t)tarn__plane_at(&set->q, t, i, j);
    int32_t q_floor = (int32_t)(set->q_min / 2u) > 1 ? (int32_t)(set->q_min / 2u) : 1;
    unsigned lz;
    uint32_t recip = reciprocal_of_q((uint32_t)tarn_clamp_i32(q, q_floor, (int32_t)TARN_T_ONE), steps, &lz);
    for (int k = set->first_varying; k < set->count; k++)
        out[k] = span_end_t((int32_t)tarn__plane_at(&set->premultiplied[k], t, i, j), recip, lz);
}

/* The span of pixel i: its exact ends, and the step between them. The far end of
 * one span is the near end of the next, so its values are kept, not taken again.
 * Once a span, so kept out of line: the loops that inline span_t stay small. */
static TARN_NOINLINE void span_fill(const tarn_attribute_set *set, const tarn_triangle_setup *t, unsigned steps, int32_t i,
                      int32_t j, tarn_span_cache *cache)
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

static TARN_ALWAYS_INLINE void span_t(const tarn_attribute_set *set, const tarn_triangle_setup *t, unsigned steps, int32_t i, int32_t j,
                   tarn_span_cache *cache, uint32_t out[TARN_ATTRIBUTES_MAX])
{
    if (i >= cache->limit) span_fill(set, t, steps, i, j, cache);
    for (int k = set->first_varying; k < set->count; k++) {
        int32_t value = cache->t0[k] + cache->dt[k] * (i - cache->start);
        out[k] = (uint32_t)tarn_clamp_i32(value, (int32_t)set->t_min[k], (int32_t)set->t_max[k]);
    }
}

/* The texel a textured pixel samples, from its u and v. */
static TARN_ALWAYS_INLINE const uint8_t *texel_at(const tarn_attribute_set *set, const tarn_texture *texture,
                                                  const uint32_t t[TARN_ATTRIBUTES_MAX])
{
    const uint32_t tx = (t[TARN_ATTRIBUTE_U] >> set->texel_shift[0]) & set->texel_mask[0];
    const uint32_t ty = (t[TARN_ATTRIBUTE_V] >> set->texel_shift[1]) & set->texel_mask[1];
    return &texture->rgb[3u * ((ty << set->log2_width) + tx)];
}

/* A lit channel (Q8.8) as a byte, to nearest. */
static TARN_ALWAYS_INLINE uint32_t lit_byte(uint32_t lit)
{
    return (lit + 128u) >> 8;
}

/* A texel's channel times a lit channel (Q8.8): / (255 * 256), to nearest. */
static TARN_ALWAYS_INLINE uint32_t lit_texel_byte(uint32_t texel, uint32_t lit)
{
    const uint32_t product = texel * lit;
    return (product + (product >> 8) + 32768u) >> 16;
}

static uint32_t shade_pixel(const tarn_attribute_set *set, const tarn_texture *texture,
                            const uint32_t t[TARN_ATTRIBUTES_MAX])
{
    uint32_t rgb = 0;
    if (texture == NULL) {
        for (int c = 0; c < 3; c++) rgb = (rgb << 8) | lit_byte(t[c] >> set->t_shift[c]);
        return rgb;
    }
    const uint8_t *texel = texel_at(set, texture, t);
    if (set->lit_full) /* the product below is then the texel itself */
        return ((uint32_t)texel[0] << 16) | ((uint32_t)texel[1] << 8) | texel[2];
    for (int c = 0; c < 3; c++) rgb = (rgb << 8) | lit_texel_byte(texel[c], t[c] >> set->t_shift[c]);
    return rgb;
}

/* shade_pixel for a lit colour on a line (first_varying 2): each channel found
 * from the key's value, attribute 2, times the texel's (`texture`, or white
 * without one). The key is clamped to its vertices' range, so `along` is
 * 0..65280, and the line keeps every channel within 0..255.0 over that range
 * (lit_line_key), so no channel is clamped. */
static TARN_ALWAYS_INLINE uint32_t shade_line_pixel(const tarn_attribute_set *set, const tarn_texture *texture,
                                                    const uint32_t t[TARN_ATTRIBUTES_MAX])
{
    const tarn_lit_line *line = &set->lit_line;
    const int32_t along = (int32_t)(t[2] >> set->t_shift[2]) - line->key_base;
    uint32_t rgb = 0;
    if (texture == NULL) {
        for (int c = 0; c < 3; c++) rgb = (rgb << 8) | lit_byte((uint32_t)tarn__lit_on_line(line, c, along));
        return rgb;
    }
    const uint8_t *texel = texel_at(set, texture, t);
    for (int c = 0; c < 3; c++) rgb = (rgb << 8) | lit_texel_byte(texel[c], (uint32_t)tarn__lit_on_line(line, c, along));
    return rgb;
}

/* A row's interpolation state before its first covered pixel: the planes'
 * origins, or a span cache that holds no span yet. */
static void row_attributes_start(tarn_row_attributes *row, const tarn_tile_target *tile, const tarn_attribute_set *set,
                                 const tarn_triangle_setup *t, int32_t j)
{
    if (TARN_LINK_PERSPECTIVE_SPAN && set->perspective == TARN_PERSPECTIVE_SPAN) {
        row->span.limit = INT32_MIN;
        row->span.length = -1;
        row->span.log2_span = tile->log2_span;
    } else {
        row_origins(set, t, j, &row->origin);
    }
}

/* The T values of every attribute at pixel i of the span in perspective mode
 * `mode`, the triangle's: a constant in each loop below, which is written once
 * and compiled for each mode, so no pixel asks which mode it is in. In pixel
 * mode, the pixel's near/d by its reciprocal too (`depth`, left alone in the
 * others); an opaque loop's is a local it never reads, and the compiler keeps
 * none of it. */
static TARN_ALWAYS_INLINE void attributes_at(tarn_span *s, int32_t i, int mode, tarn_depth_reciprocal *depth)
{
    const tarn_attribute_set *set = s->set;
    const unsigned steps = s->target->quality->recip_newton_steps;
    if (mode == TARN_PERSPECTIVE_AFFINE)
        affine_t(set, &s->row.origin, i, s->values);
    else if (mode == TARN_PERSPECTIVE_SPAN)
        span_t(set, s->triangle, steps, i, s->j, &s->row.span, s->values);
    else
        exact_t(set, &s->row.origin, i, steps, s->values, depth);
}

void tarn__span_attributes(tarn_span *s, int32_t i, tarn_depth_reciprocal *depth)
{
    const int mode = s->set->perspective;
    if (TARN_LINK_PERSPECTIVE_AFFINE && mode == TARN_PERSPECTIVE_AFFINE)
        attributes_at(s, i, TARN_PERSPECTIVE_AFFINE, depth);
    else if (TARN_LINK_PERSPECTIVE_SPAN && mode == TARN_PERSPECTIVE_SPAN)
        attributes_at(s, i, TARN_PERSPECTIVE_SPAN, depth);
    else if (TARN_LINK_PERSPECTIVE_PIXEL)
        attributes_at(s, i, TARN_PERSPECTIVE_PIXEL, depth);
}

/* An opaque pixel whose colour is the triangle's, `rgb`: untextured, lit alike at
 * its three vertices. */
static TARN_ALWAYS_INLINE uint32_t constant_pixel(void *rgb, tarn_span *s, int32_t i, int32_t index,
                                                 uint32_t inv_depth)
{
    (void)s, (void)i, (void)index, (void)inv_depth;
    return *(const uint32_t *)rgb;
}

/* Any other opaque pixel, in perspective mode `mode`: its colour interpolated (on
 * its line, `on_line`) and, with a texture, times the texel. */
static TARN_ALWAYS_INLINE uint32_t interpolated_pixel(const tarn_texture *texture, tarn_span *s, int32_t i, int mode,
                                                      int on_line)
{
    tarn_depth_reciprocal unread;
    attributes_at(s, i, mode, &unread);
    return on_line ? shade_line_pixel(s->set, texture, s->values) : shade_pixel(s->set, texture, s->values);
}

static TARN_ALWAYS_INLINE uint32_t affine_pixel(void *texture, tarn_span *s, int32_t i, int32_t index,
                                               uint32_t inv_depth)
{
    (void)index, (void)inv_depth;
    return interpolated_pixel(texture, s, i, TARN_PERSPECTIVE_AFFINE, 0);
}

static TARN_ALWAYS_INLINE uint32_t spanned_pixel(void *texture, tarn_span *s, int32_t i, int32_t index,
                                                uint32_t inv_depth)
{
    (void)index, (void)inv_depth;
    return interpolated_pixel(texture, s, i, TARN_PERSPECTIVE_SPAN, 0);
}

static TARN_ALWAYS_INLINE uint32_t perspective_pixel(void *texture, tarn_span *s, int32_t i, int32_t index,
                                                    uint32_t inv_depth)
{
    (void)index, (void)inv_depth;
    return interpolated_pixel(texture, s, i, TARN_PERSPECTIVE_PIXEL, 0);
}

static TARN_ALWAYS_INLINE uint32_t perspective_line_pixel(void *texture, tarn_span *s, int32_t i, int32_t index,
                                                         uint32_t inv_depth)
{
    (void)index, (void)inv_depth;
    return interpolated_pixel(texture, s, i, TARN_PERSPECTIVE_PIXEL, 1);
}

/* The spans of an opaque triangle, a loop each, chosen once a triangle. */
static void draw_constant_span(tarn_span *s, uint32_t rgb)
{
    tarn__span_draw(s, constant_pixel, &rgb);
}

static void draw_affine_span(tarn_span *s, const tarn_texture *texture)
{
    tarn__span_draw(s, affine_pixel, (void *)texture);
}

static void draw_spanned_span(tarn_span *s, const tarn_texture *texture)
{
    tarn__span_draw(s, spanned_pixel, (void *)texture);
}

static void draw_perspective_span(tarn_span *s, const tarn_texture *texture)
{
    tarn__span_draw(s, perspective_pixel, (void *)texture);
}

static void draw_perspective_line_span(tarn_span *s, const tarn_texture *texture)
{
    tarn__span_draw(s, perspective_line_pixel, (void *)texture);
}

static void row_edges_at(const tarn_triangle_setup *t, int32_t i, int32_t j, tarn_row_edges *r)
{
    const unsigned s = t->subpixel_bits;
    for (int k = 0; k < 3; k++) {
        r->at[k] = tarn__edge_at(&t->edges[k], tarn__pixel_centre(i, s), tarn__pixel_centre(j, s));
        r->step_x[k] = (int32_t)((uint32_t)t->edges[k].a << s);
        r->step_y[k] = (int32_t)((uint32_t)t->edges[k].b << s);
    }
}

/* The edges one row down, stepped modulo 2^32: after the last row they may leave
 * the range that rows inside the triangle's box keep to. */
static void row_edges_down(tarn_row_edges *r)
{
    for (int k = 0; k < 3; k++) r->at[k] = (int32_t)((uint32_t)r->at[k] + (uint32_t)r->step_y[k]);
}

/* The covered pixels of row j between the box's columns into the span; 0 when
 * there are none. */
static int covered_run(tarn_triangle_rows *r, int32_t j)
{
    tarn_span *s = &r->span;
    int32_t e0 = r->edges.at[0], e1 = r->edges.at[1], e2 = r->edges.at[2];
    const int32_t step0 = r->edges.step_x[0], step1 = r->edges.step_x[1], step2 = r->edges.step_x[2];
    const int exact_depth = r->set.depth.exact;
    tarn_exact_value depth = r->row_depth;
    const int32_t i1 = r->draw.x1;
    int32_t i = r->draw.x0;
    /* up to the covered run: only the edges and the depth move */
    for (; i <= i1 && (e0 | e1 | e2) < 0; i++) {
        e0 += step0;
        e1 += step1;
        e2 += step2;
        tarn__step_depth(&depth, &r->set.depth.step_x, exact_depth);
    }
    if (i > i1) return 0;
    s->i0 = i;
    s->depth = depth;
    /* each edge is linear along the row, so the covered pixels are one run: after
     * it, nothing more is covered */
    while (i < i1) {
        e0 += step0;
        e1 += step1;
        e2 += step2;
        if ((e0 | e1 | e2) < 0) break;
        i++;
    }
    s->i1 = i;
    s->j = j;
    s->offset = (j - s->target->origin_y) * s->target->stride - s->target->origin_x;
    row_attributes_start(&s->row, s->target, &r->set, &r->setup, j);
    return 1;
}

tarn_span *tarn__triangle_next_span(tarn_triangle_rows *r)
{
    while (r->next_row <= r->draw.y1) {
        const int covered = covered_run(r, r->next_row);
        r->next_row++;
        tarn__step_depth(&r->row_depth, &r->set.depth.step_y, r->set.depth.exact);
        row_edges_down(&r->edges);
        if (covered) return &r->span;
    }
    return NULL;
}

/* Span mode interpolates between exact ends a span apart; on a triangle narrower
 * than a span those ends would be extrapolated outside it, and over so few pixels
 * affine interpolation is both cheaper and closer. The choice depends on the
 * triangle alone, so the image still does not depend on the tile size. */
static uint8_t perspective_mode(const tarn_quality *quality, const tarn_pixel_box *box)
{
    if (quality->perspective == TARN_PERSPECTIVE_SPAN && box->x1 - box->x0 < quality->perspective_span)
        return TARN_PERSPECTIVE_AFFINE;
    return quality->perspective;
}

void tarn__triangle_rows_begin(tarn_triangle_rows *r, const tarn_attribute_request *request)
{
    const tarn_triangle_setup *t = &r->setup;
    const tarn_quality *quality = r->target->quality;
    tarn__setup_attributes(t, request, perspective_mode(quality, &t->box), quality->depth_interpolation, &r->set);
    for (int k = 0; k < r->set.first_varying; k++) r->values[k] = r->set.t_min[k]; /* = t_max: constant */
    r->span.target = r->target;
    r->span.triangle = t;
    r->span.set = &r->set;
    r->span.values = r->values;
    r->span.depth_range.width = 0u; /* found at the first pixel */
    r->span.row.origin.row = INT32_MIN; /* found at the first covered row */
    r->row_depth = tarn__depth_at(t, &r->set.depth, r->draw.x0, r->draw.y0);
    row_edges_at(t, r->draw.x0, r->draw.y0, &r->edges);
    r->next_row = r->draw.y0;
}

/* 1 when some edge is negative at every pixel centre of the box, so no pixel of it
 * is covered: an edge is linear, so its largest value over the box is at the
 * corner its coefficients point to. Three edge values instead of the whole
 * attribute setup for the triangles whose bounds reach into a tile that their
 * area does not. */
static int box_outside_an_edge(const tarn_triangle_setup *t, const tarn_pixel_box *box)
{
    const unsigned s = t->subpixel_bits;
    for (int k = 0; k < 3; k++) {
        const tarn_edge *e = &t->edges[k];
        const int32_t px = tarn__pixel_centre(e->a > 0 ? box->x1 : box->x0, s);
        const int32_t py = tarn__pixel_centre(e->b > 0 ? box->y1 : box->y0, s);
        if (tarn__edge_at(e, px, py) < 0) return 1;
    }
    return 0;
}

int tarn__triangle_enters_tile(tarn_triangle_rows *r, tarn_tile_target *tile, const tarn_screen_vertex vertex[3],
                              uint8_t cull)
{
    tarn_triangle_setup *t = &r->setup;
    if (!tarn__orient_triangle(vertex, cull, tile->quality->subpixel_bits, t)) return 0;
    r->target = tile;
    t->box = tarn__triangle_pixels(t);
    tarn_pixel_box *draw = &r->draw;
    *draw = t->box;
    if (draw->x0 < tile->rect.x0) draw->x0 = tile->rect.x0;
    if (draw->y0 < tile->rect.y0) draw->y0 = tile->rect.y0;
    if (draw->x1 > tile->rect.x1 - 1) draw->x1 = tile->rect.x1 - 1;
    if (draw->y1 > tile->rect.y1 - 1) draw->y1 = tile->rect.y1 - 1;
    return draw->x0 <= draw->x1 && draw->y0 <= draw->y1 && !box_outside_an_edge(t, draw);
}

void tarn__raster_triangle(void *target, const tarn_screen_vertex vertex[3], const tarn_object *object)
{
    const tarn_material *material = object->material;
    tarn_triangle_rows rows;
    if (!tarn__triangle_enters_tile(&rows, target, vertex, material->cull)) return;
    const tarn_quality *quality = rows.target->quality;
    tarn_attribute_request request = {NULL, 0, 0, TARN_LINK_LIT_LINE && quality->lit_colour == TARN_LIT_LINE};
    if (material->texture != NULL && object->mesh->uvs != NULL) {
        request.texture = material->texture;
        request.uv = 1;
    }
    tarn__triangle_rows_begin(&rows, &request);
    /* a colour the three vertices share needs no attribute at any pixel: decided
     * once a triangle */
    const int constant = request.texture == NULL && rows.set.first_varying == rows.set.count;
    const uint32_t rgb = constant ? shade_pixel(&rows.set, NULL, rows.values) : 0u;
    const int mode = rows.set.perspective, on_line = rows.set.first_varying == 2;
    for (tarn_span *s; (s = tarn__triangle_next_span(&rows)) != NULL;) {
        if (constant)
            draw_constant_span(s, rgb);
        else if (TARN_LINK_PERSPECTIVE_AFFINE && mode == TARN_PERSPECTIVE_AFFINE)
            draw_affine_span(s, request.texture);
        else if (TARN_LINK_PERSPECTIVE_SPAN && mode == TARN_PERSPECTIVE_SPAN)
            draw_spanned_span(s, request.texture);
        else if (TARN_LINK_PERSPECTIVE_PIXEL && TARN_LINK_LIT_LINE && on_line)
            draw_perspective_line_span(s, request.texture);
        else if (TARN_LINK_PERSPECTIVE_PIXEL)
            draw_perspective_span(s, request.texture);
    }
}
