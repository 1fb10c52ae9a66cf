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
#include "pipeline.h"

#define T_ONE ((uint32_t)1 << 30)
#define ATTRIBUTES_MAX 5 /* lit r, g, b; texture u, v */

typedef struct {
    uint32_t anchor, step_x, step_y; /* modulo 2^32 */
} plane;

typedef struct {
    int32_t a, b, x, y, bias; /* E(p) = a*(px - x) + b*(py - y) + bias, covered when >= 0 */
} edge;


typedef struct {
    int32_t x0, y0, x1, y1; /* pixel bounds, inclusive */
} pixel_box;

typedef struct {
    const tarn_screen_vertex *v[3]; /* oriented so that area2 > 0 */
    int64_t area2;
    unsigned subpixel_bits;
    int32_t anchor_i, anchor_j;
    pixel_box box; /* pixels whose centres may be covered */
    edge edges[3];
} triangle_setup;

/* near/d rounded to Q1.30 exactly, as quotient and remainder of N(p) / area2: N is
 * the barycentric numerator (plus area2/2 to round), linear in the pixel, so it
 * steps exactly. Exact depth makes the depth test's outcome a property of the
 * triangle, not of how its interpolation rounded: where two surfaces meet, the
 * float reference (which rounds the exact value the same way) agrees pixel for pixel. */
typedef struct {
    uint32_t quotient;  /* modulo 2^32; in range at covered pixels */
    uint32_t remainder; /* in [0, den) */
} exact_value;

typedef struct {
    uint32_t den; /* area2 */
    exact_value step_x, step_y;
} exact_plane;

typedef struct {
    int count;
    int perspective; /* tarn_perspective */
    exact_plane depth; /* near/d, Q1.30 */
    plane q;         /* normalised near/d, perspective modes */
    uint32_t q_min, q_max;
    plane premultiplied[ATTRIBUTES_MAX]; /* T * q / 2^30, or T when affine */
    uint32_t t_min[ATTRIBUTES_MAX], t_max[ATTRIBUTES_MAX];
    unsigned t_shift[ATTRIBUTES_MAX];    /* attribute = T >> t_shift */
    uint32_t u_base, v_base;             /* whole texture repeats removed from u, v (Q16.16) */
} attribute_set;

/* ---- small integer helpers ---------------------------------------------------- */

static int32_t floor_shift(int32_t v, unsigned s)
{
    /* floor(v / 2^s) without relying on >> of a negative number */
    return v >= 0 ? (v >> s) : -(int32_t)((((uint32_t)0 - (uint32_t)v) + ((1u << s) - 1u)) >> s);
}

static int64_t round_div_i64(int64_t num, int64_t den) /* den > 0 */
{
    return num >= 0 ? (num + den / 2) / den : -((-num + den / 2) / den);
}

static exact_value floor_divmod(int64_t num, int64_t den) /* den > 0 */
{
    int64_t q = num / den, r = num % den;
    if (r < 0) {
        r += den;
        q--;
    }
    exact_value v = {(uint32_t)q, (uint32_t)r};
    return v;
}

static void exact_step(exact_value *v, const exact_value *step, uint32_t den)
{
    v->quotient += step->quotient;
    if (v->remainder >= den - step->remainder) {
        v->remainder -= den - step->remainder;
        v->quotient++;
    } else {
        v->remainder += step->remainder;
    }
}

static unsigned bit_length_u32(uint32_t v)
{
    return 32u - tarn_clz32(v);
}

/* ---- setup -------------------------------------------------------------------- */

static edge make_edge(const tarn_screen_vertex *from, const tarn_screen_vertex *to)
{
    edge e;
    int32_t dx = to->x - from->x, dy = to->y - from->y;
    e.a = -dy;
    e.b = dx;
    e.x = from->x;
    e.y = from->y;
    /* With area2 > 0 on a y-down screen, top edges run in +x and left edges in -y. */
    int top_or_left = (dy == 0 && dx > 0) || dy < 0;
    e.bias = top_or_left ? 0 : -1;
    return e;
}

static int32_t edge_at(const edge *e, int32_t px, int32_t py)
{
    return e->a * (px - e->x) + e->b * (py - e->y) + e->bias;
}

static int64_t edge_unbiased_at(const edge *e, int32_t px, int32_t py)
{
    return (int64_t)e->a * (px - e->x) + (int64_t)e->b * (py - e->y);
}

static int32_t pixel_centre(int32_t pixel, unsigned s)
{
    return (int32_t)((uint32_t)pixel << s) + (int32_t)(1u << (s - 1));
}

