/* raster_internal.h: the fourth stage of a frame (core/raster/), internal to
 * core/: one screen triangle into one tile's buffers.
 *
 *   triangle_setup.c  once per triangle per tile: culling, edge functions, the pixel
 *                     box, the attribute and depth planes (64-bit products and exact
 *                     divisions are allowed here)
 *   raster.c          per row: the covered run of pixels, found with the edge
 *                     functions (tarn_span); per pixel of an opaque material:
 *                     depth test, attributes, texel, colour
 *   depth_code.c      where a pixel's near/d leaves the range of the last: the
 *                     16-bit depth code's next range
 *
 * It takes the screen triangles of core/tile/'s walk and draws them into a
 * tarn_tile_target. A triangle is set up once for a tile (tarn_triangle_rows),
 * then its rows are handed out one at a time to the stage that owns its material:
 * raster.c itself for an opaque one (a loop chosen once a triangle: a constant
 * colour, or interpolated colour and texels), core/water/ for water. The split is
 * the numeric contract made visible: setup may divide; nothing a span runs may,
 * and tests/check_core_purity.sh proves it on the Cortex-M0 build. */
#ifndef TARN_RASTER_INTERNAL_H
#define TARN_RASTER_INTERNAL_H

#include "tile/tile_internal.h"

/* Where inlining decides the per-pixel cost: a function the compiler must inline
 * (a pixel's step, written once and compiled into each loop that takes it), and
 * one it must not (what runs once a span, called from those loops); and a branch
 * a pixel rarely takes, laid out of the loop's way. */
#if defined(__GNUC__)
#define TARN_ALWAYS_INLINE __attribute__((always_inline)) inline
#define TARN_NOINLINE __attribute__((noinline))
#define TARN_UNLIKELY(condition) __builtin_expect((condition) != 0, 0)
#else
#define TARN_ALWAYS_INLINE inline
#define TARN_NOINLINE
#define TARN_UNLIKELY(condition) (condition)
#endif

#define TARN_T_ONE ((uint32_t)1 << 30)
#define TARN_ATTRIBUTES_MAX 6 /* lit r, g, b; texture u, v; fresnel */
#define TARN_ATTRIBUTE_U 3
#define TARN_ATTRIBUTE_V 4
#define TARN_ATTRIBUTE_FRESNEL 5

typedef struct {
    uint32_t anchor, step_x, step_y; /* modulo 2^32 */
} tarn_plane;

typedef struct {
    int32_t a, b, x, y, bias; /* E(p) = a*(px - x) + b*(py - y) + bias, covered when >= 0 */
} tarn_edge;

typedef struct {
    const tarn_screen_vertex *v[3]; /* oriented so that area2 > 0 */
    int64_t area2;
    unsigned subpixel_bits;
    tarn_pixel_box box; /* pixels whose centres may be covered; planes are anchored at (x0, y0) */
    tarn_edge edges[3];
} tarn_triangle_setup;

/* near/d in Q1.30 at a pixel, as quotient and remainder of N(p) / area2: N is the
 * barycentric numerator (plus area2/2 to round), linear in the pixel, so it steps
 * exactly. Exact depth makes the depth test's outcome a property of the triangle,
 * not of how its interpolation rounded: where two surfaces meet, the float reference
 * (which rounds the exact value the same way) agrees pixel for pixel. Plane depth
 * (TARN_DEPTH_PLANE) keeps the remainder at 0 and steps the quotient alone. */
typedef struct {
    uint32_t quotient;  /* modulo 2^32; in range at covered pixels */
    uint32_t remainder; /* in [0, den) */
} tarn_exact_value;

/* A step of an exact value: its quotient and remainder, and den - remainder, the
 * remainder at which the step carries into the quotient (taken once, not per pixel). */
typedef struct {
    uint32_t quotient, remainder, carry_at;
} tarn_exact_step_value;

typedef struct {
    tarn_divisor den; /* area2 */
    tarn_exact_step_value step_x, step_y;
    uint32_t anchor;  /* plane depth: near/d at the triangle's first pixel (box.x0, box.y0) */
    uint8_t exact;    /* 1: TARN_DEPTH_EXACT; 0: a plane, whose steps have no remainder */
} tarn_depth_plane;

