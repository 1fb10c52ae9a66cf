/* geometry_internal.h: the second stage of a frame (core/geometry/), internal to
 * core/: from the scene's objects to snapped screen triangles.
 *
 *   view.c          per frame: camera basis, focal length, guard band, light constants
 *   vertex.c        per object: object-to-view transform; per vertex: position, shading
 *   clip.c          polygon clipping against near, far and the guard band, in view space
 *   project.c       view space to snapped screen space; screen bounds to pixels
 *   vertex_cache.c  each vertex transformed, projected and lit about once a walk
 *                   (vertex_cache_internal.h)
 *   vertex_pass.c   or every vertex once a frame, as a baked static view keeps them
 *
 * It takes the scene and the frame config (checked by core/scene/) and hands on
 * tarn_screen_vertex triangles (tarn_render.h) to a tarn_triangle_sink. Its work
 * is per vertex and per clipped triangle, none per pixel. */
#ifndef TARN_GEOMETRY_INTERNAL_H
#define TARN_GEOMETRY_INTERNAL_H

#include "scene/scene_internal.h"

/* Everything about the camera and light that is fixed for a frame. */
typedef struct {
    int32_t basis[3][3];     /* rows: right, up, forward; Q1.30 unit vectors */
    tarn_vec3 eye;           /* Q16.16 world */
    int32_t focal_q12;       /* focal length in pixels, Q20.12 */
    /* 1 / focal length = inv_focal_mantissa * 2^-inv_focal_shift per pixel, to 2^-31
     * of itself (Q20.12 rounds a 240-row focal length by 2^-21 of itself), for a
     * flat water plane's rays (core/water/water_plane.c) */
    uint32_t inv_focal_mantissa;
    unsigned inv_focal_shift;
    tarn_q16 near, far;      /* Q16.16 view depth */
    /* focal_q12 and near as mantissa * 2^-shift (top bit set), for the projection */
    uint32_t focal_mantissa, near_mantissa;
    unsigned focal_shift, near_shift;
    int32_t half_extent_q12[2]; /* width/2 + guard, height/2 + guard, pixels Q20.12 */
    int16_t guard_pixels;    /* tarn_guard_band_pixels: below 2^15 */
    uint16_t width, height;
    /* at most half_extent / focal in Q8, and at most 511: |x| <= (d >> 8) * this
     * puts a vertex inside both guard planes of its axis (tarn__clip_outcode) */
    uint16_t guard_slope_q8[2];
    uint8_t subpixel_bits;
    uint32_t light_q16[3];   /* directional light colour / 255 per channel, Q0.16 */
    uint32_t ambient_q16[3]; /* ambient colour / 255 per channel, Q0.16 */
    tarn_vec3 light_dir;     /* Q16.16 unit, toward the light */
    uint8_t static_vertices; /* the scene's static vertices apply (tarn__static_view_applies) */
    uint8_t static_screen;   /* and so do their screen positions: the frame is theirs */
} tarn_view;

/* A vertex in view space with its shading inputs, before projection. The clipper
 * keeps nine on the stack, under every triangle its sink draws: 40 bytes each, the
 * colour and fresnel in 16 bits (their ranges). */
typedef struct {
    tarn_q16 x, y, d;  /* view space, Q16.16: right, up, depth along the view axis */
    /* the 16 bits below x, y and d: a clipped vertex's own, 0 for a mesh's. A vertex
     * cut at a near plane of 0.002 projects 1/500 of a unit from the eye, where the
     * last bit of Q16.16 is 0.4 pixels of a 128-pixel frame */
    uint16_t x_low, y_low, d_low;
    uint16_t uv_low[2]; /* the 16 bits below u and v, as x_low: a clipped vertex's own */
    uint16_t lit[3];   /* lit colour, Q8.8 per channel, at most 65280 */
    uint16_t fresnel;  /* (1 - n.v)^2, Q1.15, at most 32768; water materials only */
    tarn_uv uv;        /* Q16.16 */
} tarn_view_vertex;

