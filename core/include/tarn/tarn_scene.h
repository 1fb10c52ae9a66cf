/* tarn_scene.h: a scene as plain const C data.
 *
 * The host builds these structs from a scene file; firmware holds them as const
 * data baked into flash. Nothing here owns memory: every pointer refers to arrays
 * the caller keeps alive for as long as the scene is rendered.
 *
 * Conventions: right-handed world, +y up. The camera looks from `position` toward
 * `target`. Front faces wind counter-clockwise seen from the front. Texture
 * coordinate (0,0) is the top-left corner of the texture's first row, 1.0 is one
 * texture width or height, and coordinates wrap. Colours are 0xRRGGBB. */
#ifndef TARN_SCENE_H
#define TARN_SCENE_H

#include <stdint.h>
#include "tarn_fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    tarn_q16 x, y, z; /* Q16.16 */
} tarn_vec3;

typedef struct {
    tarn_q16 u, v; /* Q16.16, 1.0 = one texture width (height) */
} tarn_uv;

#define TARN_TEXTURE_SIZE_MAX 1024u

typedef struct {
    uint16_t width, height; /* texels; each a power of two, 1..TARN_TEXTURE_SIZE_MAX */
    const uint8_t *rgb;     /* width*height texels, rows top to bottom: 3 bytes each,
                               R then G then B, or with red_only 1 byte, the red */
    uint8_t red_only;       /* 0: R G B texels; 1: red alone, for a water's foam map,
                               which reads no other channel (a third of the bytes);
                               any other texture with it is refused */
} tarn_texture;

typedef enum {
    TARN_CULL_BACK = 0, /* draw front faces only (the default) */
    TARN_CULL_NONE = 1, /* draw both sides */
    TARN_CULL_FRONT = 2 /* draw back faces only */
} tarn_cull;

typedef struct tarn_water tarn_water;           /* tarn_water.h */
typedef struct tarn_underwater tarn_underwater; /* tarn_water.h */
typedef struct tarn_camera_path tarn_camera_path;     /* tarn_motion.h */
typedef struct tarn_object_motion tarn_object_motion; /* tarn_motion.h */
typedef struct tarn_light_motion tarn_light_motion;   /* tarn_motion.h */

typedef struct {
    uint32_t colour_rgb;          /* tint multiplying the texture or vertex colours */
    const tarn_texture *texture;  /* NULL: untextured */
    uint8_t cull;                 /* tarn_cull */
    uint8_t unlit;                /* 1: ignore the light, colour is used as is */
    const tarn_water *water;      /* NULL: opaque; else drawn after the opaque scene */
} tarn_material;

#define TARN_MESH_VERTICES_MAX 65535u
#define TARN_MESH_TRIANGLES_MAX 65535u

/* A run of a mesh's triangles that lie close together, and a sphere holding all
 * their vertices. For each tile the renderer tests the sphere against the tile's
 * slice of the view and skips the whole run when it cannot touch it: the walk stays
 * free of RAM, and most of a large mesh is never transformed for a given tile. */
typedef struct {
    tarn_vec3 centre;        /* object space, Q16.16 */
    tarn_q16 radius;         /* object space, Q16.16; every vertex of the run within it */
    uint16_t first_triangle; /* the run is triangles [first, first + count) */
    uint16_t triangle_count;
} tarn_cluster;

/* A flat mesh whose texture coordinates are an affine map of its plane: every
 * vertex p (object space) lies on normal . p = offset and takes the coordinates
 * uv = uv_origin + uv_gradient . p. The host's loader finds it for each flat mesh
 * (tarn_mesh.plane). Water drawn with it takes its texture coordinates at each
 * pixel where the ray through the pixel's centre meets the plane, as the float
 * reference does, instead of interpolating them from the triangles' snapped
 * corners; which pixels it covers stays the triangles' (core/water/water_plane.c). */
typedef struct {
    int32_t normal[3];         /* Q1.30 unit vector */
    tarn_q16 offset;           /* Q16.16 object units */
    tarn_uv uv_origin;         /* Q16.16: the map at the object's origin */
    int32_t uv_gradient[2][3]; /* u's and v's change per object unit, in units of
                                  2^-uv_gradient_bits repeats; each below 2^24 */
    uint8_t uv_gradient_bits;  /* 0..TARN_UV_PLANE_GRADIENT_BITS_MAX */
} tarn_uv_plane;

