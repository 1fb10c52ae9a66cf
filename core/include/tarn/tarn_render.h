/* tarn_render.h: drawing a frame, a tile at a time, into memory the caller owns.
 *
 * Usage:
 *     tarn_frame_config cfg = { 240, 240, tarn_quality_default(), time_ms };
 *     size_t need = tarn_frame_memory_bytes(&cfg, &scene);   0 means the config is invalid
 *     static uint32_t mem[...];                          at least `need` bytes, 4-aligned
 *     tarn_render_frame(&scene, &cfg, mem, sizeof mem, my_sink, my_ctx);
 * The sink receives each finished tile, left to right, top to bottom (or, with the
 * quality's frame_shape TARN_FRAME_STRIPS, each strip of the whole width).
 *
 * What a pixel is (the float reference in host/ implements the same rules):
 *  - View space: forward f = normalize(target - position), right r = normalize(f x Y),
 *    up u = r x f, where Y = (0,1,0); when f is (anti)parallel to Y, Y = (0,0,-1) instead.
 *    A point P has view coordinates x = (P-C).r, y = (P-C).u, depth d = (P-C).f.
 *  - Triangles are clipped to near <= d <= far (cut, not dropped) and, invisibly, to a
 *    guard band of tarn_guard_band_pixels() around the frame; attributes are linear
 *    along clipped edges in view space.
 *  - Screen: focal = (height / 2) / tan(fov_y / 2) pixels; sx = width/2 + x*focal/d,
 *    sy = height/2 - y*focal/d; rounded to the nearest 1/2^subpixel_bits pixel.
 *  - Pixel (i, j) is sampled at its centre (i + 0.5, j + 0.5). A centre exactly on an
 *    edge belongs to the triangle only if that is a top edge (horizontal, triangle
 *    below it) or a left edge (triangle to its right): shared edges draw once.
 *  - Front faces are counter-clockwise in the world, which is clockwise on the screen
 *    (y down); the material's cull mode picks which are drawn. Zero-area triangles
 *    draw nothing.
 *  - Depth test: the pixel's inverse depth near/d, interpolated exactly from the
 *    vertices' Q1.30 values and rounded to nearest Q1.30 (16-bit depth keeps its top
 *    16 bits), must be greater than the stored one: closer wins; on a tie the
 *    earlier triangle stays. Objects draw in scene order, triangles in index order
 *    (the host orders each mesh's triangles spatially when it loads it).
 *  - Vertex colour, per channel: base = material.colour * vertex colour / 255;
 *    shade = min(1, ambient/255 + light/255 * max(0, N.L)) (1 if unlit);
 *    lit = base * shade, in [0, 255].
 *  - Perspective-correct interpolation of lit colour and texture coordinates (the
 *    quality's perspective mode approximates it). Textured pixel = texel * lit / 255,
 *    untextured = lit, rounded to nearest. Texel = (floor(u*W) mod W, floor(v*H) mod H).
 */
#ifndef TARN_RENDER_H
#define TARN_RENDER_H

#include <stddef.h>
#include <stdint.h>
#include "tarn_config.h"
#include "tarn_math.h"
#include "tarn_scene.h"
#include "tarn_water.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    TARN_OK = 0,
    TARN_ERR_CONFIG,  /* a frame or quality field is out of range */
    TARN_ERR_MEMORY,  /* the memory given is smaller than tarn_frame_memory_bytes() */
    TARN_ERR_SCENE,   /* the scene is malformed (null arrays, index past the end...),
                         needs an effect this build left out (TARN_LINK_*, tarn_water.h),
                         or has a backdrop that does not apply to the frame */
    TARN_ERR_SINK     /* the tile sink asked to stop */
} tarn_status;

const char *tarn_status_text(tarn_status status);

typedef enum {
    TARN_PERSPECTIVE_AFFINE = 0, /* linear in screen space: cheapest, bends textures */
    TARN_PERSPECTIVE_SPAN = 1,   /* exact every `perspective_span` pixels, linear between */
    TARN_PERSPECTIVE_PIXEL = 2   /* exact at every pixel */
} tarn_perspective;

