/* water_load.h: a material's "water" block and the scene's "underwater" block.
 *
 *   "water": {                                       every field optional
 *     "albedo": "#rrggbb", "alpha": 0..1,            surface colour and its opacity
 *     "fog": {"colour", "density": 0..64},
 *     "absorption": {"colour", "strength": 0..64, "squared": false},
 *     "depth_colour": {"shallow", "deep", "scale": > 0, "ramp": "file.png"},
 *     "normal_maps": [{"image": "file.png", "scale": > 0, "speed": [u, v]}, ...],  1 or 2
 *     "normal_strength": 0..8,
 *     "refraction": 0..1,                            needs normal_maps
 *     "fresnel": 0..1,
 *     "specular": {"intensity": 0..4, "power": 1..256},
 *     "foam": {"texture", "scale", "speed", "distance": > 0, "line_speed", "lines": 0..16,
 *              "colour", "opacity": 0..1},
 *     "sparkles": {"amount": > 0, "colour"} }        needs normal_maps
 *   "underwater": {"level": y, "normal_map": {"image", "scale", "speed"},
 *                  "distortion": 0..1, "tint": {"colour", "density": 0..64}}
 * A feature's TARN_WATER_* flag is set exactly when its block or field is present.
 * Speeds are texture repeats (or foam bands) per second, each within -16..16.
 * docs/scene-format.md has the table with every default. */
#ifndef TARN_HOST_WATER_LOAD_H
#define TARN_HOST_WATER_LOAD_H

#include <stdint.h>
#include "scene_fields.h"
#include "tarn/tarn_water.h"

/* The "water" block of `material` (at field path `parent`, "materials.NAME"), if
 * any, into `out`; *present says whether there was one. Refraction must reach no
 * farther than TARN_WATER_APRON_MAX pixels (tarn_water_reach_pixels) at `frame_width`. */
int tarn_water_load(tarn_loader *l, const json_t *material, const char *parent,
                    uint16_t frame_width, tarn_water *out, int *present);

/* The top-level "underwater" block, if any. */
int tarn_underwater_load(tarn_loader *l, const json_t *root, tarn_underwater *out, int *present);

/* Q16.16 upper bound on |N.x| and |N.y| of step 1 of tarn_water.h for these maps
 * (b may be NULL) at this strength, at most 1.0. One map: the exact maximum over
 * its texels. Two: panning lets any texel of a meet any of b, and
 * |N.x| <= s(|a.x| + |b.x|) / sqrt(s^2 (|a.x| + |b.x|)^2 + (a.z b.z)^2), which grows with
 * the x terms and falls with |a.z b.z|: the maximum over each map's largest
 * max(|x|, |y|) for every smallest |z|. Rounded up. */
tarn_q16 tarn_water_normal_xy_max(const tarn_texture *a, const tarn_texture *b,
                                  tarn_q16 strength);

#endif