/* Per-object constants for one frame. */
typedef struct {
    /* to_view (basis * scale * rotation, `to_view_frac_bits` fraction bits, entries
     * within +-2^29) as high * 2^16 + low, for the 32-bit products of
     * tarn__vertex_position_by_halves */
    uint16_t to_view_low[3][3];
    int16_t to_view_high[3][3];
    /* per row, what tarn__vertex_position_by_halves's sum starts from (the object's
     * origin in view space, the rounding half and the offsets of its unsigned forms),
     * in 16-bit columns */
    uint16_t row_start_low[3];
    uint32_t row_start_middle[3], row_start_high[3];
#if TARN_NATIVE_MUL_HI
    /* the same two for a core with 32x32 -> 64-bit products: to_view's entries, and
     * the origin times 2^to_view_frac_bits plus the rounding half */
    int32_t to_view[3][3];
    int64_t row_start[3];
#endif
    unsigned to_view_frac_bits;
    tarn_q16 light_dir[3];  /* light direction in object space, Q16.16 unit */
    uint32_t tint_q16[3];   /* material colour / 255 per channel, Q0.16 */
    int unlit;              /* the material ignores the light */
    int32_t normal_to_view[3][3]; /* basis * rotation, Q1.30: normals into view space */
    int fresnel;            /* the material is water with the fresnel effect: vertices
                               carry the fresnel term (0 otherwise; nothing reads it) */
} tarn_object_xform;

#define TARN_CLIP_POLYGON_MAX 9 /* a triangle cut by six planes has at most 3 + 6 corners */

void tarn__view_setup(const tarn_scene *scene, const tarn_frame_config *config, tarn_view *view);

/* The object's transform into view space and, unless its static vertices apply
 * (they come lit), its lighting constants. */
void tarn__object_xform_setup(const tarn_view *view, const tarn_object *object,
                             tarn_object_xform *xform);
/* The vertex's view position (x, y, d; their low bits 0): to_view times the object
 * position plus the origin, rounded to Q16.16 and saturated. A core with a 64-bit
 * product (TARN_NATIVE_MUL_HI) takes it whole; the Cortex-M0 and RISC-V without M
 * by tarn__vertex_position_by_halves, the same numbers in 16x16-bit products, which
 * every target compiles for the test that holds the two together. */
void tarn__vertex_position_by_halves(const tarn_object_xform *xform, const tarn_vec3 *object_pos,
                                     tarn_view_vertex *out);
#if TARN_NATIVE_MUL_HI
void tarn__vertex_position(const tarn_object_xform *xform, const tarn_vec3 *object_pos,
                          tarn_view_vertex *out);
#else
#define tarn__vertex_position tarn__vertex_position_by_halves
#endif
void tarn__vertex_shade(const tarn_view *view, const tarn_object_xform *xform,
                       const tarn_mesh *mesh, uint16_t index, tarn_view_vertex *out);
/* The vector with each component cut to [-2, 2] (Q16.16): unit vectors unchanged. */
tarn_vec3 tarn__unit_vector_bounded(const tarn_vec3 *v);
/* The vertex's texture coordinates, (0, 0) for a mesh without them. */
tarn_uv tarn__vertex_uv(const tarn_mesh *mesh, uint16_t index);

/* Bit i set: the vertex is outside clip plane i (near, far, left, right, top, bottom). */
unsigned tarn__clip_outcode(const tarn_view *view, const tarn_view_vertex *v);
/* Clips the convex polygon in place against the planes in `planes` (outcode bits);
 * returns the new vertex count (0 when nothing is left). */
int tarn__clip_polygon(const tarn_view *view, unsigned planes,
                      tarn_view_vertex polygon[TARN_CLIP_POLYGON_MAX], int count);