typedef enum {
    TARN_DEPTH_EXACT = 0, /* near/d rounded exactly at every pixel: a quotient and its
                           * remainder step across the triangle, so where two surfaces
                           * meet the depth test agrees with host/reference/reference.c */
    TARN_DEPTH_PLANE = 1  /* near/d on a plane set up like the attributes' (one
                           * rounded product per step, no exact division): within
                           * 128 units of 2^-30 (tests/test_raster.c), and three
                           * exact divisions less per triangle */
} tarn_depth_interpolation;

#define TARN_SUBPIXEL_BITS_MIN 1u
#define TARN_SUBPIXEL_BITS_MAX 8u
#define TARN_TILE_SIZE_MIN 8u
#define TARN_TILE_SIZE_MAX 64u
#define TARN_FRAME_SIZE_MAX 1024u

#define TARN_APRON_FULL 255u

/* Every speed/accuracy knob. docs/figures.md gives each one's measured cost and error. */
typedef struct {
    tarn_exp2_config exp2;      /* exp2 table size and interpolation (fog, absorption) */
    uint8_t recip_newton_steps; /* 0..TARN_RECIP_STEPS_MAX, per-pixel perspective divide */
    uint8_t subpixel_bits;      /* 1..8; see tarn_frame_memory_bytes for the size limit */
    uint8_t perspective;        /* tarn_perspective */
    uint8_t perspective_span;   /* 2..64, a power of two; SPAN mode only */
    uint8_t depth_bits;         /* 16 or 32 bits per depth-buffer entry */
    uint8_t depth_interpolation; /* tarn_depth_interpolation */
    uint8_t tile_size;          /* 8..64 pixels: the side of a square tile, or a strip's
                                   rows (frame_shape); does not change the image */
    uint8_t refraction_apron;   /* how far (pixels, each axis) a refracted or underwater
                                   sample may move from its pixel, and so how much opaque
                                   scene each tile renders around its water:
                                   TARN_APRON_FULL as far as the materials reach (the
                                   default); 1..TARN_WATER_APRON_MAX caps the move, which
                                   saves memory and time; 0 moves nothing. The image
                                   never depends on the tile size. */
    uint8_t cluster_bins;       /* 1: find each cluster's screen box once a frame, so a
                                   tile walks only the clusters that meet it (4 bytes of
                                   memory a cluster); 0: each tile tests every cluster's
                                   bounding sphere. Does not change the image. */
    uint8_t fog_argument_bits;  /* TARN_FOG_ARGUMENT_BITS_MIN..16: fraction bits kept of
                                   the depth of water (Q16.16 world units) in exp2's
                                   argument, density * depth, for fog, absorption and the
                                   underwater tint. 16 multiplies exactly (four 16x16
                                   products); fewer cut the depth first, and where the
                                   density is below 1 and the cut depth fits 16 bits one
                                   32-bit product does. */
    uint8_t water_block;        /* 1: every water pixel finds its own effects (normal,
                                   fog, absorption, surface, highlights, foam, sparkles,
                                   refraction's offset); 2 or 4: each 2x2 or 4x4 block
                                   of pixels finds them once, at its top-left pixel, and
                                   applies them to each pixel's own background, where
                                   one triangle draws the block over a background of
                                   about one depth (within 1/64); over still water
                                   (tarn_scene.h), the block shares its highlight. The
                                   tile size must then be a multiple of it. Ignored
                                   under the underwater view. */
    uint8_t refraction_normal;  /* tarn_refraction_normal: the normal a refracted sample
                                   moves by, where it moves (a refraction apron, or
                                   still water's picture) */
    uint8_t frame_shape;        /* tarn_frame_shape: square tiles, or strips of the
                                   frame's width. Does not change the image. */
    uint8_t vertex_pass;        /* tarn_vertex_pass: where vertices are transformed,
                                   projected and lit. Does not change the image. */
    uint8_t lit_colour;         /* tarn_lit_colour: how a triangle interpolates its
                                   vertices' lit colour in per-pixel perspective */
    uint8_t water_coordinates;  /* tarn_water_coordinates: where a water pixel finds
                                   its texture coordinates */
} tarn_quality;

/* Where a frame finds its vertices as the camera sees them. A scene whose static
 * view applies (tarn_scene.h: a baked still scene) reads them from it either way. */
