/* water_fog.c: steps 4 and 5 of tarn_water.h, what the water between the surface and
 * the background does to it: fog (TARN_WATER_FOG) and absorption
 * (TARN_WATER_ABSORPTION). `diff` is that depth of water, Q16.16 world units. */
#include "water/water_internal.h"

#define Q16_ONE 65536u

uint32_t tarn__water_fog(const tarn_water_context *w, uint32_t diff)
{
    return tarn__water_decay(w, (uint32_t)w->water->fog_density, diff) >> 1;
}

void tarn__water_absorb(const tarn_water_context *w, uint32_t diff, uint16_t loss[3])
{
    const tarn_water *water = w->water;
    const uint32_t rate = (uint32_t)water->absorption;
    const uint32_t decay = water->absorption_squared
        ? tarn_exp2_neg_q16(-(tarn_q16)tarn__squared_argument_q16(rate, diff), w->exp2)
        : tarn__water_decay(w, rate, diff);
    const uint32_t absorbed = (Q16_ONE - decay) >> 1; /* Q1.15 */
    for (int c = 0; c < 3; c++) {
        const uint32_t inverse = 65280u - tarn__water_channel_q8(water->absorb_rgb, c);
        loss[c] = (uint16_t)((inverse * absorbed) >> 15);
    }
}