/* A lit colour whose three vertices lie on one line in RGB, within
 * TARN_LIT_LINE_TOLERANCE a channel (one light over a mesh without vertex colours:
 * each channel is ambient plus light times N.L, a line in one number). Attribute 2
 * then interpolates the key channel alone, and a pixel finds each channel c from
 * its value `key` (Q8.8) as base[c] + (key - key_base) * slope[c] / 2^15: one plane
 * and one division a pixel instead of three. */
typedef struct {
    uint16_t key_base;  /* the key channel at the vertex where it is least, Q8.8 */
    uint16_t base[3];   /* each channel there, Q8.8 */
    int32_t slope[3];   /* each channel's change per unit of the key, Q1.15 (the key's 2^15) */
} tarn_lit_line;

/* Channel c (Q8.8, unclamped) a key `along` (0..65280) above the line's key_base:
 * each product, with a slope of at most 2^15, stays below 2^31. */
static inline int32_t tarn__lit_on_line(const tarn_lit_line *line, int c, int32_t along)
{
    return line->base[c] + tarn_floor_shift(along * line->slope[c] + (1 << 14), 15);
}

/* How far from the line a vertex's channel may lie, in units of Q8.8 (1/256 of a
 * level): the vertices' own rounding to Q8.8 moves them up to half a unit each. */
#define TARN_LIT_LINE_TOLERANCE 2

typedef struct {
    int count;
    int first_varying; /* attributes below it have no plane, so the pixels neither step
                          nor divide them: 0; 3 when the lit colour is constant over
                          the triangle (t_min = t_max is each channel's value); 2 when
                          it is on a line (lit_line) */
    uint8_t lit_full;  /* the lit colour is constant and 255.0 in every channel (a white
                          material in full light): a textured pixel is its texel */
    int perspective; /* tarn_perspective */
    tarn_depth_plane depth; /* near/d, Q1.30 */
    tarn_plane q;         /* normalised near/d, perspective modes */
    uint32_t q_min, q_max;
    tarn_plane premultiplied[TARN_ATTRIBUTES_MAX]; /* T * q / 2^30, or T when affine */
    uint32_t t_min[TARN_ATTRIBUTES_MAX], t_max[TARN_ATTRIBUTES_MAX];
    unsigned t_shift[TARN_ATTRIBUTES_MAX];    /* attribute = T >> t_shift (for u and v, up to
                                                 46: Q16.16 from T's 30 bits and more) */
    uint32_t u_base, v_base;             /* removed from u, v (Q16.16): a texture's whole
                                            repeats, water's least coordinates */
    /* when textured: texel column (T_u >> texel_shift[0]) & texel_mask[0], row
     * likewise from T_v, at index (row << log2_width) + column */
    uint8_t texel_shift[2];
    uint32_t texel_mask[2];
    unsigned log2_width;
    tarn_lit_line lit_line; /* with first_varying 2: the lit colour from attribute 2 (near
                               the end: the fields before it keep the short offsets Thumb
                               loads reach) */
    uint8_t q_shift;        /* q is near/d times 2^q_shift, the vertices' normalised */
} tarn_attribute_set;

/* ---- per-pixel helpers shared with setup (32-bit arithmetic only) ------------ */

static inline int32_t tarn__edge_at(const tarn_edge *e, int32_t px, int32_t py)
{
    return e->a * (px - e->x) + e->b * (py - e->y) + e->bias;
}

static inline uint32_t tarn__plane_at(const tarn_plane *p, const tarn_triangle_setup *t, int32_t i, int32_t j)
{
    return p->anchor + p->step_x * (uint32_t)(i - t->box.x0) + p->step_y * (uint32_t)(j - t->box.y0);
}

static inline void tarn__exact_step(tarn_exact_value *v, const tarn_exact_step_value *step)
{
    v->quotient += step->quotient;
    if (v->remainder >= step->carry_at) {
        v->remainder -= step->carry_at;
        v->quotient++;
    } else {
        v->remainder += step->remainder;
    }
}

/* ---- setup, once per triangle per tile ------------------------------------------ */