typedef enum {
    TARN_VERTICES_PER_TILE = 0,  /* each tile's or strip's walk, through a 16-vertex
                                    cache: no memory, but a vertex shared by several
                                    pieces, or evicted, is found again */
    TARN_VERTICES_PER_FRAME = 1, /* once a frame, into the frame's memory (a
                                    tarn_static_vertex, 16 bytes, per mesh vertex,
                                    and the scene and its objects copied to name
                                    them), which every walk and the cluster bins read;
                                    a triangle the frame clips transforms its
                                    vertices again */
    TARN_VERTICES_PER_FRAME_VIEW = 2 /* the same, and each vertex's view position (12
                                        bytes more), which a clipped triangle reads */
} tarn_vertex_pass;

/* How a frame is cut into the pieces it draws and hands to the sink, one at a time. */
typedef enum {
    TARN_FRAME_TILES = 0,  /* tile_size squares, each drawing its own opaque apron
                              around its water: the least memory (tiles of 16 KB) */
    TARN_FRAME_STRIPS = 1  /* tile_size rows of the whole width, top to bottom; the
                              opaque pass of the strips a water pixel can sample is
                              kept (a ring of 1 + 2 * ceil(apron / tile_size)
                              strips), so every opaque pixel is drawn once and each
                              part of the scene is walked by about one strip: for
                              boards with the RAM (tarn_frame_memory_bytes). Frames
                              under the underwater view or over a backdrop are
                              drawn in tiles of the same size. */
} tarn_frame_shape;

/* Refraction moves a sample by N.xy times tens of pixels, then rounds to a pixel:
 * N's last bits decide which pixel near half-way points. */
typedef enum {
    TARN_REFRACTION_NORMAL_SHARED = 0, /* the normal the highlight uses: a 14-bit
                                          direction normalised to Q1.15 */
    TARN_REFRACTION_NORMAL_EXACT = 1   /* found from the maps' texel codes whole and
                                          normalised once, N.xy kept to 2^-30: about
                                          ten times nearer; the highlight takes the
                                          same N, rounded to Q1.15, where the pixel
                                          refracts. It normalises every refracting
                                          pixel's N, where the shared one spares the
                                          pixels whose highlight cannot show. */
} tarn_refraction_normal;

/* A triangle whose vertices are lit differently interpolates their colour; in
 * per-pixel perspective each interpolated channel is a plane set up and a division
 * at every pixel. */
typedef enum {
    TARN_LIT_PLANES = 0, /* a plane each channel */
    TARN_LIT_LINE = 1    /* where the three vertices' colours lie on one line in RGB
                            (one light over a mesh without vertex colours, unless a
                            vertex saturates), each within 2/256 of a level a channel
                            and the line within 0..255 over them, so no pixel clamps:
                            one plane, of the channel that changes most, and the
                            others found from it along the line, two planes and two
                            divisions fewer. The pixels then differ from the planes'
                            by up to 3/256 of a level before rounding. */
} tarn_lit_colour;

/* Where a water pixel finds the texture coordinates its maps (normal, foam) are
 * sampled at. */
typedef enum {
    TARN_WATER_UV_TRIANGLES = 0, /* interpolated on its triangle from the corners':
                                    where the subpixel grid moves a corner, it moves
                                    the texels along the whole surface */
    TARN_WATER_UV_PLANE = 1      /* for a mesh with a plane (tarn_uv_plane, flat water),
                                    where the ray through the pixel's centre meets it,
                                    as the host's reference does (within 1e-6 of a
                                    repeat); one reciprocal a pixel with every Newton
                                    step in place of two interpolated coordinates, and
                                    about 2.5 KB of code on the Cortex-M0
                                    (TARN_LINK_WATER_PLANE). Other meshes interpolate.
                                    Still water (tarn_scene.h) takes its plane's
                                    always, and its backdrop applies only to this. */
} tarn_water_coordinates;

#define TARN_FOG_ARGUMENT_BITS_MIN 4u
#define TARN_FOG_ARGUMENT_BITS_MAX 16u

/* Named points on the measured speed/accuracy front (docs/sweep.md gives each
 * one's cost and error, and the sweep that chose them). Every knob is set; a
 * board short of RAM then lowers tile_size, which never changes the image. */
