/* water_foam.c: step 9 of tarn_water.h, the foam band along the shore and its moving
 * lines (TARN_WATER_FOAM). */
#include "water/water_internal.h"

#define Q16_ONE 65536u

uint32_t tarn__water_foam_band(const tarn_water_context *w, uint32_t diff)
{
    return w->water->foam_texture == NULL ? Q16_ONE : tarn__water_mul_q16(diff, w->inv_foam_distance);
}

int tarn__water_foam(const tarn_water_context *w, const tarn_water_input *in, uint32_t f)
{
    const tarn_water *water = w->water;
    if (f >= Q16_ONE) return 0;
    const uint16_t turns = (uint16_t)(water->foam_line_count * (f - w->foam_phase));
    int32_t wave = tarn_sin_q15(turns);
    uint32_t lines = wave > 0 ? ((uint32_t)wave * ((Q16_ONE - f) >> 1)) >> 14 : 0u; /* Q0.16 */
    /* foam where red / 255 >= f - lines: compared exactly, red * 2^16 against 255 * (f - lines) */
    const int32_t red =
        tarn__water_panned_texel(water->foam_texture, w->foam_texel_bytes, &water->foam_pan, w->foam_pan, in)[0];
    return red * 65536 >= 255 * ((int32_t)f - (int32_t)lines); /* both below 2^24 */
}

void tarn__water_foam_over(const tarn_water_context *w, uint32_t colour[3])
{
    const tarn_water *water = w->water;
    /* colour + (foam - colour) * opacity. The colour may be brighter than 255 here
     * (specular adds up to four times the light before the final clamp: below 2^19
     * in Q8.8), so the difference times the opacity can pass 2^31: a 16x16-bit high
     * product takes it. */
    const uint32_t opacity_q15 = (uint32_t)water->foam_opacity >> 1; /* [0, 1] by the scene check */
    for (int c = 0; c < 3; c++) {
        const int32_t foam = (int32_t)tarn__water_channel_q8(water->foam_rgb, c);
        const int32_t under = (int32_t)colour[c];
        /* (foam - under) * 2^6 * opacity * 2^11 / 2^32 = (foam - under) * opacity / 2^15 */
        colour[c] = (uint32_t)(under + tarn_mul_hi_s32_u32((foam - under) * 64, opacity_q15 << 11));
    }
}