/* Culls by the material and orients the triangle; returns 0 when nothing draws. */
int tarn__orient_triangle(const tarn_screen_vertex in[3], uint8_t cull, unsigned subpixel_bits,
                         tarn_triangle_setup *t);
/* Pixels whose centres may be covered, before the tile clips them. */
tarn_pixel_box tarn__triangle_pixels(const tarn_triangle_setup *t);

/* What a triangle interpolates besides its lit colour. */
typedef struct {
    const tarn_texture *texture; /* textured opaque: its sizes for sampling */
    int uv;                      /* texture coordinates (textured, or water) */
    int fresnel;                 /* the fresnel term (water): after u and v, or in
                                    their place without them */
    int lit_line;                /* the lit colour may be found from one channel
                                    (tarn_lit_line), which the caller's pixels read */
} tarn_attribute_request;

void tarn__setup_attributes(const tarn_triangle_setup *t, const tarn_attribute_request *request,
                           uint8_t perspective, uint8_t depth_interpolation, tarn_attribute_set *set);
/* The depth one step on: exactly, or along the plane, whose steps have no
 * remainder. `exact` is the triangle's depth.exact, taken into a local by the
 * caller: read through the set at each pixel, it would be read again after every
 * store to the tile. */
static inline void tarn__step_depth(tarn_exact_value *v, const tarn_exact_step_value *step, int exact)
{
    if (TARN_LINK_EXACT_DEPTH && exact)
        tarn__exact_step(v, step);
    else
        v->quotient += step->quotient;
}

/* Exact depth (TARN_DEPTH_EXACT) at pixel (i, j). */
tarn_exact_value tarn__exact_depth_at(const tarn_triangle_setup *t, const tarn_depth_plane *depth, int32_t i, int32_t j);

/* Depth at pixel (i, j), to be stepped from there with step_depth. */
static inline tarn_exact_value tarn__depth_at(const tarn_triangle_setup *t, const tarn_depth_plane *depth, int32_t i, int32_t j)
{
    if (TARN_LINK_EXACT_DEPTH && depth->exact) return tarn__exact_depth_at(t, depth, i, j);
    const tarn_plane p = {depth->anchor, depth->step_x.quotient, depth->step_y.quotient};
    const tarn_exact_value v = {tarn__plane_at(&p, t, i, j), 0u};
    return v;
}

/* ---- depth codes along a run ---------------------------------------------------
 *
 * What a depth buffer holds for near/d q (Q1.30) clamped to [1, 2^30]: q itself in
 * 32 bits, tarn_depth16_encode(q) in 16; both at least 1. Over a range of q the
 * code is one shift and one add (depth_code.c): the 16-bit code's exponent stays
 * while q's leading one does. Along a row q moves a little a pixel, so a pixel
 * checks that it is still in the range the last one found, and the range is
 * found again only where q leaves it: a compare a pixel, not the clamps and a
 * leading-zero count of tarn_depth16_encode. The 32-bit code needs no range: a
 * pixel checks its clamps. */
typedef struct {
    uint32_t low, width; /* low <= q < low + width, compared as q - low < width */
    uint32_t offset;     /* the code is (q >> shift) + offset */
    uint8_t shift;
} tarn_depth_range;

/* ---- spans: the covered pixels of one row ----------------------------------------- */

/* The span perspective mode's interpolation (raster.c): exact values every
 * `span` pixels on a grid fixed to the frame, linear between. */
typedef struct {
    unsigned log2_span;
    int32_t limit;     /* the pixel after the cached span's grid cell; INT32_MIN before the first */
    int32_t start;     /* the cached span's first pixel */
    int32_t end;       /* and its far end, where the next span starts */
    int32_t t0[TARN_ATTRIBUTES_MAX], dt[TARN_ATTRIBUTES_MAX];
    int32_t t_end[TARN_ATTRIBUTES_MAX]; /* the exact values at `end` */
    int32_t length;                /* end - start of the last span filled, -1 before */
    uint32_t inverse_length;       /* 2^32 / length, tarn_recip_u32's */
} tarn_span_cache;

