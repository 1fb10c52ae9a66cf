/* pipeline.h: the renderer's internal stages (not part of the public API).
 *
 *   view.c       per frame: camera basis, focal length, guard band, light constants
 *   vertex.c     per object: object-to-view transform; per vertex: position, shading
 *   clip.c       polygon clipping against near, far and the guard band, in view space
 *   project.c    view space to snapped screen space
 *   triangles.c  walks the scene and hands each drawable screen triangle on
 *   raster.c     edge functions, attribute planes, depth test and shading in a tile
 *   frame.c      configuration checks, tile memory and the tile loop */
#ifndef TARN_PIPELINE_H
#define TARN_PIPELINE_H

#include "tarn_render.h"

/* Everything about the camera and light that is fixed for a frame. */
typedef struct {
    int32_t basis[3][3];     /* rows: right, up, forward; Q1.30 unit vectors */
    tarn_vec3 eye;           /* Q16.16 world */
    int32_t focal_q12;       /* focal length in pixels, Q20.12 */
    tarn_q16 near, far;      /* Q16.16 view depth */
    /* focal_q12 and near as mantissa * 2^-shift (top bit set), for the projection */
    uint32_t focal_mantissa, near_mantissa;
    unsigned focal_shift, near_shift;
    int32_t half_extent_q12[2]; /* width/2 + guard, height/2 + guard, pixels Q20.12 */
    int16_t guard_pixels;    /* tarn_guard_band_pixels: below 2^15 */
    uint16_t width, height;
    /* at most half_extent / focal in Q8, and at most 511: |x| <= (d >> 8) * this
     * puts a vertex inside both guard planes of its axis (tarn_clip_outcode) */
    uint16_t guard_slope_q8[2];
    uint8_t subpixel_bits;
    uint32_t light_q16[3];   /* directional light colour / 255 per channel, Q0.16 */
    uint32_t ambient_q16[3]; /* ambient colour / 255 per channel, Q0.16 */
    tarn_vec3 light_dir;     /* Q16.16 unit, toward the light */
    uint8_t static_vertices; /* the scene's static vertices apply (tarn_static_view_applies) */
    uint8_t static_screen;   /* and so do their screen positions: the frame is theirs */
} tarn_view;

/* A vertex in view space with its shading inputs, before projection. */
typedef struct {
    tarn_q16 x, y, d;  /* view space, Q16.16: right, up, depth along the view axis */
    tarn_uv uv;        /* Q16.16 */
    int32_t lit[3];    /* lit colour, Q8.8 per channel */
    int32_t fresnel;   /* (1 - n.v)^2, Q1.15; water materials only */
} tarn_view_vertex;

/* Per-object constants for one frame. */
typedef struct {
    /* to_view (basis * scale * rotation, `to_view_frac_bits` fraction bits, entries
     * within +-2^29) as high * 2^16 + low, for 32-bit products in tarn_vertex_position */
    uint16_t to_view_low[3][3];
    int16_t to_view_high[3][3];
    /* per row, what tarn_vertex_position's sum starts from (the object's origin in view
     * space, the rounding half and the offsets of its unsigned forms), in 16-bit columns */
    uint16_t row_start_low[3];
    uint32_t row_start_middle[3], row_start_high[3];
    unsigned to_view_frac_bits;
    tarn_q16 light_dir[3];  /* light direction in object space, Q16.16 unit */
    uint32_t tint_q16[3];   /* material colour / 255 per channel, Q0.16 */
    int unlit;              /* the material ignores the light */
    int32_t normal_to_view[3][3]; /* basis * rotation, Q1.30: normals into view space */
    int fresnel;            /* the material is water with the fresnel effect: vertices
                               carry the fresnel term (0 otherwise; nothing reads it) */
} tarn_object_xform;

#define TARN_CLIP_POLYGON_MAX 9 /* a triangle cut by six planes has at most 3 + 6 corners */

void tarn_view_setup(const tarn_scene *scene, const tarn_frame_config *config, tarn_view *view);
/* 1 when the scene has a static view and its camera and light are that view's. */
int tarn_static_view_applies(const tarn_scene *scene);
/* 1 when moreover the frame is the static view's: its screen positions and bins hold. */
int tarn_static_screen_applies(const tarn_scene *scene, const tarn_frame_config *config);

/* The object's transform into view space and, unless its static vertices apply
 * (they come lit), its lighting constants. */
void tarn_object_xform_setup(const tarn_view *view, const tarn_object *object,
                             tarn_object_xform *xform);
void tarn_vertex_position(const tarn_object_xform *xform, const tarn_vec3 *object_pos,
                          tarn_view_vertex *out);
void tarn_vertex_shade(const tarn_view *view, const tarn_object_xform *xform,
                       const tarn_mesh *mesh, uint16_t index, tarn_view_vertex *out);
/* The vector with each component cut to [-2, 2] (Q16.16): unit vectors unchanged. */
tarn_vec3 tarn_unit_vector_bounded(const tarn_vec3 *v);
/* The vertex's texture coordinates, (0, 0) for a mesh without them. */
tarn_uv tarn_vertex_uv(const tarn_mesh *mesh, uint16_t index);