/* Called for each screen triangle, in drawing order. */
typedef void (*tarn_triangle_sink)(void *ctx, const tarn_screen_vertex vertex[3],
                                   const tarn_object *object);

/* Clips the triangle (view vertices with their attributes) against the planes in
 * `planes` and hands what is left to the sink as a fan of screen triangles. */
void tarn__clip_and_emit(const tarn_view *view, unsigned planes, const tarn_view_vertex v[3],
                        const tarn_object *object, tarn_triangle_sink sink, void *ctx);

/* Screen position and inverse depth; the attributes apart, as they are needed
 * only once a triangle is known to reach the tile. */
void tarn__project_position(const tarn_view *view, const tarn_view_vertex *in, tarn_screen_vertex *out);
void tarn__project_attributes(const tarn_view_vertex *in, tarn_screen_vertex *out);

/* The subpixel position of pixel `pixel`'s centre: pixels are sampled at their
 * centres (tarn_render.h). */
static inline int32_t tarn__pixel_centre(int32_t pixel, unsigned s)
{
    return (int32_t)((uint32_t)pixel << s) + (int32_t)(1u << (s - 1));
}

/* Twice the signed area of the screen triangle (negative when it faces the
 * camera), or 0 when it has none or the material culls its side. */
int64_t tarn__drawn_area2(const tarn_screen_vertex in[3], uint8_t cull);

/* Pixels whose centres may be covered, inclusive: [x0, x1] x [y0, y1]. */
typedef struct {
    int32_t x0, y0, x1, y1;
} tarn_pixel_box;

/* The subpixel box around screen positions; empty (x0 > x1) before the first. */
typedef struct {
    int32_t x0, y0, x1, y1; /* inclusive */
} tarn_subpixel_bounds;

static inline tarn_subpixel_bounds tarn__bounds_empty(void)
{
    const tarn_subpixel_bounds b = {INT32_MAX, INT32_MAX, INT32_MIN, INT32_MIN};
    return b;
}

/* Grows the bounds by a vertex: inline, since the walk takes three a triangle. */
static inline void tarn__bounds_add(tarn_subpixel_bounds *b, const tarn_screen_vertex *v)
{
    if (v->x < b->x0) b->x0 = v->x;
    if (v->x > b->x1) b->x1 = v->x;
    if (v->y < b->y0) b->y0 = v->y;
    if (v->y > b->y1) b->y1 = v->y;
}

/* Pixels whose centres lie in non-empty bounds: from ceil((min - half) / 2^s) to
 * floor((max - half) / 2^s), half a pixel being 2^(s-1) subpixels. */
tarn_pixel_box tarn__bounds_pixels(const tarn_subpixel_bounds *b, unsigned subpixel_bits);

/* ---- the vertex pass (vertex_pass.c) ------------------------------------------ */

/* Vertex `index` of the mesh as a frame computes it: its projection (inside every
 * clip plane only) and its shading, and its view position into *position (x, y
 * and depth in z) unless that is NULL. */
tarn_static_vertex tarn__static_vertex_of(const tarn_view *view, const tarn_object_xform *xform,
                                          const tarn_mesh *mesh, uint16_t index, tarn_vec3 *position);
/* The vertices of every object's mesh, summed. */
uint32_t tarn__scene_vertex_count(const tarn_scene *scene);
/* Every vertex of the scene, whose objects are `objects` (its own, writable), as
 * the frame's camera sees it, into `vertices` (tarn__scene_vertex_count of them),
 * and their view positions into `positions` unless that is NULL; each object's
 * static_vertices then name its own, and the scene's static view is `made`, for
 * this frame's size and precision, with no bins and those positions. Every mesh
 * must have its positions. */
void tarn__vertex_pass(tarn_scene *scene, tarn_object *objects, const tarn_frame_config *config,
                       tarn_static_view *made, tarn_static_vertex *vertices, tarn_vec3 *positions);

#endif
