/* tarn_water.h: see-through water, as a material feature set.
 *
 * A material with a `water` block is drawn after every opaque triangle of the tile,
 * reading the opaque colour and depth beneath it (the seeds' grab pass and depth
 * texture, tile-sized). Each feature is off unless its flag is set; a scene without
 * water does no water work. The float reference (host/) implements the same rules.
 *
 * Per water pixel p, in this order (all fractions clamped to [0, 1]):
 *  0. ds = linear depth of the water surface at p; db = linear depth of the opaque
 *     surface at p, or the camera's far distance where nothing opaque was drawn.
 *     Water behind the opaque surface is not drawn (the ordinary depth test).
 *  1. Normal (TARN_WATER_NORMALS): each map is sampled at uv * scale + time * speed
 *     (uv: the mesh's texture coordinates; nearest texel, wrapping). A texel channel
 *     c decodes to (2c - 255) / 255. With two maps a and b,
 *     N = normalize(strength * (a.xy + b.xy), a.z * b.z); with one, a alone.
 *     Without normals N = (0, 0, 1).
 *  2. Refraction (TARN_WATER_REFRACTION): offset = N.xy * refraction * width pixels
 *     (both axes by the width: aspect-corrected), times saturate(db - ds); the sample
 *     pixel q = p + round(offset) (a whole pixel: the seeds' AlignWithGrabTexel),
 *     clamped to the frame. If the opaque surface at q is in front of the water
 *     (db(q) < ds), q = p. Then B = colour(q) and db = db(q).
 *  3. diff = max(0, db - ds), in world units.
 *  4. Fog (TARN_WATER_FOG): B = fog + (B - fog) * exp2(-density * diff).
 *  5. Absorption (TARN_WATER_ABSORPTION): B = B - (255 - absorb) * (1 - exp2(-k * x))
 *     per channel, x = diff or diff^2 (absorption_squared), floored at 0.
 *  6. Surface colour S: `albedo`; with TARN_WATER_DEPTH_COLOUR, shallow + (deep -
 *     shallow) * saturate(diff / depth_scale); with a colour ramp, the ramp's first
 *     row at x = floor(saturate(diff / depth_scale) * (W - 1) + 0.5).
 *  7. S is lit like any vertex colour (material colour * shade, interpolated), then
 *     C = S * alpha + B * (1 - alpha), where with TARN_WATER_FRESNEL
 *     alpha = alpha + (1 - alpha) * fresnel * saturate(1 - n.v)^2, n the mesh normal and v
 *     toward the camera, per vertex and interpolated.
 *  8. Specular (TARN_WATER_SPECULAR): C += light * specular * max(0, N.h)^power, h the
 *     half vector of the light and the camera's backward axis in the water's
 *     tangent frame (object x = u, object z = v, object y = up).
 *  9. Foam (TARN_WATER_FOAM): f = saturate(diff / foam_distance);
 *     lines = saturate(sin(2 pi * foam_line_count * (f - time * foam_line_speed))) * (1 - f);
 *     t = red channel / 255 of the foam texture at uv * foam_scale + time * foam_speed;
 *     foam where f < 1 and t >= f - lines: C = C + (foam_colour - C) * foam_opacity.
 * 10. Sparkles (TARN_WATER_SPARKLES): where a.x^2 * sparkle_amount > 1 and (with two
 *     maps) b.x^2 * sparkle_amount > 1: C += sparkle_colour.
 * 11. Each channel rounded to nearest and clamped to 0..255.
 * Time is the frame's time_ms / 1000 seconds; pan offsets wrap every texture repeat. */
#ifndef TARN_WATER_H
#define TARN_WATER_H

#include <stdint.h>
#include "tarn_fixed.h"
#include "tarn_scene.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    TARN_WATER_FOG = 1u << 0,
    TARN_WATER_ABSORPTION = 1u << 1,
    TARN_WATER_DEPTH_COLOUR = 1u << 2,
    TARN_WATER_REFRACTION = 1u << 3,
    TARN_WATER_NORMALS = 1u << 4,
    TARN_WATER_FRESNEL = 1u << 5,
    TARN_WATER_SPECULAR = 1u << 6,
    TARN_WATER_FOAM = 1u << 7,
    TARN_WATER_SPARKLES = 1u << 8
};