#define TARN_UV_PLANE_GRADIENT_BITS_MAX 46u

typedef struct {
    const tarn_vec3 *positions; /* object space, Q16.16; with normals, NULL only when every
                                   object drawing the mesh has static vertices that apply */
    const tarn_vec3 *normals;   /* unit length, Q16.16, object space */
    const tarn_uv *uvs;         /* NULL if the mesh has no texture coordinates */
    const uint32_t *colours;    /* 0xRRGGBB per vertex, NULL for white */
    const uint16_t *indices;    /* 3 per triangle */
    uint16_t vertex_count;
    uint16_t triangle_count;
    const tarn_cluster *clusters; /* runs covering every triangle once, in order; NULL:
                                     one run of all triangles that is never skipped */
    uint16_t cluster_count;
    const tarn_uv_plane *plane; /* NULL unless the mesh is flat, its texture
                                     coordinates an affine map of its plane (above) */
} tarn_mesh;

/* The six clip planes of a frame (near, far, and the guard band's four sides), a
 * bit each: what a vertex that was not projected lies outside. */
#define TARN_CLIP_PLANE_BITS 0x3Fu

/* A vertex as the scene's fixed camera sees it: exactly what a frame would compute
 * from the object's mesh, transform and material, the camera and the light (tarn
 * bake writes them, docs/bake.md "Static view"). A frame then neither transforms,
 * lights nor (for the frame they were made for) projects the object's vertices.
 * 16 bytes: a triangle with a vertex outside a clip plane, the only one that needs
 * the vertex's view position, finds it in the static view's positions or, without
 * them, from its mesh. */
typedef struct {
    uint32_t inv_depth;         /* near/d, Q1.30 (1..2^30), for a vertex inside every clip
                                   plane of the static view's frame; 0: not projected */
    int16_t screen_x, screen_y; /* subpixels of that frame, inside its guard band; for a
                                   vertex not projected, screen_x holds the clip planes
                                   (TARN_CLIP_PLANE_BITS) it lies outside and screen_y 0:
                                   where a build links the vertex pass, a triangle whose
                                   three vertices lie outside one plane is dropped
                                   without their view positions (0 claims none, and
                                   such a triangle is clipped as any other) */
    uint16_t lit[3];            /* lit colour, Q8.8 per channel, at most 65280 */
    uint16_t fresnel;           /* (1 - n.v)^2, Q1.15, at most 32768; 0 but on water */
} tarn_static_vertex;

/* World = position + scale * rotation * object. The rotation is orthonormal, so
 * normals transform by the rotation alone. With a motion (tarn_motion.h) the
 * position and rotation are the object's at time 0 of its bob and spin. */
typedef struct {
    const tarn_mesh *mesh;
    const tarn_material *material;
    tarn_vec3 position;     /* Q16.16 world units */
    tarn_q16 rotation[3][3]; /* Q16.16 rows of an orthonormal matrix */
    tarn_q16 scale;         /* Q16.16, > 0 */
    const tarn_static_vertex *static_vertices; /* NULL, or one per mesh vertex, for the
                                                  scene's static_view; the object must
                                                  then not move */
    const tarn_object_motion *motion; /* NULL: the object stays where it is */
} tarn_object;

typedef struct {
    tarn_vec3 position;     /* Q16.16 world */
    tarn_vec3 target;       /* Q16.16 world, distinct from position */
    tarn_q16 fov_y_degrees; /* Q16.16, vertical field of view, 1..179 */
    tarn_q16 near;          /* Q16.16 world units, > 0 */
    tarn_q16 far;           /* Q16.16 world units, > near; farther geometry is not drawn */
} tarn_camera;

typedef struct {
    tarn_vec3 direction;   /* Q16.16 unit vector pointing from the scene toward the light */
    uint32_t colour_rgb;   /* directional light colour */
    uint32_t ambient_rgb;  /* ambient light colour */
} tarn_light;

/* Where on screen a cluster draws: cells [x0, x1] x [y0, y1] of 4x4 pixels,
 * inclusive; x0 > x1 when it draws nothing, and 0, 0, 255, 255 when it is cut by the
 * near plane (its bounding sphere decides). */
