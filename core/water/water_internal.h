/* water_internal.h: the fifth stage of a frame (core/water/), internal to core/:
 * the water pixel of tarn_water.h, in integers.
 *
 *   water_setup.c      per water object per tile: the context below
 *   water_plane.c      per water object per frame: its plane's texture coordinates
 *   water_span.c       water triangles, row by row as core/raster/ hands them
 *                      out, and the 2x2 or 4x4 blocks that share effects
 *   water_pixel.c      one water pixel: its effects gathered, then applied
 *   water_normals.c, water_refraction.c, water_fog.c, water_surface.c,
 *   water_highlights.c, water_foam.c   the effects, a file each
 *   water_common.c     what the effects share: products, texels, depths
 *   water_still.c      the moving terms over a still-water backdrop, no triangle drawn,
 *                      and refracted samples read from its picture
 *   underwater.c       the underwater view (underwater_internal.h), its constants
 *                      in underwater_setup.c
 *
 * It takes the opaque pass's colour and depth around the tile and water triangles
 * from core/tile/'s walk, and hands on the tile's colour. A water pixel costs
 * hundreds of instructions where it finds its own effects, far fewer where it
 * shares its block's; a scene without water never calls this stage.
 *
 * A context holds what is fixed for one water object in one tile: the material,
 * the frame's time-dependent pan offsets, the half vector in the object's tangent
 * frame, reciprocals of the material's distances, and the opaque background
 * buffers (the tile plus its apron) that refraction and fog read. Per pixel,
 * tarn__water_effects_at and tarn__water_apply use 32-bit products only (16x16-bit partial products where a
 * result needs more), the table reciprocal, and no division. */
#ifndef TARN_WATER_INTERNAL_H
#define TARN_WATER_INTERNAL_H

#include "raster/raster_internal.h"

/* What turns a near/d into a linear depth, fixed for a frame: near left-justified
 * (its mantissa, top bit set, and the shift that made it: a count of leading zeros
 * the Cortex-M0 would otherwise take at every depth, three a water pixel), far,
 * and the reciprocal's Newton steps. */
typedef struct {
    uint32_t near_mantissa;
    unsigned near_shift;
    tarn_q16 far;
    unsigned recip_steps;
} tarn_linear_depth;

void tarn__linear_depth_setup(tarn_linear_depth *d, tarn_q16 near, tarn_q16 far, unsigned recip_steps);

/* An affine function of the pixel, at + per_i * i + per_j * j taken modulo 2^32,
 * with the steps' 16 fraction bits below: rounded to whole units, they moved a
 * value 240 pixels from the origin by up to 240 units, 2^-18 of a plane's far
 * denominator. */
typedef struct {
    int32_t at, per_i, per_j;
    uint16_t fraction_i, fraction_j;
} tarn_fine_affine;

static inline uint32_t tarn__fine_affine_at(const tarn_fine_affine *f, int32_t i, int32_t j)
{
    const uint32_t below = ((uint32_t)f->fraction_i * (uint32_t)i + (uint32_t)f->fraction_j * (uint32_t)j) >> 16;
    return (uint32_t)f->at + (uint32_t)f->per_i * (uint32_t)i + (uint32_t)f->per_j * (uint32_t)j + below;
}

/* A flat water object's texture coordinates as the frame sees them (water_plane.c):
 * at pixel (i, j), u = u_plane * 2^uv_shift / denominator in Q16.16; the
 * denominator is within [1, 2^30] wherever the surface shows. */
typedef struct {
    tarn_fine_affine denominator, u, v;
    uint8_t uv_shift; /* 0..31 */
    uint8_t holds;    /* 0: the object has no plane, or its numbers leave these 32
                         bits in this frame: its triangles interpolate the coordinates */
} tarn_water_plane;

/* The plane of `object`'s mesh (tarn_mesh.plane) in the frame of `view`, where the
 * quality's `coordinates` (tarn_water_coordinates) take it. */
void tarn__water_plane_setup(tarn_water_plane *out, const tarn_view *view, uint8_t coordinates,
                             const tarn_object *object);