/* Culls by the material and orients the triangle; returns 0 when nothing draws. */
static int orient_triangle(const tarn_screen_vertex in[3], uint8_t cull, unsigned s,
                           triangle_setup *t)
{
    int64_t area2 = (int64_t)(in[1].x - in[0].x) * (in[2].y - in[0].y) -
                    (int64_t)(in[1].y - in[0].y) * (in[2].x - in[0].x);
    if (area2 == 0) return 0;
    int front = area2 < 0; /* counter-clockwise in the y-up world */
    if ((cull == TARN_CULL_BACK && !front) || (cull == TARN_CULL_FRONT && front)) return 0;
    t->v[0] = &in[0];
    t->v[1] = front ? &in[2] : &in[1];
    t->v[2] = front ? &in[1] : &in[2];
    t->area2 = front ? -area2 : area2;
    t->subpixel_bits = s;
    /* edge k is the one opposite vertex k */
    t->edges[0] = make_edge(t->v[1], t->v[2]);
    t->edges[1] = make_edge(t->v[2], t->v[0]);
    t->edges[2] = make_edge(t->v[0], t->v[1]);
    return 1;
}

/* Pixels whose centres may be covered, before the tile clips them. */
static pixel_box triangle_pixels(const triangle_setup *t)
{
    const unsigned s = t->subpixel_bits;
    const int32_t half = (int32_t)1 << (s - 1);
    int32_t min_x = t->v[0]->x, max_x = min_x, min_y = t->v[0]->y, max_y = min_y;
    for (int k = 1; k < 3; k++) {
        if (t->v[k]->x < min_x) min_x = t->v[k]->x;
        if (t->v[k]->x > max_x) max_x = t->v[k]->x;
        if (t->v[k]->y < min_y) min_y = t->v[k]->y;
        if (t->v[k]->y > max_y) max_y = t->v[k]->y;
    }
    pixel_box box;
    box.x0 = -floor_shift(half - min_x, s); /* ceil((min - half) / 2^s) */
    box.y0 = -floor_shift(half - min_y, s);
    box.x1 = floor_shift(max_x - half, s);
    box.y1 = floor_shift(max_y - half, s);
    return box;
}

/* A plane through the three vertex values (each within [0, 2^30]). */
static plane make_plane(const triangle_setup *t, const int64_t value[3])
{
    const unsigned s = t->subpixel_bits;
    const edge *e1 = &t->edges[1], *e2 = &t->edges[2];
    const int64_t d1 = value[1] - value[0], d2 = value[2] - value[0];
    const int32_t px = pixel_centre(t->anchor_i, s), py = pixel_centre(t->anchor_j, s);
    int64_t at_anchor = value[0] + round_div_i64(edge_unbiased_at(e1, px, py) * d1 +
                                                 edge_unbiased_at(e2, px, py) * d2, t->area2);
    int64_t step_x = round_div_i64(((int64_t)e1->a * d1 + (int64_t)e2->a * d2) * ((int64_t)1 << s), t->area2);
    int64_t step_y = round_div_i64(((int64_t)e1->b * d1 + (int64_t)e2->b * d2) * ((int64_t)1 << s), t->area2);
    plane p = {(uint32_t)at_anchor, (uint32_t)step_x, (uint32_t)step_y};
    return p;
}

static uint32_t plane_at(const plane *p, const triangle_setup *t, int32_t i, int32_t j)
{
    return p->anchor + p->step_x * (uint32_t)(i - t->anchor_i) + p->step_y * (uint32_t)(j - t->anchor_j);
}

/* Scales one attribute's three values toward 2^30 and premultiplies by q. */
static void add_attribute(attribute_set *set, const triangle_setup *t, const uint32_t value[3],
                          const uint32_t q[3])
{
    const int k = set->count++;
    uint32_t largest = value[0] | value[1] | value[2];
    unsigned shift = 30u - (bit_length_u32(largest) > 30u ? 30u : bit_length_u32(largest));
    int64_t premultiplied[3];
    set->t_min[k] = T_ONE;
    set->t_max[k] = 0;
    for (int n = 0; n < 3; n++) {
        uint32_t scaled = (value[n] > T_ONE ? T_ONE : value[n]) << shift;
        if (scaled > T_ONE) scaled = T_ONE;
        if (scaled < set->t_min[k]) set->t_min[k] = scaled;
        if (scaled > set->t_max[k]) set->t_max[k] = scaled;
        premultiplied[n] = set->perspective == TARN_PERSPECTIVE_AFFINE
            ? (int64_t)scaled
            : (int64_t)(((uint64_t)scaled * q[n]) >> 30);
    }
    set->t_shift[k] = shift;
    set->premultiplied[k] = make_plane(t, premultiplied);
}

