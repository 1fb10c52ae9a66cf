/* presets.c: the named presets. Their values come from the pond's sweep
 * (docs/sweep.md, `make sweep-docs`), measured against the float reference on its
 * finest subpixel grid:
 *  - subpixel bits are the largest knob of error and cost nothing, but each bit
 *    halves the largest frame the edge functions hold: 4 bits take every frame up
 *    to TARN_FRAME_SIZE_MAX, 5 up to 640 pixels a side, 6 refuse 320x240. The
 *    default must draw any frame, so balanced and fast keep 4; exact takes 5;
 *  - balanced: one Newton step measures within 0.01 dB of two on the pond, for
 *    less cost. The fog argument keeps 12 bits of the depth of water: 8 cut the
 *    argument of dense water (density 64, scenes/extremes/dense.json) into steps
 *    of 2^-0.25 and banded its shallow strip (62.5 dB, 0.26% of pixels more than
 *    2 levels off; 71.9 dB and none at 12), and the product stays one multiply
 *    below 16 units of water, so 12 cost the host 0 to 0.5% (pond nothing, the
 *    lake 0.46%); 16 take the wide product everywhere;
 *  - exact: every knob at its most accurate;
 *  - fast: the Cortex-M0's choice, from its meshes. Its 16 KB hold no full
 *    refraction apron; without one the water pass draws in place, so 16-bit depth
 *    and 40-pixel tiles fit (the baked pond's 11,040 bytes of the board's ~11,800:
 *    bigger tiles walk each cluster fewer times, and 42 no longer fits), span
 *    perspective and one Newton step are on the M0's front, and the smallest exp2
 *    table and fog argument cost nothing visible once refraction is gone.
 *    An apron that fits 16 KB needs small tiles, each drawing the opaque scene
 *    around itself again. On the M0 (tarn compare scenes/pond.json, make
 *    firmware-run BOARD=qemu-m0 with the flags in BAKE_FLAGS; docs/firmware.md,
 *    "Refraction in 16 KB") the pond measures 21.47 dB for 1286 instructions a
 *    pixel without one; without water blocks, with apron 4 and 24-pixel tiles
 *    23.22 dB for 2566, 8 and 20 25.69 dB for 3488, 12 and 16 29.19 dB for 5408
 *    (the qemu-m0 board's bake), 16 and 8 32.87 dB for 17534; the full apron (32
 *    pixels here) fits no tile. So the preset keeps none, and a board that can pay
 *    the instructions opts in with --apron N --tile T. Over a still-water backdrop
 *    an apron takes no RAM at all, refracted samples being read from the picture:
 *    qemu-m0-still bakes --apron on (32.57 dB for 698).
 *    Without refraction, water blocks cost the pond 0.14 dB for 20% of the M0's
 *    instructions (1319 against 1648); with it they save next to nothing
 *    (refracted effects are never shared: 3499 against 3488 at apron 8) and cost
 *    up to 2.6 dB, so only fast takes them. 4x4 blocks cost the M0 more from the
 *    meshes (1378), since fewer pixels share a block with one triangle over one
 *    depth; over still water, where a block shares only its highlight, they are
 *    the board's choice (docs/bake.md).
 *    Fast also steps depth on a plane (TARN_DEPTH_PLANE): three exact divisions
 *    less a triangle and a plain add a pixel, 6% of the M0's instructions (1319
 *    against 1399), the pond the same to 0.01 dB; its images differ from exact
 *    depth's in a few pixels where surfaces meet. Fast stays below balanced (the
 *    pond: 21.47 dB against 43.60, tarn compare --quality). */
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