typedef struct tarn_water_context {
    const tarn_water *water;
    const tarn_object *object;  /* the object the context was made for */
    uint32_t features;          /* the material's TARN_WATER_* the build links */
    uint16_t width, height;     /* the frame */
    tarn_linear_depth linear;
    tarn_exp2_config exp2;
    unsigned fog_argument_bits;

    uint32_t pan_a[2], pan_b[2], foam_pan[2]; /* Q0.32 offsets of the panning textures */
    uint16_t foam_phase;        /* time * foam_line_speed, Q0.16 turns of the band */
    int32_t half_vector[3];     /* Q1.15, in the object's tangent frame (u, v, up) */
    uint32_t light_q8[3];       /* light colour, Q8.8 per channel */
    uint32_t fog_q8[3];         /* the fog's colour, Q8.8 per channel; 0 without fog */
    uint32_t inv_depth_scale;   /* Q16.16 per world unit */
    uint32_t inv_foam_distance; /* Q16.16 per world unit */
    uint8_t foam_texel_bytes;   /* the foam map's: 1 kept red alone, else 3 */
    uint32_t refraction_px;     /* refraction * width: pixels per unit normal, Q16.16 */
    uint32_t sparkle_threshold; /* sparkle where x^2 (Q2.30) exceeds this */
    int32_t dark_cosine;        /* tarn__water_dark_cosine of the material */

    const uint32_t *background;      /* opaque colour, 0x00RRGGBB */
    const void *background_depth;    /* opaque near/d, by depth_bits */
    uint8_t depth_bits;
    tarn_pixel_rect background_rect; /* frame pixels the background buffers hold */
    int32_t background_stride;
    int32_t offset_limit;            /* pixels a refracted sample may move, each axis:
                                        the frame's refraction apron */
    tarn_pixel_rect sample_rect;     /* where refracted samples may land: the frame */
    /* with an opaque backdrop (tarn_scene.h), which holds the whole frame's opaque
       picture in flash: refracted samples that move are read from it, so the tile
       draws no apron (sample_rect is then the whole frame); NULL otherwise */
    const tarn_backdrop *flash;
    /* the quality's water_block 2 or 4: the effects of each block of the tile,
       found at its top-left pixel, a slot per block column; NULL with water_block 1 */
    struct tarn_water_block *blocks;
    uint8_t block_shift;   /* log2 of the quality's water_block */
    /* a refracting pixel finds N exactly, once (tarn__water_surface_normal): the
       quality's refraction_normal is EXACT and refracted samples move
       (tarn__water_refracts); decided with the context, not at each pixel */
    uint8_t exact_normal;
    uint32_t triangle_serial; /* water triangles drawn this frame, 0 before the first */
    /* over a still-water backdrop with the quality's water_block 2 or 4: each
       block's highlight, a slot per block column (tarn_still_block); NULL otherwise */
    struct tarn_still_block *still_blocks;
    uint32_t still_walks; /* tile walks over still water this frame, 0 before the first */
#if TARN_LINK_WATER_PLANE
    tarn_water_plane plane; /* the object's texture coordinates from its plane: 52
                               bytes of the frame's stack a build without it keeps */
#endif
    /* rows the background buffers hold before they wrap to their first (a frame
       drawn in strips keeps them in a ring); INT32_MAX: they never do. Last, so
       the fields above keep the offsets a Cortex-M0 loads in one instruction. */
    int32_t background_rows;
} tarn_water_context;

/* A block's highlight over still water, and who found it: the walk of one water
 * object over one tile (its still_walks), at the block's top-left pixel. The
 * block's other pixels of that object take it; no depth need match, since the
 * highlight does not depend on it. */
typedef struct tarn_still_block {
    uint32_t highlight[3]; /* Q8.8 a channel */
    uint32_t lit;          /* 0 when the highlight adds nothing */
    uint32_t walk;         /* 0: nobody */
    int32_t row;           /* the block's top pixel row */
} tarn_still_block;

/* Per-frame and per-object constants; buffers are set by the caller. */
void tarn__water_context_setup(tarn_water_context *w, const tarn_view *view,
                              const tarn_frame_config *config, const tarn_object *object);