/* Texture coordinates less their whole repeats (which do not move a texel). */
static void texture_coordinates(const triangle_setup *t, int axis, uint32_t out[3], uint32_t *base)
{
    int32_t c[3], low;
    for (int n = 0; n < 3; n++) c[n] = axis == 0 ? t->v[n]->uv.u : t->v[n]->uv.v;
    low = c[0] < c[1] ? c[0] : c[1];
    low = low < c[2] ? low : c[2];
    int32_t whole = floor_shift(low, 16);
    *base = (uint32_t)whole << 16;
    for (int n = 0; n < 3; n++) out[n] = (uint32_t)c[n] - *base;
}

static int64_t depth_numerator_step(const triangle_setup *t, int32_t a1, int32_t a2)
{
    const int64_t d1 = (int64_t)t->v[1]->inv_depth - t->v[0]->inv_depth;
    const int64_t d2 = (int64_t)t->v[2]->inv_depth - t->v[0]->inv_depth;
    return (a1 * d1 + a2 * d2) * ((int64_t)1 << t->subpixel_bits);
}

static exact_plane make_exact_depth_plane(const triangle_setup *t)
{
    exact_plane p;
    p.den = (uint32_t)t->area2;
    p.step_x = floor_divmod(depth_numerator_step(t, t->edges[1].a, t->edges[2].a), t->area2);
    p.step_y = floor_divmod(depth_numerator_step(t, t->edges[1].b, t->edges[2].b), t->area2);
    return p;
}

/* Exact depth at pixel (i, j): (area2*z0 + E1*(z1 - z0) + E2*(z2 - z0) + area2/2) / area2,
 * each term below 2^61 inside the guard box. */
static exact_value exact_depth_at(const triangle_setup *t, int32_t i, int32_t j)
{
    const unsigned s = t->subpixel_bits;
    const int32_t px = pixel_centre(i, s), py = pixel_centre(j, s);
    const int64_t z0 = t->v[0]->inv_depth;
    int64_t num = t->area2 * z0 + t->area2 / 2 +
                  edge_unbiased_at(&t->edges[1], px, py) * ((int64_t)t->v[1]->inv_depth - z0) +
                  edge_unbiased_at(&t->edges[2], px, py) * ((int64_t)t->v[2]->inv_depth - z0);
    return floor_divmod(num, t->area2);
}

static void setup_attributes(const triangle_setup *t, int textured, uint8_t perspective,
                             attribute_set *set)
{
    int64_t q_values[3];
    uint32_t q[3], largest = 0;
    set->count = 0;
    set->perspective = perspective;
    for (int n = 0; n < 3; n++)
        if (t->v[n]->inv_depth > largest) largest = t->v[n]->inv_depth;
    set->depth = make_exact_depth_plane(t);
    unsigned normalise = tarn_clz32(largest) > 2u ? tarn_clz32(largest) - 2u : 0u;
    set->q_min = T_ONE;
    set->q_max = 0;
    for (int n = 0; n < 3; n++) {
        q[n] = t->v[n]->inv_depth << normalise;
        q_values[n] = q[n];
        if (q[n] < set->q_min) set->q_min = q[n];
        if (q[n] > set->q_max) set->q_max = q[n];
    }
    set->q = make_plane(t, q_values);
    for (int c = 0; c < 3; c++) {
        uint32_t lit[3] = {t->v[0]->lit[c], t->v[1]->lit[c], t->v[2]->lit[c]};
        add_attribute(set, t, lit, q);
    }
    if (textured) {
        uint32_t coordinate[3];
        texture_coordinates(t, 0, coordinate, &set->u_base);
        add_attribute(set, t, coordinate, q);
        texture_coordinates(t, 1, coordinate, &set->v_base);
        add_attribute(set, t, coordinate, q);
    }
}

/* ---- per pixel ------------------------------------------------------------------ */

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

/* Exact T values of every attribute at pixel (i, j). */
static void exact_t(const attribute_set *set, const triangle_setup *t, int32_t i, int32_t j,
                    unsigned steps, uint32_t out[ATTRIBUTES_MAX])
{
    if (set->perspective == TARN_PERSPECTIVE_AFFINE) {
        for (int k = 0; k < set->count; k++) {
            uint32_t v = plane_at(&set->premultiplied[k], t, i, j);
            if ((int32_t)v < (int32_t)set->t_min[k]) v = set->t_min[k];
            out[k] = v > set->t_max[k] ? set->t_max[k] : v;
        }
        return;
    }
    uint32_t q = plane_at(&set->q, t, i, j);
    if ((int32_t)q < (int32_t)set->q_min) q = set->q_min;
    if (q > set->q_max) q = set->q_max;
    unsigned lz;
    uint32_t recip = reciprocal_of_q(q, steps, &lz);
    for (int k = 0; k < set->count; k++)
        out[k] = divide_by_q(plane_at(&set->premultiplied[k], t, i, j), recip, lz,
                             set->t_min[k], set->t_max[k]);
}

