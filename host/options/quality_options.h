/* quality_options.h: the QUALITY options every rendering command takes (tarn render,
 * compare, memory, bake and show), a points file's lines (bake_points.h) and the
 * sweep's grid (sweep_grid.h):
 *   --quality fast|balanced|exact   a preset (core/scene/presets.c) as the base of the others
 *   --tile N (8..64)  --subpixel N (1..8)  --perspective affine|pixel|span:N
 *   --depth 16|32  --depth-interpolation exact|plane  --recip-steps N (0..2)
 *   --exp2 N[:nearest|:linear] (8..256)
 *   --apron on|off|N  --bins on|off  --fog-bits N (4..16)  --water-block 1|2|4 */
#ifndef TARN_HOST_QUALITY_OPTIONS_H
#define TARN_HOST_QUALITY_OPTIONS_H

#include "error.h"
#include "tarn/tarn_render.h"

/* One QUALITY option: TARN_OPTION_VALUE (0) when `name` was applied to `quality`,
 * TARN_OPTION_UNKNOWN (1) when it is not a quality option (option_values.h), -1
 * with `err` set for a bad value. --quality is only checked here: call
 * tarn_cli_apply_preset on the whole list first, so that a preset is the base the
 * other knobs change wherever they stand. */
int tarn_cli_parse_quality_option(const char *name, const char *value, tarn_quality *quality,
                                  tarn_error *err);

/* Applies the list's --quality NAME to `quality`, if it has one: 0, or -1 with
 * `err` set for an unknown name or a second --quality. */
int tarn_cli_apply_preset(int argc, char *const argv[], tarn_quality *quality, tarn_error *err);

/* The knobs' constraints on each other, once every option is applied: 0, or -1
 * with `err` naming the options (--water-block 2 needs an even --tile). */
int tarn_cli_check_quality(const tarn_quality *q, tarn_error *err);

#endif