/* The features whose terms move with the clock (from the panning maps and the foam
 * lines' phase); a still-water backdrop (tarn_scene.h) holds the others drawn. */
#define TARN_WATER_MOVING (TARN_WATER_NORMALS | TARN_WATER_SPECULAR | TARN_WATER_FOAM | TARN_WATER_SPARKLES)

/* The widest apron any frame renders: a material whose refraction could reach
 * farther is malformed (tarn_water_reach_pixels). */
#define TARN_WATER_APRON_MAX 32u

typedef struct {
    tarn_q16 scale;   /* Q16.16 texture repeats per mesh uv unit, > 0 */
    tarn_q16 speed_u; /* Q16.16 texture repeats per second, |speed| <= 16 */
    tarn_q16 speed_v;
} tarn_panning;

struct tarn_water {
    uint32_t features;        /* TARN_WATER_* bits */
    uint32_t albedo_rgb;      /* surface colour S without depth colour */
    tarn_q16 alpha;           /* Q16.16 in [0, 1]: opacity of the surface colour */

    uint32_t fog_rgb;
    tarn_q16 fog_density;     /* Q16.16 per world unit, 0..64 */

    uint32_t absorb_rgb;      /* the water colour; its inverse is absorbed */
    tarn_q16 absorption;      /* Q16.16 k per world unit (per unit^2 when squared), 0..64 */
    uint8_t absorption_squared;

    uint32_t shallow_rgb, deep_rgb;
    tarn_q16 depth_scale;     /* Q16.16 world units from shallow to deep, > 0 */
    const tarn_texture *colour_ramp; /* NULL: shallow and deep colours */

    const tarn_texture *normal_a, *normal_b; /* b may be NULL */
    tarn_panning pan_a, pan_b;
    tarn_q16 normal_strength; /* Q16.16, 0..8 */
    tarn_q16 normal_xy_max;   /* Q16.16 in [0, 1]: bound on |N.x| and |N.y| over the maps
                                 (the host computes it), which sizes the apron */

    tarn_q16 refraction;      /* Q16.16 in [0, 1]: offset per unit normal, in frame widths */

    tarn_q16 fresnel;         /* Q16.16 in [0, 1] */
    tarn_q16 specular;        /* Q16.16 intensity, 0..4 */
    uint16_t specular_power;  /* 1..256 */

    const tarn_texture *foam_texture;
    tarn_panning foam_pan;
    tarn_q16 foam_distance;   /* Q16.16 world units, > 0 */
    tarn_q16 foam_line_speed; /* Q16.16 band fractions per second, |speed| <= 16 */
    uint8_t foam_line_count;  /* lines across the band, 0..16 */
    uint32_t foam_rgb;
    tarn_q16 foam_opacity;    /* Q16.16 in [0, 1] */

    tarn_q16 sparkle_amount;  /* Q16.16, > 0: larger makes more sparkles */
    uint32_t sparkle_rgb;
};

/* The camera below the water plane: every pixel of the frame is displaced by a
 * panning normal map and tinted with depth, after the opaque and water passes:
 *   offset = N.xy * distortion * width pixels, N from `normal_map` at screen
 *   (x / width, y / width) * scale + time * speed; q = p + round(offset), clamped;
 *   C = C(q) + (tint - C(q)) * (1 - exp2(-tint_density * d(q))), d the linear depth
 *   at q (far where nothing was drawn). */
struct tarn_underwater {
    tarn_q16 level;           /* Q16.16 world y of the water surface */
    const tarn_texture *normal_map;
    tarn_panning pan;
    tarn_q16 distortion;      /* Q16.16 in [0, 1], frame widths per unit normal */
    uint32_t tint_rgb;
    tarn_q16 tint_density;    /* Q16.16 per world unit, 0..64 */
};

/* Pixels a material's refraction can reach at this frame width:
 * ceil(refraction * width * normal_xy_max), 0 without refraction. */
int32_t tarn_water_reach_pixels(const tarn_water *water, uint16_t frame_width);

#ifdef __cplusplus
}
#endif

#endif