/* Bit i set: the vertex is outside clip plane i (near, far, left, right, top, bottom). */
unsigned tarn_clip_outcode(const tarn_view *view, const tarn_view_vertex *v);
/* Clips the convex polygon in place against the planes in `planes` (outcode bits);
 * returns the new vertex count (0 when nothing is left). */
int tarn_clip_polygon(const tarn_view *view, unsigned planes,
                      tarn_view_vertex polygon[TARN_CLIP_POLYGON_MAX], int count);

/* Called for each screen triangle, in drawing order. */
typedef void (*tarn_triangle_sink)(void *ctx, const tarn_screen_vertex vertex[3],
                                   const tarn_object *object);

/* Clips the triangle (view vertices with their attributes) against the planes in
 * `planes` and hands what is left to the sink as a fan of screen triangles. */
void tarn_clip_and_emit(const tarn_view *view, unsigned planes, const tarn_view_vertex v[3],
                        const tarn_object *object, tarn_triangle_sink sink, void *ctx);

/* Screen position and inverse depth; the attributes apart, as they are needed
 * only once a triangle is known to reach the tile. */
void tarn_project_position(const tarn_view *view, const tarn_view_vertex *in, tarn_screen_vertex *out);
void tarn_project_attributes(const tarn_view_vertex *in, tarn_screen_vertex *out);

typedef struct {
    int32_t x0, y0, x1, y1; /* pixel rectangle [x0, x1) x [y0, y1) */
} tarn_pixel_rect;

typedef enum {
    TARN_WALK_OPAQUE, /* objects whose material has no water block */
    TARN_WALK_WATER   /* water objects only */
} tarn_walk_pass;


/* Walks the triangles of the pass's objects in scene order; triangles whose screen
 * bounds miss `only_rect` (when not NULL) are skipped as early as possible, whole
 * clusters first: by their bins when `bins` (this frame's, tarn_bin_clusters) is
 * not NULL, else by their bounding spheres. */
void tarn_walk_triangles(const tarn_scene *scene, const tarn_view *view, tarn_walk_pass pass,
                         const tarn_cluster_bin *bins, const tarn_pixel_rect *only_rect,
                         tarn_triangle_sink sink, void *ctx);

struct tarn_water_context; /* water.h */

/* What a pass draws into: the pixels it may draw, and buffers whose index 0 holds
 * frame pixel (origin_x, origin_y). */
typedef struct {
    tarn_pixel_rect rect;
    int32_t origin_x, origin_y;
    uint32_t *colour;   /* 0x00RRGGBB, `stride` pixels per row */
    void *depth;        /* uint16_t or uint32_t per pixel by depth_bits, near/d */
    int32_t stride;
    const tarn_quality *quality;
    uint8_t log2_span;  /* log2 of the quality's perspective_span, taken once a frame */
    /* the water pass only: the frame, and the water shading context (its buffers
     * point at the opaque pass's colour and depth) */
    const tarn_view *view;
    const tarn_frame_config *config;
    struct tarn_water_context *water;
    uint32_t water_mark;    /* TARN_WATER_MARK when the water pass draws over the
                               opaque buffers themselves, else 0 */
    uint32_t water_overlap; /* non-zero once it wrote over a pixel it had written */
} tarn_tile_target;

/* A bit above 0x00RRGGBB that an in-place water pass sets on the pixels it writes;
 * the frame clears it before the sink sees the tile. */
#define TARN_WATER_MARK 0x01000000u

void tarn_raster_triangle(tarn_tile_target *tile, const tarn_screen_vertex vertex[3],
                          const tarn_object *object);

/* The scene's backdrop (backdrop.c) when it applies to the frame (the static
 * view's screen, the quality it was drawn at), else NULL; whether its arrays hold
 * what it says for the static view's frame and the scene's objects. */
const tarn_backdrop *tarn_backdrop_for(const tarn_scene *scene, const tarn_frame_config *config);
int tarn_backdrop_valid(const tarn_backdrop *backdrop, const tarn_scene *scene);
/* The target's rect from the backdrop of a frame `frame_width` pixels wide, as the
 * opaque pass would draw it; the colours alone with depth_bytes 0. */
void tarn_backdrop_fill(const tarn_backdrop *backdrop, uint16_t frame_width, tarn_tile_target *target,
                        size_t depth_bytes);
/* A still-water backdrop's place in the foam band of frame pixel (i, j), Q0.16;
 * 65536, beyond the band, where it keeps none. */
uint32_t tarn_backdrop_foam_band(const tarn_backdrop *backdrop, int32_t i, int32_t j);

/* Validates the scene's arrays so the walk never reads past them. */
tarn_status tarn_scene_check(const tarn_scene *scene);
/* TARN_ERR_SCENE when a water material's refraction reaches past the widest apron,
 * or when the scene has a backdrop that does not apply to the frame. */
tarn_status tarn_scene_check_reach(const tarn_scene *scene, const tarn_frame_config *config);
/* Validates a frame config; TARN_OK or TARN_ERR_CONFIG. */
tarn_status tarn_config_check(const tarn_frame_config *config);

#endif