/* Where the row's planes start: along row j each plane is origin + step_x * i,
 * modulo 2^32 as tarn__plane_at, so a pixel takes one product a plane, not two.
 * The origins of the row below are these plus each plane's step_y, exactly (modulo
 * 2^32), so a triangle finds them by products once and steps them a row at a time.
 * The steps are copied beside the origins, once a triangle, so the loops over the
 * attributes walk arrays of words instead of the planes' 12-byte records. */
typedef struct {
    int32_t row;                               /* the row j they are of; INT32_MIN: none yet */
    uint32_t q, q_step_y;                      /* the q plane's (pixel perspective) */
    uint32_t attributes[TARN_ATTRIBUTES_MAX]; /* each premultiplied plane's */
    uint32_t step_x[TARN_ATTRIBUTES_MAX];     /* and its step along the row */
    uint32_t step_y[TARN_ATTRIBUTES_MAX];     /* and down a row */
} tarn_row_origin;

/* What one row keeps for its pixels' attributes, by the triangle's perspective
 * mode: the planes' origins (affine and pixel), or the span cache. */
typedef union {
    tarn_row_origin origin;
    tarn_span_cache span;
} tarn_row_attributes;

/* Pixels i0..i1 (inclusive, i0 <= i1) of row j, each covered by the triangle. */
typedef struct {
    tarn_tile_target *target;
    const tarn_triangle_setup *triangle;
    const tarn_attribute_set *set;
    int32_t j, i0, i1;
    tarn_exact_value depth;  /* near/d (Q1.30) at i0, stepped along the row with tarn__step_depth */
    int32_t offset;          /* index of pixel (0, j) in the target's buffers */
    uint32_t *values;        /* T values of the attributes: the constant ones set, the
                                varying ones by tarn__span_attributes */
    tarn_row_attributes row; /* the row's interpolation state */
    tarn_depth_range depth_range; /* the last pixel's, kept from row to row of the triangle */
} tarn_span;

/* A surface's near/d by its reciprocal, as the perspective divide finds it:
 * 2^62 / (near/d << lz) (tarn_recip_q30's Q2.30), with lz the leading zeros that
 * normalised near/d; recip 0 where none was found. A linear depth is one product
 * from it. */
typedef struct {
    uint32_t recip;
    unsigned lz;
} tarn_depth_reciprocal;

/* The T values of the varying attributes at pixel i of the span, into its values,
 * for a shader that needs them at some pixels only. Pixels must come in order;
 * one may be skipped in any perspective mode. In pixel perspective the pixel's q
 * is near/d to more bits, and its reciprocal, which the divide takes, is given
 * as near/d's (`depth`); the other modes find none and leave `depth` alone (NULL
 * in a build without pixel perspective). */
void tarn__span_attributes(tarn_span *span, int32_t i, tarn_depth_reciprocal *depth);

/* The 16-bit code's range around q (a width of 0 finds one at the next pixel). */
void tarn__depth_range_find(tarn_depth_range *range, uint32_t q);

/* The depth at buffer index `index` as the buffer holds it (by `depth_bits`), or 0
 * when near/d inv_depth is not closer than the stored one. */
static TARN_ALWAYS_INLINE uint32_t tarn__closer_depth(const void *depth, int depth_bits, tarn_depth_range *range,
                                                     int32_t index, uint32_t inv_depth)
{
    if (tarn__depth_is_16_bits((unsigned)depth_bits)) {
        if (TARN_UNLIKELY(inv_depth - range->low >= range->width)) tarn__depth_range_find(range, inv_depth);
        const uint32_t value = (inv_depth >> range->shift) + range->offset;
        return value > ((const uint16_t *)depth)[index] ? value : 0u;
    }
    if ((int32_t)inv_depth < 1) inv_depth = 1;
    if (inv_depth > TARN_T_ONE) inv_depth = TARN_T_ONE;
    return inv_depth > ((const uint32_t *)depth)[index] ? inv_depth : 0u;
}

/* Stored after the pixel is shaded: a water pass drawing in place reads the depth
 * beneath it first. */
