/* presets.c: the named presets. Their values come from the sweep (docs/sweep.md,
 * `make sweep-docs`) on tarn compare's yardstick; the figures behind each choice are
 * in docs/sweep.md and docs/firmware.md, measured, not here:
 *  - subpixel bits move edges and texels least at the most bits, and cost nothing,
 *    but each bit halves the largest frame the edge functions hold: 4 bits take
 *    every frame up to TARN_FRAME_SIZE_MAX, 5 up to 640 pixels a side, 6 refuse
 *    320x240. The default must draw any frame, so balanced and fast keep 4; exact
 *    takes 5;
 *  - balanced: one Newton step, a 64-entry exp2 table and a 12-bit fog argument
 *    measure within the rounding of exact's knobs on the scenes and the extremes
 *    (8 bits banded the shallow strip of dense fog, scenes/extremes/dense.json),
 *    and refraction moves by the exact normal (TARN_REFRACTION_NORMAL_EXACT): the
 *    shared one moves a refracted sample to a neighbour on about 0.15% of the
 *    pond's pixels; a lit colour on a line is found from one channel
 *    (TARN_LIT_LINE), within the rounding of the vertices' colours; flat water's
 *    texture coordinates come from its plane (TARN_WATER_UV_PLANE), which the
 *    subpixel grid cannot move (docs/figures.md, "Flat water");
 *  - exact: every knob at its most accurate;
 *  - fast: the Cortex-M0's choice, from its meshes. Its 16 KB hold no full
 *    refraction apron, and an apron that fits needs small tiles, each drawing the
 *    opaque scene around itself again (several times the instructions: docs/
 *    firmware.md, "Refraction in 16 KB"), so the preset keeps none and a board that
 *    can pay opts in with --apron N --tile T; over a still-water backdrop an apron
 *    takes no RAM, refracted samples being read from the picture. Without an apron
 *    the water pass draws in place, so 16-bit depth and 40-pixel tiles fit, span
 *    perspective and one Newton step are on the M0's front, and the smallest exp2
 *    table and fog argument cost nothing visible. Water blocks (2x2) save a fifth
 *    of the M0's instructions without refraction and cost next to nothing there;
 *    with refraction they save nothing (refracted effects are never shared), so
 *    only fast takes them. Depth stepped on a plane saves three exact divisions a
 *    triangle; the images differ from exact depth's only where surfaces meet.
 *    The refraction normal is the shared one: the exact one costs the still-water
 *    board more for nothing visible at this preset. Water interpolates its texture
 *    coordinates on its triangles: the plane's (the other presets',
 *    TARN_WATER_UV_PLANE) are about 2.5 KB of code the 16 KB board's 32 KB
 *    budget has not left. */
#include "tarn/tarn_render.h"

static tarn_quality preset_exact(void)
{
    tarn_quality q;
    q.exp2.entries = 256;
    q.exp2.interpolate = 1;
    q.recip_newton_steps = 2;
    q.subpixel_bits = 5;
    q.perspective = TARN_PERSPECTIVE_PIXEL;
    q.perspective_span = 16;
    q.depth_bits = 32;
    q.depth_interpolation = TARN_DEPTH_EXACT;
    q.tile_size = 32;
    q.refraction_apron = TARN_APRON_FULL;
    q.cluster_bins = 1;
    q.fog_argument_bits = 16;
    q.water_block = 1;
    q.refraction_normal = TARN_REFRACTION_NORMAL_EXACT;
    q.frame_shape = TARN_FRAME_TILES;
    q.vertex_pass = TARN_VERTICES_PER_TILE;
    q.lit_colour = TARN_LIT_PLANES;
    q.water_coordinates = TARN_WATER_UV_PLANE;
    return q;
}

tarn_quality tarn_quality_preset(tarn_preset preset)
{
    tarn_quality q = preset_exact();
    if (preset == TARN_PRESET_BALANCED || preset == TARN_PRESET_FAST) {
        q.subpixel_bits = 4;
        q.exp2.entries = 64;
        q.recip_newton_steps = 1;
        q.fog_argument_bits = 12;
        q.lit_colour = TARN_LIT_LINE;
    }
    if (preset == TARN_PRESET_FAST) {
        q.exp2.entries = 16;
        q.exp2.interpolate = 0;
        q.perspective = TARN_PERSPECTIVE_SPAN;
        q.depth_bits = 16;
        q.depth_interpolation = TARN_DEPTH_PLANE;
        q.tile_size = 40;
        q.refraction_apron = 0;
        q.fog_argument_bits = 6;
        q.water_block = 2;
        q.refraction_normal = TARN_REFRACTION_NORMAL_SHARED;
        q.water_coordinates = TARN_WATER_UV_TRIANGLES;
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
