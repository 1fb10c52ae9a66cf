/* water_fog.c: steps 4 and 5 of tarn_water.h, what the water between the surface and
 * the background does to it: fog (TARN_WATER_FOG) and absorption
 * (TARN_WATER_ABSORPTION). `diff` is that depth of water, Q16.16 world units. */
#include "water/water_internal.h"

#define Q16_ONE 65536u
/* The most halvings a colour moves away from the endless water's */
#define MOVED_HALVINGS_MAX 15u
#define FEW_HALVINGS 4096u /* 1/16, Q16.16 */
#define LN2_Q16 45426u     /* ln 2 */
#define UNSEEN_FALL 128u   /* 255 * 128 / 2^16 < 1/2 */

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

/* exp2(-density * (to - from)) as a mantissa (Q16.16, at most 1) times 2^up: below 1
 * where the water is deeper, up to 2^MOVED_HALVINGS_MAX where it is shallower. From
 * the whole table, interpolated, whatever the quality's exp2: the ratio of two of
 * its coarsest values strays by a step of the table, where the fog it moves keeps
 * within one of either value. */
static uint32_t fog_ratio(const tarn_water_context *w, uint32_t from, uint32_t to, unsigned *up)
{
    static const tarn_exp2_config whole_table = {TARN_EXP2_ENTRIES_MAX, 1u};
    const uint32_t density = (uint32_t)w->water->fog_density;
    const uint32_t more = to >= from ? to - from : from - to;
    uint32_t halvings = (density | more) < Q16_ONE ? (density * more) >> 16 : tarn__water_mul_q16(density, more);
    if (halvings < FEW_HALVINGS) {
        /* 2^-x = 1 - x ln 2 + (x ln 2)^2 / 2 - ...: within 2^-11 below 1/16 of a
         * halving, a pixel's move across most of the water */
        const uint32_t fall = (halvings * LN2_Q16) >> 16;
        *up = to >= from ? 0u : 1u;
        return to >= from ? Q16_ONE - fall : (Q16_ONE + fall) >> 1;
    }
    if (to >= from) {
        *up = 0u;
        return tarn_exp2_neg_q16(-(tarn_q16)halvings, whole_table);
    }
    if (halvings > MOVED_HALVINGS_MAX << 16) halvings = MOVED_HALVINGS_MAX << 16;
    *up = (halvings + 0xFFFFu) >> 16;
    return tarn_exp2_neg_q16(-(tarn_q16)((*up << 16) - halvings), whole_table);
}

uint32_t tarn__water_fog_moved(const tarn_water_context *w, uint32_t colour, uint32_t endless, uint32_t from,
                               uint32_t to)
{
    unsigned up;
    const int32_t mantissa = (int32_t)fog_ratio(w, from, to, &up);
    /* a ratio within UNSEEN_FALL / 2^16 of 1 moves no channel by half a level: the
     * colour stands as the rounding below would leave it */
    if ((up == 0u && mantissa > (int32_t)(Q16_ONE - UNSEEN_FALL)) ||
        (up == 1u && mantissa < (int32_t)((Q16_ONE + UNSEEN_FALL) >> 1)))
        return colour & 0xFFFFFFu;
    /* (colour - endless) * mantissa lies within +-2^24: lifted by 2^24, it shifts
     * down as a non-negative number, rounded, from 16 - up >= 1 bits */
    const unsigned shift = 16u - up;
    const uint32_t lift = 1u << 24, half = 1u << (shift - 1u);
    uint32_t rgb = 0u;
    for (unsigned at = 24u; at > 0u;) {
        at -= 8u;
        const int32_t end = (int32_t)((endless >> at) & 0xFFu);
        const int32_t away = (int32_t)((colour >> at) & 0xFFu) - end;
        const uint32_t lifted = (uint32_t)(away * mantissa) + lift + half;
        const int32_t v = end + (int32_t)(lifted >> shift) - (int32_t)(lift >> shift);
        rgb = (rgb << 8) | (uint32_t)(v < 0 ? 0 : (v > 255 ? 255 : v));
    }
    return rgb;
}