/* Interpolated inputs of one water pixel. */
typedef struct {
    uint32_t inv_depth; /* the water surface's near/d, Q1.30 */
    uint32_t lit[3];    /* material colour times shade, Q8.8 */
    uint32_t u, v;      /* texture coordinates, Q16.16 modulo 2^16 repeats */
    uint16_t u_low, v_low; /* their next 16 fraction bits, as far as the triangle's
                              interpolation holds them: a map's scale multiplies the
                              coordinate's rounding, and at a scale of 12 the last
                              bit of Q16.16 alone was 1/85 of a texel */
    uint32_t fresnel;   /* saturate(1 - n.v)^2, Q1.15 */
} tarn_water_input;

/* An affine function of a plane at pixel (i, j), modulo 2^32. */
static inline uint32_t tarn__pixel_affine_at(const int32_t f[3], int32_t i, int32_t j)
{
    return (uint32_t)f[0] + (uint32_t)f[1] * (uint32_t)i + (uint32_t)f[2] * (uint32_t)j;
}

/* numerator * 2^shift / denominator in Q16.16, modulo 2^32, from the denominator's
 * reciprocal recip = 2^62 / (denominator << lz): numerator * recip / 2^32 *
 * 2^(shift + lz - 30), and in `low` the 16 fraction bits below, as the rasterizer
 * hands them on (tarn_water_input): the panned maps multiply the coordinate by
 * their scale. */
static inline uint32_t tarn__plane_coordinate(uint32_t numerator, uint32_t recip, unsigned lz, unsigned shift,
                                              uint16_t *low)
{
    const int32_t high = tarn_mul_hi_s32_u32((int32_t)numerator, recip);
    const int up = (int)(shift + lz) - 30; /* -29..32: lz 1..31, shift 0..31 */
    *low = 0u;
    if (up >= 32) return 0u;
    if (up >= 0) return (uint32_t)high << up;
    const unsigned down = (unsigned)-up;
    /* past 16 bits below Q16.16, rounded to nearest there */
    const int32_t rounded = down > 16u ? (int32_t)((uint32_t)high + (1u << (down - 17u))) : high;
    *low = (uint16_t)(((uint32_t)rounded << (32u - down)) >> 16);
    return (uint32_t)tarn_floor_shift(rounded, down);
}

/* A water pixel's texture coordinates from a plane's u and v numerators and its
 * denominator at the pixel, within [1, 2^30] (tarn_water_plane, tarn_still_plane):
 * one reciprocal for both. */
static inline void tarn__plane_coordinates(uint32_t denominator, uint32_t u, uint32_t v, unsigned uv_shift,
                                           unsigned recip_steps, tarn_water_input *in)
{
    const unsigned lz = tarn_clz32(denominator);
    const uint32_t recip = tarn_recip_q30(denominator << lz, recip_steps);
    in->u = tarn__plane_coordinate(u, recip, lz, uv_shift, &in->u_low);
    in->v = tarn__plane_coordinate(v, recip, lz, uv_shift, &in->v_low);
}

/* A plane's denominator, within [1, 2^30]. */
static inline uint32_t tarn__plane_denominator(uint32_t value)
{
    return (uint32_t)tarn_clamp_i32((int32_t)value, 1, 1 << 30);
}

/* Per-pixel helpers the underwater pass shares (32-bit products only). */
/* a * b / 2^16 for unsigned Q16.16 values, saturated to INT32_MAX. */
uint32_t tarn__water_mul_q16(uint32_t a, uint32_t b);
/* exp2's argument rate * x / 2^16 (both Q16.16, non-negative) with the depth x cut
 * to `bits` fraction bits (tarn_quality.fog_argument_bits; 16 keeps it whole),
 * saturated like tarn__water_mul_q16. */
