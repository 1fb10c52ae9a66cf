/* raster_setup.h: the rasterizer's per-triangle setup (raster_setup.c) and the
 * shapes it hands to the per-pixel loops (raster.c). The split is the numeric
 * contract made visible: setup may use 64-bit products and divisions once per
 * triangle; nothing in raster.c may, and tests/check_core_purity.sh proves it on
 * the Cortex-M0 build. Private to core/. */
#ifndef TARN_RASTER_SETUP_H
#define TARN_RASTER_SETUP_H

#include "pipeline.h"

#define T_ONE ((uint32_t)1 << 30)
#define ATTRIBUTES_MAX 6 /* lit r, g, b; texture u, v; fresnel */
#define ATTRIBUTE_U 3
#define ATTRIBUTE_V 4
#define ATTRIBUTE_FRESNEL 5

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
    pixel_box box; /* pixels whose centres may be covered; planes are anchored at (x0, y0) */
    edge edges[3];
} triangle_setup;

/* near/d in Q1.30 at a pixel, as quotient and remainder of N(p) / area2: N is the
 * barycentric numerator (plus area2/2 to round), linear in the pixel, so it steps
 * exactly. Exact depth makes the depth test's outcome a property of the triangle,
 * not of how its interpolation rounded: where two surfaces meet, the float reference
 * (which rounds the exact value the same way) agrees pixel for pixel. Plane depth
 * (TARN_DEPTH_PLANE) keeps the remainder at 0 and steps the quotient alone. */
typedef struct {
    uint32_t quotient;  /* modulo 2^32; in range at covered pixels */
    uint32_t remainder; /* in [0, den) */
} exact_value;

/* A step of an exact value: its quotient and remainder, and den - remainder, the
 * remainder at which the step carries into the quotient (taken once, not per pixel). */
typedef struct {
    uint32_t quotient, remainder, carry_at;
} exact_step_value;

typedef struct {
    tarn_divisor den; /* area2 */
    exact_step_value step_x, step_y;
    uint32_t anchor;  /* plane depth: near/d at the triangle's first pixel (box.x0, box.y0) */
    uint8_t exact;    /* 1: TARN_DEPTH_EXACT; 0: a plane, whose steps have no remainder */
} depth_plane;

typedef struct {
    int count;
    int first_varying; /* attributes below it are constant over the triangle (0, or 3 when
                          its lit colour is): t_min = t_max is their value and they
                          have no plane, so the pixels neither step nor divide them */
    uint8_t lit_full;  /* the lit colour is constant and 255.0 in every channel (a white
                          material in full light): a textured pixel is its texel */
    int perspective; /* tarn_perspective */
    depth_plane depth; /* near/d, Q1.30 */
    plane q;         /* normalised near/d, perspective modes */
    uint32_t q_min, q_max;
    plane premultiplied[ATTRIBUTES_MAX]; /* T * q / 2^30, or T when affine */
    uint32_t t_min[ATTRIBUTES_MAX], t_max[ATTRIBUTES_MAX];
    unsigned t_shift[ATTRIBUTES_MAX];    /* attribute = T >> t_shift */
    uint32_t u_base, v_base;             /* whole texture repeats removed from u, v (Q16.16) */
    /* when textured: texel column (T_u >> texel_shift[0]) & texel_mask[0], row
     * likewise from T_v, at index (row << log2_width) + column */
    uint8_t texel_shift[2];
    uint32_t texel_mask[2];
    unsigned log2_width;
} attribute_set;

/* ---- per-pixel helpers shared with setup (32-bit arithmetic only) ------------ */

static inline int32_t pixel_centre(int32_t pixel, unsigned s)
{
    return (int32_t)((uint32_t)pixel << s) + (int32_t)(1u << (s - 1));
}

static inline int32_t edge_at(const edge *e, int32_t px, int32_t py)
{
    return e->a * (px - e->x) + e->b * (py - e->y) + e->bias;
}

static inline uint32_t plane_at(const plane *p, const triangle_setup *t, int32_t i, int32_t j)
{
    return p->anchor + p->step_x * (uint32_t)(i - t->box.x0) + p->step_y * (uint32_t)(j - t->box.y0);
}

static inline void exact_step(exact_value *v, const exact_step_value *step)
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

/* Twice the signed area of the screen triangle (negative when it faces the
 * camera), or 0 when it has none or the material culls its side. */
int64_t tarn_drawn_area2(const tarn_screen_vertex in[3], uint8_t cull);
/* Culls by the material and orients the triangle; returns 0 when nothing draws. */
int tarn_orient_triangle(const tarn_screen_vertex in[3], uint8_t cull, unsigned subpixel_bits,
                         triangle_setup *t);
/* Pixels whose centres may be covered, before the tile clips them. */
pixel_box tarn_triangle_pixels(const triangle_setup *t);

/* The subpixel box around screen positions; empty (x0 > x1) before the first. */
typedef struct {
    int32_t x0, y0, x1, y1; /* inclusive */
} subpixel_bounds;

static inline subpixel_bounds tarn_bounds_empty(void)
{
    const subpixel_bounds b = {INT32_MAX, INT32_MAX, INT32_MIN, INT32_MIN};
    return b;
}

/* Grows the bounds by a vertex: inline, since the walk takes three a triangle. */
static inline void tarn_bounds_add(subpixel_bounds *b, const tarn_screen_vertex *v)
{
    if (v->x < b->x0) b->x0 = v->x;
    if (v->x > b->x1) b->x1 = v->x;
    if (v->y < b->y0) b->y0 = v->y;
    if (v->y > b->y1) b->y1 = v->y;
}

/* Pixels whose centres lie in non-empty bounds: from ceil((min - half) / 2^s) to
 * floor((max - half) / 2^s), half a pixel being 2^(s-1) subpixels. */
pixel_box tarn_bounds_pixels(const subpixel_bounds *b, unsigned subpixel_bits);
/* What a triangle interpolates besides its lit colour. */
typedef struct {
    const tarn_texture *texture; /* textured opaque: its sizes for sampling */
    int uv;                      /* texture coordinates (textured, or water) */
    int fresnel;                 /* the fresnel term (water; needs uv) */
} attribute_request;

void tarn_setup_attributes(const triangle_setup *t, const attribute_request *request,
                           uint8_t perspective, uint8_t depth_interpolation, attribute_set *set);
/* The depth one step on: exactly, or along the plane, whose steps have no
 * remainder. `exact` is the triangle's depth.exact, taken into a local by the
 * caller: read through the set at each pixel, it would be read again after every
 * store to the tile. */
static inline void step_depth(exact_value *v, const exact_step_value *step, int exact)
{
    if (TARN_LINK_EXACT_DEPTH && exact)
        exact_step(v, step);
    else
        v->quotient += step->quotient;
}

/* Exact depth (TARN_DEPTH_EXACT) at pixel (i, j). */
exact_value tarn_exact_depth_at(const triangle_setup *t, const depth_plane *depth, int32_t i, int32_t j);

/* Depth at pixel (i, j), to be stepped from there with step_depth. */
static inline exact_value tarn_depth_at(const triangle_setup *t, const depth_plane *depth, int32_t i, int32_t j)
{
    if (TARN_LINK_EXACT_DEPTH && depth->exact) return tarn_exact_depth_at(t, depth, i, j);
    const plane p = {depth->anchor, depth->step_x.quotient, depth->step_y.quotient};
    const exact_value v = {plane_at(&p, t, i, j), 0u};
    return v;
}

#endif
