/* underwater.c: the underwater view, per pixel in 32-bit products. */
#include "water/underwater_internal.h"

static uint32_t depth_q30(const tarn_underwater_context *u, int32_t offset)
{
    if (tarn__depth_is_16_bits(u->depth_bits)) return tarn_depth16_decode(((const uint16_t *)u->depth)[offset]);
    return ((const uint32_t *)u->depth)[offset];
}

/* The pixel the displacement at (i, j) samples. */
static int32_t displaced_offset(const tarn_underwater_context *u, int32_t i, int32_t j)
{
    const tarn_underwater *under = u->under;
    /* screen (x / width, y / width) at the pixel centre, Q0.16, then panned */
    const uint32_t sx = tarn_mul_hi_u32((uint32_t)(2 * i + 1) << 16, u->screen_u_per_half);
    const uint32_t sy = tarn_mul_hi_u32((uint32_t)(2 * j + 1) << 16, u->screen_u_per_half);
    const uint32_t fu = tarn__water_map_fraction(sx, 0u, (uint32_t)under->pan.scale) + u->pan[0];
    const uint32_t fv = tarn__water_map_fraction(sy, 0u, (uint32_t)under->pan.scale) + u->pan[1];
    const uint8_t *texel = tarn__water_texel_at(under->normal_map, fu >> 16, fv >> 16, 3u); /* R G B */
    int32_t target[2] = {i, j};
    for (int k = 0; k < 2; k++) {
        /* N (Q1.15) * pixels per unit normal (Q16.16) / 2^23 -> pixels, Q24.8 */
        int32_t offset_q8 = tarn_mul_hi_s32_u32(tarn__water_normal_component(texel[k]) * 512, u->distortion_px);
        const int32_t offset = tarn_floor_shift(tarn_clamp_i32(offset_q8, -(64 << 8), 64 << 8) + 128, 8);
        target[k] += tarn_clamp_i32(offset, -u->offset_limit, u->offset_limit);
    }
    const int32_t x = tarn_clamp_i32(target[0], u->sample_rect.x0, u->sample_rect.x1 - 1);
    const int32_t y = tarn_clamp_i32(target[1], u->sample_rect.y0, u->sample_rect.y1 - 1);
    return (y - u->origin_y) * u->stride + (x - u->origin_x);
}

static uint32_t tinted(const tarn_underwater_context *u, int32_t offset)
{
    const uint32_t d = tarn__water_linear_depth(depth_q30(u, offset), &u->linear);
    const uint32_t argument = tarn__fog_argument_q16((uint32_t)u->under->tint_density, d, u->fog_argument_bits);
    const uint32_t keep = tarn_exp2_neg_q16(-(tarn_q16)argument, u->exp2) >> 1; /* Q1.15 */
    const uint32_t rgb = u->colour[offset];
    uint32_t out = 0;
    for (int c = 0; c < 3; c++) {
        const int32_t below = (int32_t)(((rgb >> (16 - 8 * c)) & 0xFFu) << 8);
        const int32_t tint = (int32_t)(((u->under->tint_rgb >> (16 - 8 * c)) & 0xFFu) << 8);
        const int32_t mixed = tint + ((below - tint) * (int32_t)keep) / 32768; /* Q8.8 */
        const int32_t byte = (mixed + 128) >> 8;
        out = (out << 8) | (uint32_t)(byte > 255 ? 255 : (byte < 0 ? 0 : byte));
    }
    return out;
}

void tarn__underwater_tile(const tarn_underwater_context *u, const tarn_pixel_rect *rect,
                          uint32_t *out, int32_t out_stride)
{
    for (int32_t j = rect->y0; j < rect->y1; j++)
        for (int32_t i = rect->x0; i < rect->x1; i++)
            out[(j - rect->y0) * out_stride + (i - rect->x0)] = tinted(u, displaced_offset(u, i, j));
}
