/* depth_code.c: the range of near/d over which the 16-bit depth code is one shift
 * and one add (tarn_depth_range, raster_internal.h), found where a pixel's near/d
 * leaves the last one. */
#include "raster/raster_internal.h"

static void set_range(tarn_depth_range *r, uint32_t low, uint32_t width, unsigned shift, uint32_t offset)
{
    r->low = low;
    r->width = width;
    r->shift = (uint8_t)shift;
    r->offset = offset;
}

/* tarn_depth16_encode of q clamped to [1, 2^30], and of every q around it that
 * codes alike: those below 1 code as 1, those above 2^30 as 2^30; up to 2^17 the
 * code is q >> 4 (1 below 16, where it must not be 0), and above, the 12 bits
 * under q's leading one after its exponent, which is q shifted by where that one
 * sits, less the one, plus the exponent. */
void tarn__depth_range_find(tarn_depth_range *r, uint32_t q)
{
    const uint32_t one = TARN_T_ONE;
    if (q == 0u)
        set_range(r, 0u, 1u, 0u, 1u);
    else if (q >= 0x80000000u)
        set_range(r, 0x80000000u, 0x80000000u, 31u, 0u); /* negative: q >> 31 is 1 */
    else if (q < 16u)
        set_range(r, 1u, 15u, 4u, 1u);
    else if (q < (1u << 17))
        set_range(r, 16u, (1u << 17) - 16u, 4u, 0u);
    else if (q >= one)
        set_range(r, one, one, 30u, tarn_depth16_encode(one) - 1u); /* q >> 30 is 1 */
    else {
        const unsigned top = 31u - tarn_clz32(q); /* 17..29 */
        set_range(r, 1u << top, 1u << top, top - 12u, (top - 16u) << 12);
    }
}