typedef enum {
    TARN_PRESET_FAST,     /* the least cost on the Cortex-M0 that keeps the water legible */
    TARN_PRESET_BALANCED, /* the default: close to exact, at a fraction of its cost */
    TARN_PRESET_EXACT     /* the least error tarn can give, whatever it costs; frames
                             up to 640 pixels a side (5 subpixel bits) */
} tarn_preset;

#define TARN_PRESET_COUNT 3

tarn_quality tarn_quality_preset(tarn_preset preset);
/* "fast", "balanced", "exact"; NULL for a value outside tarn_preset. */
const char *tarn_preset_name(tarn_preset preset);
/* The balanced preset. */
tarn_quality tarn_quality_default(void);

typedef struct {
    uint16_t width, height; /* pixels, 1..TARN_FRAME_SIZE_MAX */
    tarn_quality quality;
    uint32_t time_ms;       /* the clock: panning textures, foam lines and every motion
                               (tarn_motion.h); wraps after ~49 days */
} tarn_frame_config;

/* Pixels the guard band extends beyond each frame edge. */
int32_t tarn_guard_band_pixels(const tarn_frame_config *config);

/* Pixels of opaque scene rendered around each tile for refraction: the farthest any
 * water material's refraction reaches at this width, cut to refraction_apron. */
int32_t tarn_frame_apron_pixels(const tarn_scene *scene, const tarn_frame_config *config);

/* Bytes of working memory a frame of this scene needs, or 0 if the config is
 * invalid: a field out of range, or a frame too large for the subpixel precision
 * ((max(width,height) + 2*guard band) << subpixel_bits must stay below 2^15 so that
 * edge functions fit 32 bits). Opaque scenes need tile_size^2 * (4 + depth_bits/8);
 * with water, the opaque buffers grow by the apron on every side and the tile
 * gains a second colour and depth buffer for the water pass. Without an apron
 * (tarn_frame_apron_pixels 0: refraction_apron 0, or no material refracts) and
 * without the underwater view, the water pass draws over the opaque buffers
 * instead, and needs two rows of the tile more: (tile_size^2 + 2 * tile_size) *
 * (4 + depth_bits/8). With water and water_block 2 or 4, the blocks add
 * tile_size/water_block * 48 bytes (24 over still water). Cluster bins add 4 bytes for each cluster of the scene's
 * meshes (one for a mesh without clusters), unless the scene's static view holds
 * them for this frame (tarn_scene.h).
 * `scene` may be NULL for an opaque-only budget without bins. */
size_t tarn_frame_memory_bytes(const tarn_frame_config *config, const tarn_scene *scene);

/* The 16-bit depth buffer holds near/d (Q1.30, 1..2^30) as a small float: a 4-bit
 * exponent over a 12-bit mantissa with its leading one implied, truncated. Codes
 * order as the values do, so depth tests compare codes. The relative step is 2^-12
 * everywhere above near/d = 2^-14 (d < 16384 near): a plain Q0.16 would step by
 * 2^16/(near/d) relative, 1/655 at d = 100 near, too coarse for water's depth
 * differences. Code 0 is "no triangle"; a drawn pixel's code is at least 1. */
static inline uint16_t tarn_depth16_encode(uint32_t inv_depth_q30)
{
    if (inv_depth_q30 < (1u << 16)) return inv_depth_q30 < 16u ? 1u : (uint16_t)(inv_depth_q30 >> 4);
    const unsigned top = 31u - tarn_clz32(inv_depth_q30); /* 16..30 */
    return (uint16_t)(((top - 15u) << 12) | ((inv_depth_q30 >> (top - 12u)) & 0xFFFu));
}

/* near/d in Q1.30 of a code, the bottom of the range that encodes to it. */
static inline uint32_t tarn_depth16_decode(uint16_t code)
{
    const unsigned exponent = code >> 12;
    const uint32_t mantissa = code & 0xFFFu;
    return exponent == 0u ? mantissa << 4 : (mantissa + 4096u) << (exponent + 3u);
}