typedef struct tarn_cluster_bin {
    uint8_t x0, y0, x1, y1;
} tarn_cluster_bin;

/* A run of one row's pixels whose depth a backdrop keeps: [x0, x1), stored at
 * depth[first .. first + x1 - x0). */
typedef struct {
    uint16_t x0, x1;
    uint32_t first;
} tarn_backdrop_span;

#define TARN_BACKDROP_COLOURS_MAX 65536u

/* Still water. Under a fixed camera, all the water does but its moving terms
 * (TARN_WATER_MOVING in tarn_water.h: the normal maps' highlights, the foam lines,
 * the sparkles) is the same in every frame: the fog, absorption, depth colour and
 * fresnel of steps 3 to 7, over an opaque background that does not move either. A
 * still-water backdrop holds those pixels drawn (tarn bake --backdrop still), each
 * channel rounded to 0..255, with the water object drawn there (1 + its index in
 * the scene's objects, in the bits of TARN_BACKDROP_STILL_OBJECT) and, where foam
 * can show, TARN_BACKDROP_STILL_FOAM; it keeps their place in the foam band. Its
 * water objects are flat, and it holds each one's surface as the frame sees it
 * (tarn_still_plane). A frame draws no water triangle: it walks each tile's marked
 * pixels and finds only the moving terms there, from texture coordinates the plane
 * gives (a block's highlight once, with the quality's water_block 2 or 4). Its
 * images differ from the scene drawn whole by the rounding of the still terms, by
 * the texture coordinates (exact on the plane, where triangles interpolate them)
 * and, with water blocks, by the highlights the blocks share; docs/bake.md gives
 * the error. Its frames take the quality's water_coordinates TARN_WATER_UV_PLANE,
 * and no other. A refracted sample (with the quality's apron) is read from the
 * picture itself wherever it lands: on the water, the still colour there with its
 * fog moved from that pixel's surface to the refracting one's (its other still
 * terms are that pixel's); beside the water (on the bank behind it, on an object
 * standing in it), the opaque colour with the refracting pixel's still terms over
 * it, but for the fresnel raise of alpha; and the pixel's own where it lands on
 * another object's water or in front of it. It applies to a frame without the
 * underwater view. */
#define TARN_BACKDROP_STILL_OBJECT 0x7E000000u
#define TARN_BACKDROP_STILL_SHIFT 25u
#define TARN_BACKDROP_STILL_OBJECTS_MAX 63u
#define TARN_BACKDROP_STILL_FOAM 0x80000000u
/* A still backdrop keeps a depth of water, or a place in the foam band, in Q2.14
 * (tarn_backdrop's depth): Q16.16 shifted down by this. */
#define TARN_BACKDROP_KEPT_SHIFT 2u

/* A flat water object's surface as the frame of a still-water backdrop sees it:
 * three affine functions of the pixel (i, j), f = f[0] + f[1] * i + f[2] * j taken
 * modulo 2^32, which hold at the pixel's centre. */
typedef struct {
    int32_t depth[3];  /* near/d, Q1.30 (2^30 on the near plane), as the depth buffer */
    int32_t u[3], v[3]; /* u * near/d and v * near/d: the texture coordinates (Q16.16,
                           modulo 2^16 repeats) are u = u_plane * 2^uv_shift / depth */
    uint8_t uv_shift;   /* 0..31 */
    uint16_t lit[3];    /* Q8.8 a channel (255.0 = 65280): step 7's lit surface colour,
                           the material's colour times its light, as the water's
                           vertices have it (their mean, where they differ) */
} tarn_still_plane;

/* The scene's opaque objects as the static view's frame draws them, drawn once by
 * tarn bake (docs/bake.md, "Backdrop"): every pixel's colour, and its depth in each
 * row's span of pixels where water draws or samples. A frame starts each tile from
 * it instead of drawing the opaque pass (the scene's opaque objects, if it still
 * lists them, are not drawn); outside the spans the depth reads as in front of
 * every water pixel, since none draws there. It stands for a quality's opaque
 * image, so it applies only to frames the static view's screen applies to with
 * these quality settings (tarn_quality); a frame it does not apply to is refused
 * (TARN_ERR_SCENE), the objects it replaced being gone. */
