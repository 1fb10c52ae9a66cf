/* quality_text.c: a quality as its options (quality_text.h). */
#include "quality_text.h"

#include <stdio.h>
#include <string.h>

const char *tarn_quality_perspective_text(const tarn_quality *q, char *buffer, size_t size)
{
    if (q->perspective == TARN_PERSPECTIVE_AFFINE) return "affine";
    if (q->perspective == TARN_PERSPECTIVE_PIXEL) return "pixel";
    snprintf(buffer, size, "span:%u", (unsigned)q->perspective_span);
    return buffer;
}

const char *tarn_quality_apron_text(const tarn_quality *q, char *buffer, size_t size)
{
    if (q->refraction_apron == TARN_APRON_FULL) return "on";
    if (q->refraction_apron == 0) return "off";
    snprintf(buffer, size, "%u", (unsigned)q->refraction_apron);
    return buffer;
}

const char *tarn_quality_depth_text(const tarn_quality *q)
{
    return q->depth_interpolation == TARN_DEPTH_PLANE ? "plane" : "exact";
}

void tarn_quality_text(const tarn_quality *q, char *out, size_t size)
{
    char span[16], apron[16];
    snprintf(out, size,
             "--perspective %s --recip-steps %u --depth %u --apron %s --exp2 %u:%s --fog-bits %u "
             "--subpixel %u --tile %u --bins %s --water-block %u --depth-interpolation %s --refraction-normal %s "
             "--lit %s --water-uv %s",
             tarn_quality_perspective_text(q, span, sizeof span), (unsigned)q->recip_newton_steps,
             (unsigned)q->depth_bits, tarn_quality_apron_text(q, apron, sizeof apron), (unsigned)q->exp2.entries,
             q->exp2.interpolate ? "linear" : "nearest", (unsigned)q->fog_argument_bits,
             (unsigned)q->subpixel_bits, (unsigned)q->tile_size, q->cluster_bins ? "on" : "off",
             (unsigned)q->water_block, tarn_quality_depth_text(q),
             q->refraction_normal == TARN_REFRACTION_NORMAL_EXACT ? "exact" : "shared",
             q->lit_colour == TARN_LIT_LINE ? "line" : "planes",
             q->water_coordinates == TARN_WATER_UV_PLANE ? "plane" : "triangles");
    if (q->frame_shape == TARN_FRAME_STRIPS) {
        const size_t used = strlen(out);
        snprintf(out + used, size - used, " --frame strips");
    }
    if (q->vertex_pass != TARN_VERTICES_PER_TILE) {
        const size_t used = strlen(out);
        snprintf(out + used, size - used, " --vertices %s",
                 q->vertex_pass == TARN_VERTICES_PER_FRAME_VIEW ? "frame-view" : "frame");
    }
}