uint32_t tarn__fog_argument_q16(uint32_t rate, uint32_t x, unsigned bits);
/* The squared absorption's exp2 argument rate * x^2 (rate per unit^2 and x, Q16.16,
 * non-negative; the result Q16.16), within 2^-27 of the product relative, saturated
 * only where the product passes INT32_MAX (where exp2 is 0 long before). The depth is
 * not cut to fog_argument_bits: the cut buys fog one multiply, which this has not to
 * save, and cut before squaring it would cost a shallow depth most of its bits. */
uint32_t tarn__squared_argument_q16(uint32_t rate, uint32_t x);
/* A map coordinate's fraction of a repeat, Q0.32: (u + low / 2^16) * scale modulo
 * one repeat, u and scale Q16.16, low the coordinate's next 16 bits; within two
 * units below the exact value. u * scale is Q32.32, and its low word, all a 32-bit
 * product keeps, is exactly its fraction (negative or wrapped u too); the low bits'
 * share is low * scale / 2^16, split so no product passes 32 bits. At Q0.16 a
 * 64-texel map's texel edges fell at 1/1024 of a texel, and a whole row of pixels
 * level with one tipped with the pan offset's rounding. */
static inline uint32_t tarn__water_map_fraction(uint32_t u, uint32_t low, uint32_t scale)
{
    return u * scale + low * (scale >> 16) + ((low * (scale & 0xFFFFu)) >> 16);
}
/* A texel channel as a normal component, (2c - 255) / 255 in Q1.15. */
static inline int32_t tarn__water_normal_component(uint8_t c)
{
    return ((2 * (int32_t)c - 255) * 257) / 2;
}
/* The texel at a repeat fraction (Q0.16 each axis), nearest, power-of-two sides. */
const uint8_t *tarn__water_texel_at(const tarn_texture *t, uint32_t u_fraction, uint32_t v_fraction,
                                    unsigned texel_bytes);
/* near / (iz / 2^30) in Q16.16 world units, saturated; far for iz 0. */
uint32_t tarn__water_linear_depth(uint32_t iz_q30, const tarn_linear_depth *d);
/* The same from iz's reciprocal (the perspective divide's, tarn_depth_reciprocal):
 * near * recip * 2^(lz - 32), saturated. */
uint32_t tarn__water_linear_depth_of(const tarn_depth_reciprocal *iz, const tarn_linear_depth *d);
/* Pan offset of a speed (repeats per second, Q16.16) at time_ms, Q0.16. */
uint16_t tarn__water_pan_offset(tarn_q16 speed, uint32_t time_ms);
/* The same in Q0.32, for the maps' Q0.32 fractions: floor(speed * time_ms * 2^16 /
 * 1000) modulo 2^32. */
uint32_t tarn__water_pan_offset_q32(tarn_q16 speed, uint32_t time_ms);

/* What the water does to the background of one pixel: every step of tarn_water.h
 * but the background's colour, gathered so that the pixel's colour is one product
 * a channel of its background B: base + B * gain. The quality's water_block 2
 * finds it once for a 2x2 block of pixels and applies it to each pixel's own
 * background; only the sharp features (TARN_WATER_SHOWS_*) are found again at
 * every pixel. Absorption takes its loss between the fog and the surface, and
 * clamps there at 0, so with it the pixel is
 *     base + max(0, B * gain + lift) * through
 * instead (all products Q1.15 and shifted down by 15). */
typedef struct {
    int8_t offset[2];        /* the background sample, from the pixel (refraction) */
    uint8_t sharp;           /* TARN_WATER_SHOWS_* at the pixel that found them */
    uint16_t gain;           /* Q1.15: the share of B the pixel keeps (steps 4 and 7's
                                fog keep times 1 - alpha); with absorption the fog
                                keep alone */
    uint16_t through;        /* Q1.15, with absorption: 1 - alpha */
    uint32_t base[3];        /* Q8.8: the fog colour's and the lit surface's shares
                                (steps 4, 6, 7) and the specular (step 8); with
                                absorption the surface's and the specular only */
    int32_t lift[3];         /* Q8.8, with absorption: the fog colour's share less
                                what absorption takes (step 5) */
    uint32_t foam_band;      /* step 9: where in the shore's foam band, Q0.16 (0 at the
                                shore); 65536 or more beyond it, where no foam shows */
} tarn_water_effects;