typedef struct {
    uint16_t x, y, width, height; /* the tile's rectangle in the frame, pixels: at most
                                     tile_size square, or a strip tile_size rows by
                                     the frame's width */
    const uint32_t *rgb;          /* 0x00RRGGBB pixels, rows `stride` pixels apart */
    const void *depth;            /* near/d per pixel (uint16_t tarn_depth16 code or uint32_t
                                     Q1.30 by depth_bits), same layout; 0 where no triangle drew.
                                     NULL under the underwater view, whose displaced
                                     pixels have no single depth, and over a backdrop,
                                     which keeps depth only where water may draw */
    uint16_t stride;
    uint8_t depth_bits;
} tarn_tile;

/* Receives each finished tile; returns 0 to continue, non-zero to stop the frame. */
typedef int (*tarn_tile_sink)(void *user, const tarn_tile *tile);

/* Renders one frame. `memory` must be 4-byte aligned and at least
 * tarn_frame_memory_bytes(config) long; nothing outside it is written. */
tarn_status tarn_render_frame(const tarn_scene *scene, const tarn_frame_config *config,
                              void *memory, size_t memory_bytes,
                              tarn_tile_sink sink, void *user);

/* One part of a frame drawn by several workers: part `index` of `count`. */
typedef struct {
    uint16_t index; /* 0 .. count - 1 */
    uint16_t count; /* the workers, at least 1 */
} tarn_frame_part;

/* Renders one part of a frame, so that `part.count` workers, each a core or a thread,
 * draw a frame together. Each part delivers its own share of the frame's tiles to
 * its sink, byte for byte as tarn_render_frame draws them; together the parts
 * deliver every tile once, whatever their count. With tiles, part p draws the tiles
 * whose number (left to right, top to bottom, from 0) is p modulo the count;
 * with strips (TARN_FRAME_STRIPS), a run of consecutive strips, first drawing the
 * opaque pass of the strips above its first that its refracted samples reach. Each
 * part needs memory of its own, as tarn_render_frame does, and finds the frame's
 * own work in it (the scene posed, the vertex pass, the cluster bins): that much is
 * done once a part. The parts share nothing the core writes, so they may run at the
 * same time; a sink they share must allow that. A count of 0 or an index past it
 * is TARN_ERR_CONFIG, as is a count above 1 in a build without TARN_LINK_PARTS
 * (tarn_config.h). tarn_render_frame is part 0 of 1. (One argument for both: a
 * Cortex-M0 call passes each stack argument with code of its own.) */
tarn_status tarn_render_frame_part(const tarn_scene *scene, const tarn_frame_config *config,
                                   void *memory, size_t memory_bytes, tarn_frame_part part,
                                   tarn_tile_sink sink, void *user);

/* ---- a frame in strips by two workers over one ring ----------------------------
 *
 * Parts need memory each, and a ring of strips is most of a frame's: two rarely fit
 * a small board's RAM. A strip pipeline shares one ring between two workers (two
 * cores, or threads). A strip's work is two steps: its opaque pass into the ring,
 * and its water over the ring, after which the strip goes to the sink. Either
 * worker takes either step of any strip, in this order:
 *   - opaque strip d once the water of strips 0 .. d - ahead - 2 is done: the ring,
 *     one strip deeper than one core's, then has a slot no water still reads;
 *   - water strip k once the opaque passes of strips 0 .. k + ahead are drawn (or
 *     of every strip, near the frame's end): all its refracted samples reach.
 * Each step is taken once; the strips delivered are tarn_render_frame's (frame_shape
 * TARN_FRAME_STRIPS), byte for byte, though not in order: the two workers call the
 * sink each with its own strips, perhaps at once.
 *
 *     size_t need = tarn_strip_pipeline_memory_bytes(&cfg, &scene);
 *     tarn_strip_pipeline p;
 *     tarn_strip_pipeline_begin(&scene, &cfg, memory, need, &p);   once, first
 *     each worker w (0 or 1), until every step is taken:
 *         take the next water strip k, if tarn_strip_pipeline_drawn_before_water(&p, k)
 *             opaque passes are drawn: tarn_strip_pipeline_water(memory, w, k, sink, user)
 *         or else the next opaque strip d, if the water of
 *             tarn_strip_pipeline_sent_before_opaque(&p, d) strips is done:
 *             tarn_strip_pipeline_opaque(memory, w, d)
 *         or else wait for the other worker
 *
 * Taking and waiting are the caller's (a lock and words both cores read, a mutex
 * and a condition variable): the core has no threads. Within this order the workers
 * share nothing the core writes; each has its own state and water buffers in the
 * memory. A frame that cannot be drawn in strips (under the underwater view, or
 * over a backdrop) sets p.strips to 0: draw it with tarn_render_frame in the same
 * memory. A config whose frame_shape is not TARN_FRAME_STRIPS is TARN_ERR_CONFIG. */