static inline void tarn__store_depth(void *depth, int depth_bits, int32_t index, uint32_t value)
{
    if (tarn__depth_is_16_bits((unsigned)depth_bits))
        ((uint16_t *)depth)[index] = (uint16_t)value;
    else
        ((uint32_t *)depth)[index] = value;
}

/* The colour of pixel i of a span (at buffer index `index`, its near/d inv_depth),
 * which has passed the depth test. */
typedef uint32_t (*tarn_span_pixel)(void *ctx, tarn_span *span, int32_t i, int32_t index, uint32_t inv_depth);

/* Each pixel of the span that passes the depth test takes the colour `pixel` gives
 * it, then its depth. The loop of every span, written once and compiled into each
 * caller with its own pixel function: a constant there, so inlined, and no pixel
 * pays a call. The buffers and the depth's steps are held in locals: read through
 * the span, they would be read again after every store to the tile. */
static TARN_ALWAYS_INLINE void tarn__span_draw(tarn_span *s, tarn_span_pixel pixel, void *ctx)
{
    uint32_t *const colour = s->target->colour;
    void *const depth_buffer = s->target->depth;
    const int depth_bits = s->target->quality->depth_bits;
    const tarn_exact_step_value step = s->set->depth.step_x;
    const int exact_depth = s->set->depth.exact;
    tarn_exact_value depth = s->depth;
    tarn_depth_range range = s->depth_range; /* a copy: a store through s would reload the span's fields */
    const int32_t i1 = s->i1;
    for (int32_t i = s->i0, index = s->offset + s->i0; i <= i1; i++, index++) {
        const uint32_t closer = tarn__closer_depth(depth_buffer, depth_bits, &range, index, depth.quotient);
        if (closer != 0u) {
            colour[index] = pixel(ctx, s, i, index, depth.quotient);
            tarn__store_depth(depth_buffer, depth_bits, index, closer);
        }
        tarn__step_depth(&depth, &step, exact_depth);
    }
    s->depth_range = range;
}

/* ---- a triangle into a tile, row by row ---------------------------------------
 *
 * The material's stage drives the rows, so the rasterizer calls no shader: for an
 * opaque material raster.c itself (tarn__raster_triangle), for water core/water/.
 *
 *     tarn_triangle_rows rows;
 *     if (!tarn__triangle_enters_tile(&rows, target, vertex, cull)) return;
 *     tarn__triangle_rows_begin(&rows, &request);
 *     for (tarn_span *s; (s = tarn__triangle_next_span(&rows)) != NULL;)
 *         ...each pixel of s that passes the depth test...
 */

/* The edge values at the first pixel of a row, their steps along a row and down to
 * the next: a row starts from the row above's by adds, not from products. */
typedef struct {
    int32_t at[3];
    int32_t step_x[3], step_y[3];
} tarn_row_edges;

/* A triangle set up for one tile, and where its walk down the rows stands. */
typedef struct {
    tarn_tile_target *target;
    tarn_triangle_setup setup;
    tarn_pixel_box draw;           /* the pixels of the tile its box covers */
    uint32_t values[TARN_ATTRIBUTES_MAX];
    tarn_row_edges edges;          /* at (draw.x0, next row) */
    tarn_exact_value row_depth;    /* likewise */
    int32_t next_row;
    tarn_span span;
    tarn_attribute_set set;        /* last: the row walk's fields keep shorter offsets */
} tarn_triangle_rows;

/* Sets up the triangle for the tile; 0 when it draws no pixel there (culled, or
 * its box misses the tile or lies beyond one of its edges). */
int tarn__triangle_enters_tile(tarn_triangle_rows *rows, tarn_tile_target *target,
                              const tarn_screen_vertex vertex[3], uint8_t cull);
/* Its attribute and depth planes for `request`, and the walk at its first row. */
void tarn__triangle_rows_begin(tarn_triangle_rows *rows, const tarn_attribute_request *request);
/* The covered pixels of the next row that has any, or NULL after the last. */
tarn_span *tarn__triangle_next_span(tarn_triangle_rows *rows);

/* A triangle of an opaque material into the tile `target` (a tarn_tile_target): a
 * tarn_triangle_sink. */
void tarn__raster_triangle(void *target, const tarn_screen_vertex vertex[3], const tarn_object *object);

#endif