/* A block's effects, and who found them: the water triangle (its triangle_serial)
 * and the block row (the block's top pixel row). A block's other pixels take them
 * when the same triangle draws them next (the rest of that row, then the row below)
 * and their background lies as deep as the top-left pixel's, within
 * TARN_WATER_BLOCK_DEPTH_SHIFT: across a submerged object's edge the depth of water
 * changes at once, and the block's effects would fog the object as deep water. */
typedef struct tarn_water_block {
    tarn_water_effects effects;
    uint32_t serial;     /* 0: nobody */
    int32_t row;
    uint32_t depth_q30;  /* the top-left pixel's background, near/d (Q1.30) */
} tarn_water_block;

/* A pixel shares its block's effects when its background's near/d is within
 * 1/2^TARN_WATER_BLOCK_DEPTH_SHIFT of the top-left pixel's. */
#define TARN_WATER_BLOCK_DEPTH_SHIFT 6u

/* The opaque background's near/d (Q1.30) at frame pixel (i, j). */
uint32_t tarn__water_background_q30(const tarn_water_context *w, int32_t i, int32_t j);

/* The effects at water pixel (i, j), each called only when the material has it and
 * the build links it. */
void tarn__water_effects_at(const tarn_water_context *w, int32_t i, int32_t j, const tarn_water_input *in,
                           uint32_t surface_depth, tarn_water_effects *out);
/* The features a pixel sharp, which blocks find at every pixel: step 9's foam
 * lines and step 10's sparkles. */
#define TARN_WATER_SHOWS_FOAM 1u
#define TARN_WATER_SHOWS_SPARKLES 2u

/* The colour (0x00RRGGBB) of water pixel (i, j): its background, moved by the
 * effects' offset (found for this pixel: never shared), through the effects, with
 * the sharp features `sharp` (TARN_WATER_SHOWS_*: the effects' own, or the pixel's). */
uint32_t tarn__water_apply(const tarn_water_context *w, const tarn_water_effects *e, unsigned sharp, int32_t i,
                          int32_t j);
/* Steps 3 to 7 over `diff` of water (Q16.16) and background colour `rgb_below`
 * (0x00RRGGBB), for a pixel with inputs `in` (its lit colour and fresnel term):
 * the colour, 0x00RRGGBB, rounded as step 11 rounds. */
uint32_t tarn__water_still_over(const tarn_water_context *w, const tarn_water_input *in, uint32_t diff,
                               uint32_t rgb_below);
/* The sharp features that show at a pixel sharing effects `e` (TARN_WATER_SHOWS_*),
 * of those the material has and the build links; for a pixel where one can
 * (tarn__water_sharp_possible). */
unsigned tarn__water_sharp_features(const tarn_water_context *w, const tarn_water_input *in,
                                   const tarn_water_effects *e);
/* Whether a sharp feature could show at a pixel sharing effects `e`: sparkles, or
 * foam within its band. A pixel where none can needs no inputs of its own. */
int tarn__water_sharp_possible(const tarn_water_context *w, const tarn_water_effects *e);
/* Both at one pixel: the colour of water pixel (i, j) with its own effects, its
 * surface at linear depth ds = `surface_depth` (Q16.16 world units). */
uint32_t tarn__water_shade(const tarn_water_context *w, int32_t i, int32_t j, const tarn_water_input *in,
                          uint32_t surface_depth);

/* ---- what the steps share (water_common.c) ---- */

/* Whether the material has an effect and the build links it: with
 * TARN_LINK_WATER_FEATURES a constant, the calls of effects left out are removed at
 * compile time, and with TARN_LINK_WATER_FEATURES_ALL the questions of effects
 * every material has. */
static inline int tarn__water_uses(const tarn_water_context *w, uint32_t feature)
{
    if (((uint32_t)TARN_LINK_WATER_FEATURES_ALL & feature) != 0u) return 1;
    return (TARN_LINK_WATER_FEATURES & feature) != 0 && (w->features & feature) != 0;
}

