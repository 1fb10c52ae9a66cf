/* quality_text.h: a quality as the options that give it, the words the sweep's
 * CSV and points files hold, `tarn view` prints as a render command, and every
 * QUALITY parser (quality_options.h) reads back to the same quality. */
#ifndef TARN_HOST_QUALITY_TEXT_H
#define TARN_HOST_QUALITY_TEXT_H

#include <stddef.h>
#include "tarn/tarn_render.h"

/* Room for tarn_quality_text's words. */
#define TARN_QUALITY_TEXT_MAX 512

/* Every knob as tarn's options, e.g. "--perspective span:16 --recip-steps 1 ...
 * --refraction-normal shared --lit line", then " --frame strips" and " --vertices frame"
 * when the quality asks for them. */
void tarn_quality_text(const tarn_quality *q, char *out, size_t size);

/* The perspective and apron knobs as their options' values ("span:16", "off"):
 * `buffer` holds the text when it is not a constant. */
const char *tarn_quality_perspective_text(const tarn_quality *q, char *buffer, size_t size);
const char *tarn_quality_apron_text(const tarn_quality *q, char *buffer, size_t size);
/* "exact" or "plane": the quality's --depth-interpolation. */
const char *tarn_quality_depth_text(const tarn_quality *q);

#endif
