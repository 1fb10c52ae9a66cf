/* water_common.c: what the steps of the water pixel share, each a leaf: 32-bit
 * products, texels of a repeating map, linear depths and the opaque background. */
#include "water/water_internal.h"

/* a * b / 2^16 for unsigned Q16.16 values, saturated to INT32_MAX: 16x16-bit
 * partial products summed in 64 bits (adds only; no divider, no 64-bit multiply). */
uint32_t tarn__water_mul_q16(uint32_t a, uint32_t b)
{
    const uint32_t ah = a >> 16, al = a & 0xFFFFu, bh = b >> 16, bl = b & 0xFFFFu;
    const uint64_t sum = ((uint64_t)(ah * bh) << 16) + ah * bl + al * bh + ((al * bl) >> 16);
    return sum > (uint64_t)INT32_MAX ? (uint32_t)INT32_MAX : (uint32_t)sum;
}

uint32_t tarn__fog_argument_q16(uint32_t rate, uint32_t x, unsigned bits)
{
    if (bits >= 16u) return tarn__water_mul_q16(rate, x);
    /* Only the depth is cut: a density is set once and may be tiny, and cutting it
     * would lose all of a thin fog. */
    const uint32_t depth = x >> (16u - bits); /* Q.bits */
    if ((rate | depth) < 65536u) return (rate * depth) >> bits; /* below 2^31 for bits >= 1 */
    return tarn__water_mul_q16(rate, depth << (16u - bits));
}

uint32_t tarn__squared_argument_q16(uint32_t rate, uint32_t x)
{
    if (rate == 0u || x == 0u) return 0u;
    /* x^2 would saturate Q16.16 from x = 181 while a weak rate keeps the product
     * small: each factor is kept as a mantissa (top bit set) and a power of two, like
     * a small float, so nothing saturates before the whole product does. */
    const unsigned x_shift = tarn_clz32(x), rate_shift = tarn_clz32(rate);
    const uint32_t x_mantissa = x << x_shift;
    const uint32_t square = tarn_mul_hi_u32(x_mantissa, x_mantissa); /* x^2 ~ square * 2^(32 - 2 x_shift) */
    const uint32_t product = tarn_mul_hi_u32(square, rate << rate_shift); /* at least 2^29 */
    /* rate * x^2 / 2^32, the Q16.16 product, = product * 2^(32 - 2 x_shift - rate_shift) */
    const int up = 32 - 2 * (int)x_shift - (int)rate_shift;
    if (up <= -32) return 0u;
    if (up <= 0) {
        const uint32_t down = product >> -up;
        return down > (uint32_t)INT32_MAX ? (uint32_t)INT32_MAX : down;
    }
    return up >= 31 || product > ((uint32_t)INT32_MAX >> up) ? (uint32_t)INT32_MAX : product << up;
}

const uint8_t *tarn__water_texel_at(const tarn_texture *t, uint32_t u_fraction, uint32_t v_fraction,
                                    unsigned texel_bytes)
{
    /* For a power-of-two side, fraction * side / 2^16 is the shift by 16 - log2(side)
     * without finding the log: one multiply, where clz costs the M0 a dozen
     * instructions. Exact: the fraction is below 2^16 and a side at most 2^10. */
    const uint32_t x = (u_fraction * t->width) >> 16, y = (v_fraction * t->height) >> 16;
    return &t->rgb[texel_bytes * (y * t->width + x)];
}

void tarn__linear_depth_setup(tarn_linear_depth *d, tarn_q16 near, tarn_q16 far, unsigned recip_steps)
{
    d->near_shift = tarn_clz32((uint32_t)near); /* near > 0 (tarn__scene_check) */
    d->near_mantissa = (uint32_t)near << d->near_shift;
    d->far = far;
    d->recip_steps = recip_steps;
}

/* near * recip * 2^(lz - 32), saturated: the linear depth of a near/d whose
 * reciprocal is `recip` once shifted up by lz. */
static inline uint32_t linear_depth_from(uint32_t recip, unsigned lz, const tarn_linear_depth *d)
{
    const unsigned near_shift = d->near_shift;
    /* near pre-shifted for precision */
    const uint32_t scaled = tarn_mul_hi_u32(d->near_mantissa, recip);
    if (lz >= near_shift) {
        unsigned up = lz - near_shift;
        return up >= 31u || scaled > ((uint32_t)INT32_MAX >> up) ? (uint32_t)INT32_MAX : scaled << up;
    }
    return scaled >> (near_shift - lz);
}

uint32_t tarn__water_linear_depth_of(const tarn_depth_reciprocal *iz, const tarn_linear_depth *d)
{
    return linear_depth_from(iz->recip, iz->lz, d);
}

uint32_t tarn__water_linear_depth(uint32_t iz_q30, const tarn_linear_depth *d)
{
    if (iz_q30 == 0u) return (uint32_t)d->far;
    const unsigned lz = tarn_clz32(iz_q30);
    return linear_depth_from(tarn_recip_q30(iz_q30 << lz, d->recip_steps), lz, d); /* 2^62 / (iz << lz) */
}

static uint32_t background_depth_q30(const tarn_water_context *w, int32_t offset)
{
    if (tarn__depth_is_16_bits(w->depth_bits)) return tarn_depth16_decode(((const uint16_t *)w->background_depth)[offset]);
    return ((const uint32_t *)w->background_depth)[offset];
}

uint32_t tarn__water_decay(const tarn_water_context *w, uint32_t rate, uint32_t x)
{
    return tarn_exp2_neg_q16(-(tarn_q16)tarn__fog_argument_q16(rate, x, w->fog_argument_bits), w->exp2);
}

uint32_t tarn__water_background_q30(const tarn_water_context *w, int32_t i, int32_t j)
{
    return background_depth_q30(w, tarn__water_background_offset(w, i, j));
}

tarn_water_sample tarn__water_background(const tarn_water_context *w, int32_t i, int32_t j)
{
    tarn_water_sample s = {i, j, tarn__water_depth_of(w, tarn__water_background_q30(w, i, j))};
    return s;
}