/* Sparkles show only from the maps' components, which the normals step reads. */
static inline int tarn__water_sparkles_possible(const tarn_water_context *w)
{
    return tarn__water_uses(w, TARN_WATER_SPARKLES) && tarn__water_uses(w, TARN_WATER_NORMALS);
}

/* The linear depth (Q16.16 world units) of a near/d (Q1.30) in the context's frame. */
static inline uint32_t tarn__water_depth_of(const tarn_water_context *w, uint32_t iz_q30)
{
    return tarn__water_linear_depth(iz_q30, &w->linear);
}

/* The index of frame pixel (i, j) in the background buffers. */
static inline int32_t tarn__water_background_offset(const tarn_water_context *w, int32_t i, int32_t j)
{
    int32_t row = j - w->background_rect.y0;
    if (TARN_LINK_STRIPS && row >= w->background_rows) row -= w->background_rows; /* rows held span less than the ring */
    return row * w->background_stride + (i - w->background_rect.x0);
}

/* A 0xRRGGBB colour's channel c (0 red, 1 green, 2 blue) in Q8.8. */
static inline uint32_t tarn__water_channel_q8(uint32_t rgb, int c)
{
    return ((rgb >> (16 - 8 * c)) & 0xFFu) << 8;
}

/* The texel of a panning texture under the pixel's uv, at the frame's pan offset. */
static inline const uint8_t *tarn__water_panned_texel(const tarn_texture *t, unsigned texel_bytes,
                                                     const tarn_panning *pan, const uint32_t offset[2],
                                                     const tarn_water_input *in)
{
    const uint32_t u = tarn__water_map_fraction(in->u, in->u_low, (uint32_t)pan->scale) + offset[0];
    const uint32_t v = tarn__water_map_fraction(in->v, in->v_low, (uint32_t)pan->scale) + offset[1];
    /* a power-of-two side's texel is the Q0.32 fraction's top bits: its top 16 do */
    return tarn__water_texel_at(t, u >> 16, v >> 16, texel_bytes);
}

/* 2^(-rate * x) for rate, x >= 0 (Q16.16), Q0.16, through the frame's exp2 table. */
uint32_t tarn__water_decay(const tarn_water_context *w, uint32_t rate, uint32_t x);

typedef struct {
    int32_t x, y;   /* the frame pixel of the background B */
    uint32_t depth; /* its linear depth db, Q16.16 world units */
} tarn_water_sample;

/* The opaque background at frame pixel (i, j); its colour is read when applied. */
tarn_water_sample tarn__water_background(const tarn_water_context *w, int32_t i, int32_t j);
/* The same where a refracted sample lands: from the backdrop in flash if the
 * context has one (w->flash), else from the tile's buffers. */
static inline tarn_water_sample tarn__water_moved_background(const tarn_water_context *w, int32_t i, int32_t j)
{
    if (!TARN_LINK_BACKDROP || w->flash == NULL) return tarn__water_background(w, i, j);
    tarn_water_sample s = {i, j, tarn__water_depth_of(w, tarn__backdrop_depth_q30(w->flash, i, j))};
    return s;
}

/* The surface normal N, or before tarn__water_normalise its direction: normalising
 * takes a reciprocal square root, which a pixel whose highlight cannot show (most
 * of them) is spared when nothing else needs N. */
typedef struct {
    int32_t x, y, z;  /* N, Q1.15; or while length2 > 0 the direction, Q2.13, its
                         largest component in [2^13, 2^14) */
    uint32_t length2; /* the direction's squared length, Q4.26; 0 once (x, y, z) is N */
    int32_t a_x, b_x; /* the maps' own x components, for sparkles */
    int has_b;
    int32_t xy_q30[2]; /* where the pixel refracts by the EXACT normal: N.xy, Q1.30 */
} tarn_water_normal;

/* (0, 0, 1): the surface without normal maps. Filled field by field, as every
 * normal is filled in place: copied whole, a struct this size is a call to memcpy
 * on the Cortex-M0. */
