/* quality.c: the named presets. Their values come from the sweep of docs/sweep.md
 * (`make sweep-docs`): each is a point on the pond's measured front. */
#include "tarn_render.h"

static tarn_quality preset_balanced(void)
{
    tarn_quality q;
    q.exp2.entries = 64;
    q.exp2.interpolate = 1;
    q.recip_newton_steps = 2;
    q.subpixel_bits = 4;
    q.perspective = TARN_PERSPECTIVE_PIXEL;
    q.perspective_span = 16;
    q.depth_bits = 32;
    q.tile_size = 32;
    q.refraction_apron = TARN_APRON_FULL;
    q.cluster_bins = 1;
    q.fog_argument_bits = 16;
    return q;
}

tarn_quality tarn_quality_preset(tarn_preset preset)
{
    tarn_quality q = preset_balanced();
    if (preset == TARN_PRESET_FAST) {
        q.exp2.entries = 16;
        q.exp2.interpolate = 0;
        q.recip_newton_steps = 1;
        q.perspective = TARN_PERSPECTIVE_SPAN;
        q.depth_bits = 16;
        q.refraction_apron = 0;
        q.fog_argument_bits = 8;
    } else if (preset == TARN_PRESET_EXACT) {
        q.exp2.entries = 256;
    }
    return q;
}

const char *tarn_preset_name(tarn_preset preset)
{
    switch (preset) {
    case TARN_PRESET_FAST: return "fast";
    case TARN_PRESET_BALANCED: return "balanced";
    case TARN_PRESET_EXACT: return "exact";
    }
    return NULL;
}

tarn_quality tarn_quality_default(void)
{
    return tarn_quality_preset(TARN_PRESET_BALANCED);
}