/* Linear interpolation between exact values every `span` pixels. Spans sit on a
 * grid fixed to the frame, cut to the triangle's own pixel box, so neither depends
 * on the tile. A span's ends may lie outside the triangle: there the exact values
 * are extrapolated, signed and unclamped (clamping them would bend the slope
 * between the ends); only the interpolated pixels are clamped to the triangle. */
typedef struct {
    int32_t start; /* first pixel of the cached span, or INT32_MIN */
    int32_t t0[ATTRIBUTES_MAX], dt[ATTRIBUTES_MAX];
} span_cache;

#define SPAN_END_MIN (-(1 << 28))
#define SPAN_END_MAX ((1 << 30) + (1 << 28)) /* ends this far apart still fit a step */

/* T = p * 2^30 / q for a signed, extrapolated p, saturated to the span end range. */
static int32_t span_end_t(int32_t premultiplied, uint32_t recip, unsigned lz)
{
    int32_t p = tarn_clamp_i32(premultiplied, -(1 << 30) + 1, (1 << 30) - 1);
    int64_t t = tarn_mul_hi_s32_u32(p * 2, recip); /* |t| <= 2^30 */
    t = t < 0 ? -((-t) << (lz - 1u)) : t << (lz - 1u);
    return (int32_t)(t < SPAN_END_MIN ? SPAN_END_MIN : (t > SPAN_END_MAX ? SPAN_END_MAX : t));
}

static void span_end(const attribute_set *set, const triangle_setup *t, int32_t i, int32_t j,
                     unsigned steps, int32_t out[ATTRIBUTES_MAX])
{
    int32_t q = (int32_t)plane_at(&set->q, t, i, j);
    int32_t q_floor = (int32_t)(set->q_min / 2u) > 1 ? (int32_t)(set->q_min / 2u) : 1;
    unsigned lz;
    uint32_t recip = reciprocal_of_q((uint32_t)tarn_clamp_i32(q, q_floor, (int32_t)T_ONE), steps, &lz);
    for (int k = 0; k < set->count; k++)
        out[k] = span_end_t((int32_t)plane_at(&set->premultiplied[k], t, i, j), recip, lz);
}

static void span_t(const attribute_set *set, const triangle_setup *t, int32_t span, unsigned steps,
                   int32_t i, int32_t j, span_cache *cache, uint32_t out[ATTRIBUTES_MAX])
{
    const unsigned log2_span = 31u - tarn_clz32((uint32_t)span);
    const int32_t grid = (int32_t)((uint32_t)floor_shift(i, log2_span) << log2_span);
    const int32_t start = grid > t->box.x0 ? grid : t->box.x0;
    if (cache->start != start) {
        const int32_t end = grid + span < t->box.x1 ? grid + span : t->box.x1;
        int32_t last[ATTRIBUTES_MAX];
        span_end(set, t, start, j, steps, cache->t0);
        span_end(set, t, end, j, steps, last);
        /* per span, not per pixel: 1/length from the reciprocal, not a division */
        const uint32_t inverse_length = end > start ? tarn_recip_u32((uint32_t)(end - start), 2) : 0u;
        for (int k = 0; k < set->count; k++)
            cache->dt[k] = tarn_mul_hi_s32_u32(last[k] - cache->t0[k], inverse_length);
        cache->start = start;
    }
    for (int k = 0; k < set->count; k++) {
        int32_t value = cache->t0[k] + cache->dt[k] * (i - start);
        out[k] = (uint32_t)tarn_clamp_i32(value, (int32_t)set->t_min[k], (int32_t)set->t_max[k]);
    }
}