static inline void tarn__water_flat_normal(tarn_water_normal *n)
{
    n->x = n->y = 0;
    n->z = 32768;
    n->length2 = 0u;
    n->a_x = n->b_x = 0;
    n->has_b = 0;
    n->xy_q30[0] = n->xy_q30[1] = 0;
}

/* Whether the context's refracted samples move: the material refracts, the build
 * links the apron, and the frame gives one (offset_limit). */
static inline int tarn__water_refracts(const tarn_water_context *w)
{
    return TARN_LINK_APRON && tarn__water_uses(w, TARN_WATER_REFRACTION) && w->offset_limit > 0;
}
/* N from its direction, in place; nothing when it is N already. */
void tarn__water_normalise(tarn_water_normal *n);

/* The sharp features (TARN_WATER_SHOWS_*) at a pixel at `foam_band` (as
 * tarn_water_effects') with normal `n`, of those the material has and the build
 * links; and a colour (Q8.8 a channel) with them over it, rounded to 0x00RRGGBB. */
unsigned tarn__water_sharp_at(const tarn_water_context *w, const tarn_water_input *in, uint32_t foam_band,
                             const tarn_water_normal *n);
uint32_t tarn__water_finish(const tarn_water_context *w, unsigned sharp, uint32_t colour[3]);

/* ---- water triangles (water_span.c) ---- */

/* The water pass of a tile: where its triangles draw, and the context that shades
 * them (whose background buffers are the opaque pass's). */
typedef struct {
    tarn_tile_target target;
    tarn_water_context *water;
    const tarn_view *view;
    const tarn_frame_config *config;
    uint32_t mark;    /* TARN_WATER_MARK (scene_internal.h) when the pass draws over the opaque buffers
                         themselves, else 0 */
    uint32_t overlap; /* non-zero once it wrote over a pixel it had written */
} tarn_water_pass;

/* A triangle of a water material into the pass (a tarn_water_pass): a
 * tarn_triangle_sink. */
void tarn__water_draw_triangle(void *pass, const tarn_screen_vertex vertex[3], const tarn_object *object);
/* The marks of an in-place pass off the pixels of its rect. */
void tarn__water_clear_marks(const tarn_tile_target *target);

/* ---- over a still-water backdrop (water_still.c) ---- */

/* What a still-water backdrop keeps at the water pixels of a material whose
 * refracted samples move or not (`refracts`: refraction with an apron): 1 for the
 * depth of water beneath, db - ds in Q0.16 world units, where it is less than one
 * unit; 0 for the place in the foam band (step 9's f, Q0.16) where that is less
 * than 1, which also gives saturate(db - ds) when the band is one unit deep or
 * deeper. tarn bake keeps what this says, and the frame reads it so. */
int tarn__still_keeps_depth(const tarn_water *water, int refracts);

/* The moving terms (TARN_WATER_MOVING) of the context's water object, the scene's
 * object `object`, over the tile's pixels in its rect that the backdrop marks
 * with it: each keeps its still colour with a highlight and the sharp features
 * over it, and loses the marks. */
void tarn__water_still_tile(tarn_water_context *w, const tarn_backdrop *backdrop, uint32_t object,
                           tarn_tile_target *tile);

/* ---- the effects, a file each: with TARN_LINK_WATER_FEATURES, the ones a scene
 * does not use are never called and so never linked ---- */

/* Step 1 (water_normals.c, TARN_WATER_NORMALS) at a pixel, the flat normal without
 * maps. Where the pixel refracts by the quality's EXACT refraction normal: N itself,
 * from the maps' texel codes exactly (strength * (a.xy + b.xy), a.z * b.z), each
 * component within 3 units of Q1.15, with N.xy in Q1.30 for refraction, which
 * scales it by tens of pixels and rounds. Elsewhere the direction of N in 14 bits, to be normalised by
 * the steps that need N. */
void tarn__water_surface_normal(const tarn_water_context *w, const tarn_water_input *in, tarn_water_normal *n);
/* The same for any material: without normal maps (or a build that links none) the
 * flat normal, and step 1 is not linked. */