typedef struct {
    uint8_t recip_newton_steps, perspective, perspective_span; /* tarn_quality's */
    uint8_t depth_bits, depth_interpolation;
    uint8_t still_water;       /* 0: the opaque objects alone. 1: the water's still
                                  terms too (above, "Still water") */
    /* with still_water, the rest of tarn_quality that shapes the still terms */
    uint8_t water_block, fog_argument_bits, exp2_interpolate;
    uint16_t exp2_entries;
    const tarn_still_plane *planes; /* with still_water: one per object of the scene,
                                       read for its water objects */
    uint8_t index_bits;        /* 1..16: bits of a palette index */
    const uint32_t *palette;   /* 0xRRGGBB colours; with still_water, a water pixel's
                                  also holds its marks (TARN_BACKDROP_STILL_*), and
                                  they are in ascending order */
    uint32_t palette_count;    /* 1..2^index_bits: an index past the last colour
                                  reads the last (tarn bake writes none) */
    const uint16_t *colour;    /* a palette index per pixel, rows top to bottom: pixel
                                  (i, j)'s index_bits bits start at bit
                                  (j * width + i) * index_bits, counted from bit 0 of
                                  colour[0] up through each uint16_t */
    const uint16_t *row_spans; /* height + 1 entries: row j's spans, left to right and
                                  apart, are spans[row_spans[j] .. row_spans[j + 1]) */
    const tarn_backdrop_span *spans;
    uint32_t span_count;       /* entries of spans, row_spans[height] */
    const void *depth;         /* near/d of the kept pixels, as the depth buffer holds
                                  it by depth_bits (a uint16_t tarn_depth16 code or a
                                  uint32_t Q1.30), 0 where no triangle drew, all ones
                                  where the backdrop keeps none (between close spans);
                                  with still_water, whatever depth_bits, a uint16_t:
                                  where the frame refracts (an apron) and the water's
                                  foam band, if any, is less than one unit deep, the
                                  depth of water beneath, db - ds in Q2.14 world
                                  units, where that is less than one unit, or less
                                  than four where a refracted sample may land within
                                  the foam band of the water it moved from; else the
                                  place in the foam band (step 9's f, Q2.14) where
                                  that is less than 1, or less than 4 where a sample
                                  may land within the band; at a pixel no water draws
                                  (unmarked) where a refracted sample may land behind
                                  its water, the opaque near/d as a tarn_depth16
                                  code */
    uint32_t depth_count;      /* entries of depth */
} tarn_backdrop;

/* What a scene's static vertices were computed for. They apply while the scene's
 * camera and light are these, and their screen positions and bins while the frame
 * also has this size and subpixel precision; otherwise each frame computes what they
 * hold (and an object whose mesh has no positions cannot be drawn: TARN_ERR_SCENE). */
typedef struct {
    tarn_camera camera;
    tarn_light light;
    uint16_t width, height; /* pixels, 1..TARN_FRAME_SIZE_MAX */
    uint8_t subpixel_bits;  /* TARN_SUBPIXEL_BITS_MIN..MAX */
    const tarn_cluster_bin *bins; /* NULL, or every cluster's bin in this frame, the
                                     objects' in scene order (one for a mesh without
                                     clusters): a frame with cluster bins reads these
                                     instead of finding them, and needs no memory for them */
    const tarn_backdrop *backdrop; /* NULL, or the scene's opaque objects already drawn */
    const tarn_vec3 *positions; /* NULL, or every object's vertices' view positions
                                   (Q16.16 right, up and depth in x, y, z), the objects'
                                   in scene order, one per mesh vertex: read where a
                                   triangle is clipped; NULL: found from the meshes
                                   there, which a build that computes no vertices
                                   (TARN_LINK_COMPUTED_VERTICES 0) cannot */
} tarn_static_view;

typedef struct {
    const tarn_object *objects;
    uint16_t object_count;
    tarn_camera camera;
    tarn_light light;
    uint32_t background_rgb; /* colour of pixels no triangle covers */
    const tarn_underwater *underwater; /* NULL: no underwater view */
    const tarn_static_view *static_view; /* NULL when no object has static vertices;
                                            applies only if camera and light never move */
    const tarn_camera_path *camera_path;   /* NULL: the camera stays (tarn_motion.h) */
    const tarn_light_motion *light_motion; /* NULL: the light stays */
} tarn_scene;

#ifdef __cplusplus
}
#endif

#endif