static uint32_t shade_pixel(const attribute_set *set, const tarn_texture *texture,
                            const uint32_t t[ATTRIBUTES_MAX])
{
    uint32_t lit[3], rgb = 0;
    for (int c = 0; c < 3; c++) lit[c] = t[c] >> set->t_shift[c]; /* Q8.8 */
    if (texture == NULL) {
        for (int c = 0; c < 3; c++) rgb = (rgb << 8) | ((lit[c] + 128u) >> 8);
        return rgb;
    }
    const unsigned log2_w = 31u - tarn_clz32(texture->width);
    const unsigned log2_h = 31u - tarn_clz32(texture->height);
    const uint32_t u = t[3] >> set->t_shift[3], v = t[4] >> set->t_shift[4]; /* Q16.16 */
    const uint32_t tx = (u >> (16u - log2_w)) & (texture->width - 1u);
    const uint32_t ty = (v >> (16u - log2_h)) & (texture->height - 1u);
    const uint8_t *texel = &texture->rgb[3u * ((ty << log2_w) + tx)];
    for (int c = 0; c < 3; c++) {
        uint32_t product = texel[c] * lit[c]; /* / (255 * 256), to nearest */
        rgb = (rgb << 8) | ((product + (product >> 8) + 32768u) >> 16);
    }
    return rgb;
}

/* Depth test and write; returns 1 when the pixel is the closest so far. */
static int depth_pass(void *depth, int depth_bits, int32_t offset, uint32_t inv_depth)
{
    if ((int32_t)inv_depth < 1) inv_depth = 1;
    if (inv_depth > T_ONE) inv_depth = T_ONE;
    if (depth_bits == 16) {
        uint16_t *d = (uint16_t *)depth + offset;
        uint32_t value = inv_depth >> 14;
        value = value < 1u ? 1u : (value > 0xFFFFu ? 0xFFFFu : value);
        if (value <= *d) return 0;
        *d = (uint16_t)value;
        return 1;
    }
    uint32_t *d = (uint32_t *)depth + offset;
    if (inv_depth <= *d) return 0;
    *d = inv_depth;
    return 1;
}

static void raster_row(tarn_tile_target *tile, const triangle_setup *t, const attribute_set *set,
                       const tarn_texture *texture, int32_t j, int32_t i0, int32_t i1,
                       exact_value depth)
{
    const tarn_quality *quality = tile->quality;
    const unsigned s = t->subpixel_bits;
    const int32_t px = pixel_centre(i0, s), py = pixel_centre(j, s);
    int32_t e[3];
    int32_t e_step[3];
    for (int k = 0; k < 3; k++) {
        e[k] = edge_at(&t->edges[k], px, py);
        e_step[k] = (int32_t)((uint32_t)t->edges[k].a << s);
    }
    const int32_t row = (j - tile->rect.y0) * tile->stride - tile->rect.x0;
    span_cache cache;
    cache.start = INT32_MIN;
    for (int32_t i = i0; i <= i1; i++) {
        if ((e[0] | e[1] | e[2]) >= 0 &&
            depth_pass(tile->depth, quality->depth_bits, row + i, depth.quotient)) {
            uint32_t values[ATTRIBUTES_MAX];
            if (set->perspective == TARN_PERSPECTIVE_SPAN)
                span_t(set, t, quality->perspective_span, quality->recip_newton_steps, i, j, &cache, values);
            else
                exact_t(set, t, i, j, quality->recip_newton_steps, values);
            tile->colour[row + i] = shade_pixel(set, texture, values);
        }
        for (int k = 0; k < 3; k++) e[k] += e_step[k];
        exact_step(&depth, &set->depth.step_x, set->depth.den);
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

void tarn_raster_triangle(tarn_tile_target *tile, const tarn_screen_vertex vertex[3],
                          const tarn_object *object)
{
    const tarn_material *material = object->material;
    triangle_setup t;
    if (!orient_triangle(vertex, material->cull, tile->quality->subpixel_bits, &t)) return;
    t.box = triangle_pixels(&t);
    t.anchor_i = t.box.x0;
    t.anchor_j = t.box.y0;
    pixel_box draw = t.box;
    if (draw.x0 < tile->rect.x0) draw.x0 = tile->rect.x0;
    if (draw.y0 < tile->rect.y0) draw.y0 = tile->rect.y0;
    if (draw.x1 > tile->rect.x1 - 1) draw.x1 = tile->rect.x1 - 1;
    if (draw.y1 > tile->rect.y1 - 1) draw.y1 = tile->rect.y1 - 1;
    if (draw.x0 > draw.x1 || draw.y0 > draw.y1) return;
    const int textured = material->texture != NULL && object->mesh->uvs != NULL;
    attribute_set set;
    setup_attributes(&t, textured, perspective_mode(tile->quality, &t.box), &set);
    exact_value depth = exact_depth_at(&t, draw.x0, draw.y0);
    for (int32_t j = draw.y0; j <= draw.y1; j++) {
        raster_row(tile, &t, &set, textured ? material->texture : NULL, j, draw.x0, draw.x1, depth);
        exact_step(&depth, &set.depth.step_y, set.depth.den);
    }
}