static inline void tarn__water_pixel_normal(const tarn_water_context *w, const tarn_water_input *in,
                                            tarn_water_normal *n)
{
    if (tarn__water_uses(w, TARN_WATER_NORMALS)) tarn__water_surface_normal(w, in, n); else tarn__water_flat_normal(n);
}
/* Only the maps' own x components (a_x, b_x, has_b), which sparkles read: the flat
 * normal with them. */
void tarn__water_map_x(const tarn_water_context *w, const tarn_water_input *in, tarn_water_normal *n);
/* Step 2 (water_refraction.c, TARN_WATER_REFRACTION), where the context refracts
 * (tarn__water_refracts): the pixel a refracted sample at (i, j) reads, `target`:
 * moved by N.xy times the material's pixels per unit normal and `reach`
 * (saturate(db - ds), Q0.16), snapped to a whole pixel, at most the context's
 * offset_limit each axis and inside its sample_rect. `n` is step 1's
 * (tarn__water_pixel_normal): with the quality's EXACT refraction normal its
 * xy_q30; else it is normalised, for the steps after too, and moves by its N.xy. */
void tarn__water_refracted_pixel(const tarn_water_context *w, int32_t i, int32_t j, tarn_water_normal *n,
                                 uint32_t reach, int32_t target[2]);
/* The refracted sample of water pixel (i, j), or the pixel's own background where
 * the refracted one would lie in front of the water. */
tarn_water_sample tarn__water_refract(const tarn_water_context *w, int32_t i, int32_t j, tarn_water_normal *n,
                                     uint32_t surface_depth);
/* Steps 4 and 5 (water_fog.c), over `diff` (Q16.16 world units) of water: the share
 * of the background the fog keeps (Q1.15), and what absorption takes from each
 * channel (Q8.8). */
uint32_t tarn__water_fog(const tarn_water_context *w, uint32_t diff);
void tarn__water_absorb(const tarn_water_context *w, uint32_t diff, uint16_t loss[3]);
/* Step 4 moved: a colour (0xRRGGBB, marks above ignored) of water whose fog saw its
 * background through some depth of water, seen through to - from more (Q16.16
 * world units each: two depths of the surface, say, the background's depth less
 * the one less the other): endless + (colour - endless) * exp2(-density * (to -
 * from)) a channel, `endless` the colour over water of endless depth (0xRRGGBB). A
 * refracted sample over still water is read where the fog saw it from another
 * pixel's surface. Past 16 halvings' worth less water the colour moves as for 16. */
uint32_t tarn__water_fog_moved(const tarn_water_context *w, uint32_t colour, uint32_t endless, uint32_t from,
                               uint32_t to);
/* Step 6's depth colour and step 7's fresnel raise of alpha (Q1.15) (water_surface.c). */
void tarn__water_depth_colour(const tarn_water_context *w, uint32_t diff, uint32_t out[3]);
uint32_t tarn__water_fresnel_alpha(const tarn_water_context *w, const tarn_water_input *in, uint32_t alpha);
/* Steps 8, 9 and 10 (water_highlights.c, water_foam.c). Colours are Q8.8. */
/* 1 where the specular highlight shows, with what it adds to each channel (Q8.8). */
int tarn__water_specular(const tarn_water_context *w, tarn_water_normal *n, uint32_t highlight[3]);
/* The largest cosine N.h (Q1.15) whose specular adds nothing to a colour, for a
 * material; -1 when even a cosine of 0 adds something. */
int32_t tarn__water_dark_cosine(const tarn_water *water);
/* Where `diff` of water lies in the foam band (tarn_water_effects.foam_band); 1
 * where the foam shows at a pixel at that place of the band; tarn__water_foam_over
 * turns a colour toward the foam's by its opacity. */
uint32_t tarn__water_foam_band(const tarn_water_context *w, uint32_t diff);
int tarn__water_foam(const tarn_water_context *w, const tarn_water_input *in, uint32_t f);
void tarn__water_foam_over(const tarn_water_context *w, uint32_t colour[3]);
/* 1 where the sparkles show. */
int tarn__water_sparkles(const tarn_water_context *w, const tarn_water_normal *n);

#endif
