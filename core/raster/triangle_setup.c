/* raster_setup.c: per-triangle setup for the rasterizer: winding and culling, edge
 * functions, the pixel box, attribute planes and the exact depth plane. 64-bit
 * products and divisions are allowed here (once per triangle per tile), never in
 * raster.c. */
#include "raster/raster_internal.h"

static tarn_exact_value floor_divmod(int64_t num, const tarn_divisor *den)
{
    uint32_t r;
    const int64_t q = tarn_divide_floor_i64(num, den, &r);
    tarn_exact_value v = {(uint32_t)q, r};
    return v;
}

static tarn_exact_step_value exact_step_of(int64_t num, const tarn_divisor *den)
{
    const tarn_exact_value v = floor_divmod(num, den);
    const tarn_exact_step_value step = {v.quotient, v.remainder, den->divisor - v.remainder};
    return step;
}

static unsigned bit_length_u32(uint32_t v)
{
    return 32u - tarn_clz32(v);
}

static tarn_edge make_edge(const tarn_screen_vertex *from, const tarn_screen_vertex *to)
{
    tarn_edge e;
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

/* The edge function without its bias at a pixel centre inside the triangle's
 * bounds: 32-bit, as raster.c's edge_at, since coordinates inside the guard box
 * differ by less than 2^15 subpixels (tarn__config_check) and each product stays
 * below 2^30. */
static int32_t edge_unbiased_at(const tarn_edge *e, int32_t px, int32_t py)
{
    return e->a * (px - e->x) + e->b * (py - e->y);
}

int tarn__orient_triangle(const tarn_screen_vertex in[3], uint8_t cull, unsigned s,
                           tarn_triangle_setup *t)
{
    const int64_t area2 = tarn__drawn_area2(in, cull);
    if (area2 == 0) return 0;
    int front = area2 < 0;
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

tarn_pixel_box tarn__triangle_pixels(const tarn_triangle_setup *t)
{
    tarn_subpixel_bounds bounds = tarn__bounds_empty();
    for (int k = 0; k < 3; k++) tarn__bounds_add(&bounds, t->v[k]);
    return tarn__bounds_pixels(&bounds, t->subpixel_bits);
}

/* Where every plane of a triangle is found: the pixel nearest its farthest vertex
 * (the least near/d), from that vertex's value and the edge values there that
 * weigh the other two. A plane's rounding grows with the distance from where it
 * is found, and perspective divides by the plane of q, which is least at that
 * vertex: found there, the rounding is least where a unit of it weighs the most.
 * Found at the box's corner instead, a triangle cut by the near plane, its q a
 * thousand times smaller at the far end, moved texels there by a third of a texel
 * at a few thousand texels a triangle. The plane is then carried to the box's
 * corner, modulo 2^32, so each pixel's value is the same number. */
typedef struct {
    uint8_t far, next, after; /* the vertex the planes start from, and the two others */
    int32_t i, j;         /* the pixel they are found at */
    int32_t e_next, e_after; /* the edge values there weighing vertices next and after */
} plane_anchor;

static plane_anchor anchor_of(const tarn_triangle_setup *t)
{
    const unsigned s = t->subpixel_bits;
    plane_anchor anchor;
    anchor.far = 0;
    for (int k = 1; k < 3; k++)
        if (t->v[k]->inv_depth < t->v[anchor.far]->inv_depth) anchor.far = (uint8_t)k;
    anchor.next = (uint8_t)(anchor.far == 2 ? 0 : anchor.far + 1); /* no % 3: the M0 would call a divider */
    anchor.after = (uint8_t)(anchor.far == 0 ? 2 : anchor.far - 1);
    const tarn_screen_vertex *far = t->v[anchor.far];
    anchor.i = tarn_floor_shift(far->x, s); /* the pixel whose square holds it */
    anchor.j = tarn_floor_shift(far->y, s);
    const int32_t px = tarn__pixel_centre(anchor.i, s), py = tarn__pixel_centre(anchor.j, s);
    anchor.e_next = edge_unbiased_at(&t->edges[anchor.next], px, py);
    anchor.e_after = edge_unbiased_at(&t->edges[anchor.after], px, py);
    return anchor;
}

/* e1 * d1 + e2 * d2 for a plane: its two weights (or the anchor pixel's edge
 * values, below 2^24) and the values' differences, each within +-2^30. */
static int64_t weighted_sum(int32_t e1, int32_t d1, int32_t e2, int32_t d2)
{
    return tarn_dot2_i30_wide(e1, d1, e2, d2);
}

/* The same for two edge coefficients (a or b), which are coordinate differences
 * inside the guard box and so below 2^15. */
static int64_t coefficient_sum(int32_t a1, int32_t d1, int32_t a2, int32_t d2)
{
    return tarn_mul_i16_i32_wide(a1, d1) + tarn_mul_i16_i32_wide(a2, d2);
}

/* What every plane of a triangle divides by area2, divided once: the weights of the
 * anchor's two other vertices (edges next and after over area2) a pixel step along
 * x, along y, and at the anchor pixel, each times 2^shift. A plane through values
 * from, from + d1 and from + d2 then steps by (d1 * x[0] + d2 * x[1]) / 2^shift:
 * two products where a division by area2 cost the Cortex-M0 about 120
 * instructions, three of them a plane. The largest weight keeps 29 bits or more.
 * A sliver (a step weight of 1 or more: less than a pixel across) keeps the
 * divisions: its steps across are so much larger than its steps along that
 * weights of 29 bits would move its far pixels by hundreds of units (test_raster's
 * random triangles: 74 units of 2^-30 at most, where weights alone gave 3,681). */
typedef struct {
    int32_t x[2], y[2], at[2];
    unsigned shift;
    tarn_divisor area2;
    uint8_t sliver;
} plane_basis;

static uint32_t magnitude_u32(int32_t v)
{
    return v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
}

/* c / area2 = c * recip / 2^(62 - shift) for each edge coefficient or value c
 * (below 2^24 in magnitude: the guard box's 2^15 subpixels times a pixel's, or two
 * such products at the anchor pixel, within a pixel of its vertex): the high words
 * of c * 2^up (below 2^31) times the reciprocal (at most 2^31), on the scale
 * 2^(30 - shift + up). */
static plane_basis basis_of(const tarn_triangle_setup *t, const plane_anchor *anchor)
{
    const tarn_edge *e1 = &t->edges[anchor->next], *e2 = &t->edges[anchor->after];
    const int32_t pixel = 1 << t->subpixel_bits;
    const int32_t c[6] = {e1->a * pixel, e2->a * pixel, e1->b * pixel, e2->b * pixel, anchor->e_next, anchor->e_after};
    plane_basis b;
    b.area2 = tarn_divisor_of((uint32_t)t->area2);
    uint32_t largest = 1u;
    for (int k = 0; k < 6; k++) largest |= magnitude_u32(c[k]);
    const unsigned up = tarn_clz32(largest) - 1u;
    int32_t w[6];
    uint32_t steepest = 0u;
    for (int k = 0; k < 6; k++) {
        const uint32_t high = tarn_mul_hi_u32(magnitude_u32(c[k]) << up, b.area2.recip);
        if (k < 4 && high > steepest) steepest = high;
        w[k] = c[k] < 0 ? -(int32_t)high : (int32_t)high;
    }
    b.shift = 30u - b.area2.shift + up;
    for (int k = 0; k < 2; k++) {
        b.x[k] = w[k];
        b.y[k] = w[2 + k];
        b.at[k] = w[4 + k];
    }
    b.sliver = b.shift < 31u && (steepest >> b.shift) != 0u; /* a step weight of 1 or more */
    return b;
}

/* (d1 * w[0] + d2 * w[1]) / 2^shift, rounded: |d| <= 2^30 and |w| <= 2^30, so the
 * sum stays below 2^61. */
static uint32_t weighted(int32_t d1, int32_t d2, const int32_t w[2], unsigned shift)
{
    return tarn_round_shift_low32((uint64_t)weighted_sum(d1, w[0], d2, w[1]), shift);
}

/* n / area2 rounded to nearest (halves away from 0), exactly (|n| < 2^61), modulo 2^32. */
static uint32_t over_area(int64_t n, const tarn_divisor *area2)
{
    const int64_t half = area2->divisor / 2u;
    return (uint32_t)tarn_divide_trunc_i64(n < 0 ? n - half : n + half, area2);
}

/* A sliver's plane: each of its three sums divided by area2 exactly. */
static void sliver_plane(const tarn_triangle_setup *t, const plane_basis *basis, const plane_anchor *anchor,
                         int32_t d1, int32_t d2, tarn_plane *p)
{
    const int64_t pixel = (int64_t)1 << t->subpixel_bits;
    const tarn_edge *e1 = &t->edges[anchor->next], *e2 = &t->edges[anchor->after];
    p->step_x = over_area(coefficient_sum(e1->a, d1, e2->a, d2) * pixel, &basis->area2);
    p->step_y = over_area(coefficient_sum(e1->b, d1, e2->b, d2) * pixel, &basis->area2);
    p->anchor = over_area(weighted_sum(anchor->e_next, d1, anchor->e_after, d2), &basis->area2);
}

/* A plane found at the anchor pixel through `from` there, carried to the box's
 * corner, where tarn__plane_at counts from. */
static tarn_plane at_box_corner(const tarn_triangle_setup *t, const plane_anchor *anchor, tarn_plane p, uint32_t from)
{
    p.anchor += from + p.step_x * (uint32_t)(t->box.x0 - anchor->i) + p.step_y * (uint32_t)(t->box.y0 - anchor->j);
    return p;
}

/* A plane through the three vertex values (each within [0, 2^30], so their
 * differences fit 32 bits), from the triangle's basis. */
static tarn_plane make_plane(const tarn_triangle_setup *t, const plane_basis *basis, const plane_anchor *anchor,
                             const uint32_t value[3])
{
    const uint32_t from = value[anchor->far];
    const int32_t d1 = (int32_t)(value[anchor->next] - from), d2 = (int32_t)(value[anchor->after] - from);
    if (d1 == 0 && d2 == 0) { /* a flat plane: every product below would be 0 */
        const tarn_plane flat = {from, 0u, 0u};
        return flat;
    }
    tarn_plane p;
    if (basis->sliver) {
        sliver_plane(t, basis, anchor, d1, d2, &p);
    } else {
        p.step_x = weighted(d1, d2, basis->x, basis->shift);
        p.step_y = weighted(d1, d2, basis->y, basis->shift);
        p.anchor = weighted(d1, d2, basis->at, basis->shift);
    }
    return at_box_corner(t, anchor, p, from);
}

/* sum / 2^shift and sum / 2^(shift - up), each rounded as `weighted` rounds, modulo
 * 2^32; where up passes shift the second is sum times 2^(up - shift), exactly, whose
 * low 32 bits are the low word's. */
static void shifted_and_up(int64_t sum, unsigned shift, unsigned up, uint32_t *value, uint32_t *value_up)
{
    *value = tarn_round_shift_low32((uint64_t)sum, shift);
    if (shift >= up)
        *value_up = tarn_round_shift_low32((uint64_t)sum, shift - up);
    else
        *value_up = up - shift < 32u ? (uint32_t)sum << (up - shift) : 0u;
}

/* The planes through three values and through the same values times 2^up (each
 * within [0, 2^30]), `p` and `p_up`, from the one basis of a triangle that is not a
 * sliver: the second's sums are the first's times 2^up, exactly, so the same three
 * sums shifted down by `up` less give it, as make_plane would, without its six
 * products. */
static void planes_and_up(const tarn_triangle_setup *t, const plane_basis *basis, const plane_anchor *anchor,
                          const uint32_t value[3], unsigned up, tarn_plane *p, tarn_plane *p_up)
{
    const uint32_t from = value[anchor->far];
    const int32_t d1 = (int32_t)(value[anchor->next] - from), d2 = (int32_t)(value[anchor->after] - from);
    shifted_and_up(weighted_sum(d1, basis->x[0], d2, basis->x[1]), basis->shift, up, &p->step_x, &p_up->step_x);
    shifted_and_up(weighted_sum(d1, basis->y[0], d2, basis->y[1]), basis->shift, up, &p->step_y, &p_up->step_y);
    shifted_and_up(weighted_sum(d1, basis->at[0], d2, basis->at[1]), basis->shift, up, &p->anchor, &p_up->anchor);
    *p = at_box_corner(t, anchor, *p, from);
    *p_up = at_box_corner(t, anchor, *p_up, from << up);
}

/* An attribute's three T values (each at most 2^30), with the shift that makes
 * them the attribute (attribute = T >> shift): their range and, with q, their plane;
 * an attribute below set->first_varying is constant and gets no plane. */
static void add_attribute(tarn_attribute_set *set, const tarn_triangle_setup *t, const plane_basis *basis,
                          const plane_anchor *anchor, uint32_t scaled[3], unsigned shift, const uint32_t q[3])
{
    const int k = set->count++;
    /* at most T_ONE: the signed least and largest are the same numbers */
    set->t_min[k] = (uint32_t)tarn_min3_i32((int32_t)scaled[0], (int32_t)scaled[1], (int32_t)scaled[2]);
    set->t_max[k] = (uint32_t)tarn_max3_i32((int32_t)scaled[0], (int32_t)scaled[1], (int32_t)scaled[2]);
    set->t_shift[k] = shift;
    if (k < set->first_varying) return; /* constant: no plane */
    /* floor(T * q / 2^30) for T and q at most 2^30: the high word of their doubles'
       product (each at most 2^31), which the Cortex-M0 takes in four 16x16 products
       instead of the whole 64-bit product's words */
    if (set->perspective != TARN_PERSPECTIVE_AFFINE)
        for (int n = 0; n < 3; n++) scaled[n] = tarn_mul_hi_u32_small(scaled[n] << 1, q[n] << 1);
    set->premultiplied[k] = make_plane(t, basis, anchor, scaled);
}

/* Three values (each at most 2^30) scaled toward 2^30 as T values; returns the
 * shift. (Found before add_attribute is called, not inside it: the Cortex-M0's
 * deepest stack runs through the plane it makes.) */
static unsigned attribute_t(const uint32_t value[3], uint32_t scaled[3])
{
    const unsigned length = bit_length_u32(value[0] | value[1] | value[2]);
    const unsigned shift = 30u - (length > 30u ? 30u : length);
    for (int n = 0; n < 3; n++) {
        const uint32_t v = (value[n] > TARN_T_ONE ? TARN_T_ONE : value[n]) << shift;
        scaled[n] = v > TARN_T_ONE ? TARN_T_ONE : v;
    }
    return shift;
}

/* Whether the lit colour's three channels are all 255.0 (65280 in Q8.8). */
static int lit_is_full(const tarn_attribute_set *set)
{
    for (int c = 0; c < 3; c++)
        if ((set->t_min[c] >> set->t_shift[c]) != 65280u) return 0;
    return 1;
}

/* Whether the three vertices are lit alike: on a level surface or a flat-lit one. */
static int lit_alike(const tarn_triangle_setup *t)
{
    for (int c = 0; c < 3; c++)
        if (t->v[1]->lit[c] != t->v[0]->lit[c] || t->v[2]->lit[c] != t->v[0]->lit[c]) return 0;
    return 1;
}

/* The vertex whose channel c is least (ties to the first) and the one where it is
 * largest (ties to the last), so they differ when the channel varies. */
static void channel_extremes(const tarn_triangle_setup *t, int c, int *least, int *largest)
{
    *least = 0;
    *largest = 2;
    for (int n = 1; n < 3; n++)
        if (t->v[n]->lit[c] < t->v[*least]->lit[c]) *least = n;
    for (int n = 1; n >= 0; n--)
        if (t->v[n]->lit[c] > t->v[*largest]->lit[c]) *largest = n;
}

/* The channel whose values spread the widest over the three vertices. */
static int widest_channel(const tarn_triangle_setup *t)
{
    int widest = 0;
    uint32_t widest_range = 0u;
    for (int c = 0; c < 3; c++) {
        int least, largest;
        channel_extremes(t, c, &least, &largest);
        const uint32_t range = (uint32_t)t->v[largest]->lit[c] - t->v[least]->lit[c];
        if (range > widest_range) {
            widest = c;
            widest_range = range;
        }
    }
    return widest;
}

/* The line the lit colour lies on, into `line`, keyed by its widest channel,
 * which it returns; -1 when a vertex's channel lies further from it than
 * TARN_LIT_LINE_TOLERANCE. Found from the key's least and largest vertices; the
 * key's slope is exactly one. Kept out of line: the boards' deepest stack runs
 * through the setup's planes, after it. */
static TARN_NOINLINE int lit_line_key(const tarn_triangle_setup *t, tarn_lit_line *line)
{
    int least, largest;
    const int key = widest_channel(t);
    channel_extremes(t, key, &least, &largest);
    const int32_t spread = (int32_t)t->v[largest]->lit[key] - t->v[least]->lit[key]; /* 1..65280 */
    line->key_base = t->v[least]->lit[key];
    for (int c = 0; c < 3; c++) {
        const int32_t change = (int32_t)t->v[largest]->lit[c] - t->v[least]->lit[c]; /* |change| <= spread */
        const int32_t half = change < 0 ? -spread / 2 : spread / 2;
        line->base[c] = t->v[least]->lit[c];
        line->slope[c] = (change * 32768 + half) / spread; /* below 2^31 */
        /* the line is monotone in the key, so in range at its far end it is in range
           at every pixel, which then needs no clamp */
        const int32_t far = tarn__lit_on_line(line, c, spread);
        if (far < 0 || far > 65280) return -1;
    }
    for (int n = 0; n < 3; n++)
        for (int c = 0; c < 3; c++) {
            const int32_t along = (int32_t)t->v[n]->lit[key] - line->key_base; /* as a pixel finds it */
            const int32_t off = tarn__lit_on_line(line, c, along) - t->v[n]->lit[c];
            if (off > TARN_LIT_LINE_TOLERANCE || off < -TARN_LIT_LINE_TOLERANCE) return -1;
        }
    return key;
}

/* Texture coordinates less a base the pixels add back: for a texture, their whole
 * repeats, which do not move a texel, so a pixel finds its texel in T alone; for
 * water, whose maps add the base to each pixel's coordinate, their least value.
 * The perspective divide's error is a share of T, and a water map's scale
 * multiplies it: T holding a whole repeat of the mesh's coordinates, a map at
 * scale 8192 on a triangle 1/128 of it across was off by a texel at one Newton
 * step (2^-18); holding only the triangle's own span, by 1/64 of one. */
static void texture_coordinates(const tarn_triangle_setup *t, int axis, int whole_repeats, uint32_t out[3],
                                uint32_t *base)
{
    int32_t c[3], low;
    for (int n = 0; n < 3; n++) c[n] = axis == 0 ? t->v[n]->uv.u : t->v[n]->uv.v;
    low = c[0] < c[1] ? c[0] : c[1];
    low = low < c[2] ? low : c[2];
    *base = whole_repeats ? (uint32_t)tarn_floor_shift(low, 16) << 16 : (uint32_t)low;
    for (int n = 0; n < 3; n++) out[n] = (uint32_t)c[n] - *base;
}

/* One texture coordinate axis as T values, as attribute_t: the coordinates less
 * their base, with the 16 bits below Q16.16 a clipped vertex keeps, scaled toward
 * 2^30; returns the shift (up to 46). Those bits count for as much as T holds: a
 * triangle across less than a repeat keeps most of them, and near the eye, where
 * one bit of Q16.16 spans hundreds of pixels, such a triangle is all that draws. */
static unsigned texture_coordinate_t(const tarn_triangle_setup *t, int axis, int whole_repeats, uint32_t *base,
                                     uint32_t scaled[3])
{
    uint32_t value[3], whole = 0u, below = 0u;
    texture_coordinates(t, axis, whole_repeats, value, base);
    for (int n = 0; n < 3; n++) {
        whole |= value[n];
        below |= t->v[n]->uv_low[axis];
    }
    if (below == 0u) return attribute_t(value, scaled); /* no clipped vertex: the same numbers */
    /* the values with their low bits are value * 2^16 + low (Q16.32, below 2^48): T
       is that times 2^up / 2^down, at most 2^30, taken in 32-bit words; past 2^14
       repeats (down > 16) the values saturate as a plain attribute's would */
    const unsigned length = whole != 0u ? 16u + bit_length_u32(whole) : bit_length_u32(below);
    const unsigned down = length > 30u ? (length - 30u > 16u ? 16u : length - 30u) : 0u;
    const unsigned up = length < 30u ? 30u - length : 0u;
    const unsigned shift = 16u + up - down; /* at most 29 where a value is not 0 */
    for (int n = 0; n < 3; n++) {
        /* the two parts share no bit: the low bits land below `shift` */
        const uint32_t high = value[n] == 0u ? 0u : (value[n] > (TARN_T_ONE >> shift) ? TARN_T_ONE : value[n] << shift);
        const uint32_t v = high | (((uint32_t)t->v[n]->uv_low[axis] << up) >> down);
        scaled[n] = v > TARN_T_ONE ? TARN_T_ONE : v;
    }
    return shift;
}

/* Vertex k's inverse depth less vertex 0's: both within [1, 2^30]. */
static int32_t depth_difference(const tarn_triangle_setup *t, int k)
{
    return (int32_t)(t->v[k]->inv_depth - t->v[0]->inv_depth);
}

static int64_t depth_numerator_step(const tarn_triangle_setup *t, int32_t a1, int32_t a2)
{
    return coefficient_sum(a1, depth_difference(t, 1), a2, depth_difference(t, 2)) * ((int64_t)1 << t->subpixel_bits);
}

static tarn_depth_plane make_exact_depth_plane(const tarn_triangle_setup *t, const tarn_divisor *area2)
{
    tarn_depth_plane p;
    p.den = *area2;
    p.step_x = exact_step_of(depth_numerator_step(t, t->edges[1].a, t->edges[2].a), &p.den);
    p.step_y = exact_step_of(depth_numerator_step(t, t->edges[1].b, t->edges[2].b), &p.den);
    p.anchor = 0u;
    p.exact = 1u;
    return p;
}

/* The depth plane `p` of a plane's steps, set in place: the Cortex-M0's and the
 * RISC-V's deepest stack runs through the setup's depth. */
static void depth_on_plane(tarn_depth_plane *p, const plane_basis *basis, const tarn_plane *steps)
{
    p->den = basis->area2;
    p->step_x.quotient = steps->step_x;
    p->step_y.quotient = steps->step_y;
    p->step_x.remainder = p->step_y.remainder = 0u;
    p->step_x.carry_at = p->step_y.carry_at = UINT32_MAX;
    p->anchor = steps->anchor;
    p->exact = 0u;
}

/* Depth on a plane through the vertices' near/d, as the attributes' planes, into `p`. */
static void make_depth_plane(const tarn_triangle_setup *t, const plane_basis *basis, const plane_anchor *anchor,
                             tarn_depth_plane *p)
{
    const uint32_t value[3] = {t->v[0]->inv_depth, t->v[1]->inv_depth, t->v[2]->inv_depth};
    const tarn_plane steps = make_plane(t, basis, anchor, value);
    depth_on_plane(p, basis, &steps);
}

/* Exact depth at pixel (i, j): (area2*z0 + E1*(z1 - z0) + E2*(z2 - z0) + area2/2) / area2,
 * each term below 2^61 inside the guard box. */
tarn_exact_value tarn__exact_depth_at(const tarn_triangle_setup *t, const tarn_depth_plane *depth, int32_t i, int32_t j)
{
    const unsigned s = t->subpixel_bits;
    const int32_t px = tarn__pixel_centre(i, s), py = tarn__pixel_centre(j, s);
    /* area2 is below 2^31: two products of coordinate differences; an edge's value
       at a pixel of the box may pass 2^30, so whole 32-bit products */
    int64_t num = (int64_t)tarn_mul_u32_wide((uint32_t)t->area2, t->v[0]->inv_depth) + t->area2 / 2 +
                  tarn_mul_i32_wide(edge_unbiased_at(&t->edges[1], px, py), depth_difference(t, 1)) +
                  tarn_mul_i32_wide(edge_unbiased_at(&t->edges[2], px, py), depth_difference(t, 2));
    return floor_divmod(num, &depth->den);
}

/* The texel a pixel samples, from u or v's T value: (T >> t_shift) is Q16.16, whose
 * top log2(size) fraction bits pick the texel. Taken as one shift, which at 31
 * gives 0 as the two would (T is at most 2^30). */
static uint8_t texel_shift(unsigned t_shift, uint32_t size)
{
    const unsigned shift = t_shift + 16u - (31u - tarn_clz32(size));
    return (uint8_t)(shift > 31u ? 31u : shift);
}

/* Depth on a plane through the vertices' near/d, and q's plane, near/d times
 * 2^normalise, from the same sums (planes_and_up); 0 where they cannot share them:
 * a sliver's planes are exact divisions, and a vertex's q of 0 is lifted to 1.
 * Kept out of line, beside the planes made one at a time: its frame is not on the
 * setup's deepest path, which runs through a sliver's division. */
static TARN_NOINLINE int shared_depth_and_q(const tarn_triangle_setup *t, const plane_basis *basis,
                                            const plane_anchor *anchor, unsigned normalise, tarn_attribute_set *set)
{
    const uint32_t inv_depth[3] = {t->v[0]->inv_depth, t->v[1]->inv_depth, t->v[2]->inv_depth};
    if (basis->sliver || inv_depth[0] == 0u || inv_depth[1] == 0u || inv_depth[2] == 0u) return 0;
    tarn_plane depth;
    planes_and_up(t, basis, anchor, inv_depth, normalise, &depth, &set->q);
    depth_on_plane(&set->depth, basis, &depth);
    return 1;
}

static void set_texel_lookup(tarn_attribute_set *set, const tarn_texture *texture)
{
    set->texel_shift[0] = texel_shift(set->t_shift[TARN_ATTRIBUTE_U], texture->width);
    set->texel_shift[1] = texel_shift(set->t_shift[TARN_ATTRIBUTE_V], texture->height);
    set->texel_mask[0] = texture->width - 1u;
    set->texel_mask[1] = texture->height - 1u;
    set->log2_width = 31u - tarn_clz32(texture->width);
}

void tarn__setup_attributes(const tarn_triangle_setup *t, const tarn_attribute_request *request,
                           uint8_t perspective, uint8_t depth_interpolation, tarn_attribute_set *set)
{
    uint32_t q[3], largest = 0;
    set->count = 0;
    int channel_2 = 2; /* the channel attribute 2 holds: blue, or on a line the key */
    set->first_varying = lit_alike(t) ? 3 : 0;
    if (TARN_LINK_LIT_LINE && set->first_varying == 0 && request->lit_line &&
        perspective == TARN_PERSPECTIVE_PIXEL) {
        const int key = lit_line_key(t, &set->lit_line);
        if (key >= 0) {
            set->first_varying = 2;
            channel_2 = key;
        }
    }
    set->perspective = perspective;
    for (int n = 0; n < 3; n++)
        if (t->v[n]->inv_depth > largest) largest = t->v[n]->inv_depth;
    unsigned normalise = tarn_clz32(largest) > 2u ? tarn_clz32(largest) - 2u : 0u;
    set->q_shift = (uint8_t)normalise;
    set->q_min = TARN_T_ONE;
    set->q_max = 0;
    for (int n = 0; n < 3; n++) {
        q[n] = t->v[n]->inv_depth << normalise;
        if (q[n] == 0u) q[n] = 1u; /* a pixel's reciprocal of q takes [1, 2^30] */
        if (q[n] < set->q_min) set->q_min = q[n];
        if (q[n] > set->q_max) set->q_max = q[n];
    }
    const plane_anchor anchor = anchor_of(t);
    const plane_basis basis = basis_of(t, &anchor);
    const int exact_depth = TARN_LINK_EXACT_DEPTH && depth_interpolation == TARN_DEPTH_EXACT;
    const int uses_q = perspective != TARN_PERSPECTIVE_AFFINE; /* affine interpolation never reads q */
    /* a build without pixel perspective (the 16 KB boards') keeps them apart: span
     * mode divides by q only at its spans' ends, so sharing saves it little, and
     * its code would take most of what is left of the M0's 32 KB code budget */
    if (exact_depth || !uses_q || !TARN_LINK_PERSPECTIVE_PIXEL || !shared_depth_and_q(t, &basis, &anchor, normalise, set)) {
        if (exact_depth)
            set->depth = make_exact_depth_plane(t, &basis.area2);
        else
            make_depth_plane(t, &basis, &anchor, &set->depth);
        if (uses_q) set->q = make_plane(t, &basis, &anchor, q);
    }
    uint32_t scaled[3];
    unsigned shift;
    for (int k = 0; k < 3; k++) {
        const int c = k == 2 ? channel_2 : k;
        const uint32_t lit[3] = {t->v[0]->lit[c], t->v[1]->lit[c], t->v[2]->lit[c]};
        shift = attribute_t(lit, scaled);
        add_attribute(set, t, &basis, &anchor, scaled, shift, q);
    }
    set->lit_full = (uint8_t)(set->first_varying == 3 && lit_is_full(set));
    if (request->uv) {
        const int whole_repeats = request->texture != NULL;
        shift = texture_coordinate_t(t, 0, whole_repeats, &set->u_base, scaled);
        add_attribute(set, t, &basis, &anchor, scaled, shift, q);
        shift = texture_coordinate_t(t, 1, whole_repeats, &set->v_base, scaled);
        add_attribute(set, t, &basis, &anchor, scaled, shift, q);
        if (request->texture != NULL) set_texel_lookup(set, request->texture);
    }
    if (request->fresnel) {
        const uint32_t fresnel[3] = {t->v[0]->fresnel, t->v[1]->fresnel, t->v[2]->fresnel};
        shift = attribute_t(fresnel, scaled);
        add_attribute(set, t, &basis, &anchor, scaled, shift, q);
    }
}