typedef struct {
    int32_t strips; /* the frame's strips, top to bottom; 0: draw it with tarn_render_frame */
    int32_t ahead;  /* strips below its own that a strip's water reads */
} tarn_strip_pipeline;

#define TARN_STRIP_PIPELINE_WORKERS 2

/* How many strips' water, from strip 0, is done before opaque strip d may start (it
 * draws over the slot of strip d - ahead - 2, which that strip's water reads last),
 * and how many strips' opaque passes are drawn before water strip k may start
 * (those its refracted samples reach). */
static inline int32_t tarn_strip_pipeline_sent_before_opaque(const tarn_strip_pipeline *p, int32_t d)
{
    return d - p->ahead - 1;
}

static inline int32_t tarn_strip_pipeline_drawn_before_water(const tarn_strip_pipeline *p, int32_t k)
{
    return k + p->ahead + 1 < p->strips ? k + p->ahead + 1 : p->strips;
}

/* The bytes a pipeline's memory needs (the frame's, a strip more of ring, and each
 * worker's state and water buffers); 0 when the config is invalid. */
size_t tarn_strip_pipeline_memory_bytes(const tarn_frame_config *config, const tarn_scene *scene);
/* Checks the scene and config and finds the frame's own work (the scene posed, the
 * vertex pass, the cluster bins) in `memory` (4-byte aligned), before either worker. */
tarn_status tarn_strip_pipeline_begin(const tarn_scene *scene, const tarn_frame_config *config, void *memory,
                                      size_t memory_bytes, tarn_strip_pipeline *pipeline);
/* Worker `worker` (0 or 1): strip `strip`'s opaque pass into the ring. */
void tarn_strip_pipeline_opaque(void *memory, unsigned worker, int32_t strip);
/* Worker `worker`: strip `strip`'s water, and the strip to the sink; TARN_ERR_SINK
 * when the sink stopped, TARN_ERR_CONFIG for a worker or strip past the last. */
tarn_status tarn_strip_pipeline_water(void *memory, unsigned worker, int32_t strip, tarn_tile_sink sink, void *user);

/* A vertex after transform, clipping and snapping: what the rasterizer sees. */
typedef struct {
    int32_t x, y;        /* screen position in 1/2^subpixel_bits pixels */
    uint32_t inv_depth;  /* near/d, Q1.30, in 1..2^30 (2^30 on the near plane) */
    tarn_uv uv;          /* Q16.16 texture coordinates */
    uint16_t uv_low[2];  /* the 16 bits below u and v: a clipped vertex's own, 0 elsewhere
                            (near the eye one bit of Q16.16 can span many pixels) */
    uint16_t lit[3];     /* lit vertex colour, Q8.8 per channel (0..65280) */
    uint16_t fresnel;    /* (1 - n.v)^2, Q1.15 (32768 = 1): n the unit vertex normal, v the
                            unit vector toward the camera; water materials only, else 0 */
} tarn_screen_vertex;

typedef void (*tarn_triangle_visitor)(void *user, const tarn_screen_vertex vertex[3],
                                      const tarn_object *object);

/* Calls `visit` for every triangle the rasterizer is handed, in drawing order,
 * after clipping and snapping, with the mesh's own vertex order. Culling is not yet
 * applied: the rasterizer culls on the snapped winding (see the rules above), and a
 * visitor that draws must do the same. The float reference uses this to rasterize
 * exactly the core's triangles, isolating rasterization from transform precision.
 * A moving scene is refused (TARN_ERR_SCENE): visit its pose (tarn_scene_pose). */
tarn_status tarn_visit_screen_triangles(const tarn_scene *scene,
                                        const tarn_frame_config *config,
                                        tarn_triangle_visitor visit, void *user);

#ifdef __cplusplus
}
#endif

#endif
