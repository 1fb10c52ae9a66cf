/* water_setup.c: what a water context holds for one object in one tile: pan
 * offsets from the frame's time, the half vector in the object's tangent frame,
 * reciprocals of the material's distances, the plane its texture coordinates
 * come from (water_plane.c). 64-bit products are fine here, and
 * divisions through tarn_divide_*; the per-pixel files have neither. */
#include "water/water_internal.h"

#define Q15_ONE 32768

uint32_t tarn__water_pan_offset_q32(tarn_q16 speed, uint32_t time_ms)
{
    int64_t travelled = (int64_t)speed * time_ms; /* |speed| <= 2^20: below 2^52 */
    const tarn_divisor thousand = tarn_divisor_of(1000);
    uint32_t left; /* of the thousandths, in [0, 1000) */
    int64_t q16 = tarn_divide_floor_i64(travelled, &thousand, &left);
    const uint32_t below = (uint32_t)tarn_divide_u64((uint64_t)left << 16, &thousand, NULL);
    return ((uint32_t)((uint64_t)q16 & 0xFFFFu) << 16) + below;
}

/* floor(speed * time_ms / 1000) modulo one repeat, Q0.16: the Q0.32 offset's top
 * half (a floor of a floor). */
uint16_t tarn__water_pan_offset(tarn_q16 speed, uint32_t time_ms)
{
    return (uint16_t)(tarn__water_pan_offset_q32(speed, time_ms) >> 16);
}

/* 2^32 / x: the reciprocal of a Q16.16 distance in Q16.16, saturated. */
static uint32_t reciprocal_q16(tarn_q16 x)
{
    if (x <= 0) return UINT32_MAX;
    int64_t r = tarn_divide_once_i64((int64_t)1 << 32, (uint32_t)x);
    return r > (int64_t)UINT32_MAX ? UINT32_MAX : (uint32_t)r;
}

/* normalize(L + V) in the object's tangent frame (object x, z, y), Q1.15. */
static void half_vector(const tarn_view *view, const tarn_object *object, int32_t out[3])
{
    int64_t h[3] = {(int64_t)view->light_dir.x - (view->basis[2][0] >> 14),
                    (int64_t)view->light_dir.y - (view->basis[2][1] >> 14),
                    (int64_t)view->light_dir.z - (view->basis[2][2] >> 14)}; /* Q16.16 */
    uint64_t length2 = 0;
    for (int k = 0; k < 3; k++) length2 += (uint64_t)(h[k] * h[k]);
    const int64_t length = (int64_t)tarn_isqrt_u64(length2); /* below 2^32 */
    const tarn_divisor by_length = tarn_divisor_of((uint32_t)length);
    static const int axis_of[3] = {0, 2, 1}; /* tangent u = object x, v = object z, up = object y */
    for (int k = 0; k < 3; k++) {
        int64_t along = 0;
        for (int r = 0; r < 3; r++) along += h[r] * object->rotation[r][axis_of[k]]; /* Q32 */
        /* within +-1 for an orthonormal rotation; cut there for one that is not */
        const int64_t component = length > 0 ? tarn_divide_trunc_i64(along, &by_length) / 2 : (k == 2 ? Q15_ONE : 0);
        out[k] = (int32_t)(component > Q15_ONE ? Q15_ONE : (component < -Q15_ONE ? -Q15_ONE : component));
    }
}

void tarn__water_context_setup(tarn_water_context *w, const tarn_view *view,
                              const tarn_frame_config *config, const tarn_object *object)
{
    const tarn_water *water = object->material->water;
    w->water = water;
    w->object = object;
    w->features = TARN_LINK_WATER_FEATURES & water->features;
    w->width = config->width;
    w->height = config->height;
    tarn__linear_depth_setup(&w->linear, view->near, view->far, config->quality.recip_newton_steps);
    w->exp2 = config->quality.exp2;
    w->fog_argument_bits = config->quality.fog_argument_bits;
    w->block_shift = (uint8_t)(config->quality.water_block == 4 ? 2u : config->quality.water_block == 2 ? 1u : 0u);
    /* after features; the frame set offset_limit before the first context */
    w->exact_normal = (uint8_t)(TARN_LINK_REFRACTION_EXACT &&
                                config->quality.refraction_normal == TARN_REFRACTION_NORMAL_EXACT &&
                                tarn__water_refracts(w));
    const tarn_panning *pans[3] = {&water->pan_a, &water->pan_b, &water->foam_pan};
    uint32_t *offsets[3] = {w->pan_a, w->pan_b, w->foam_pan};
    for (int k = 0; k < 3; k++) {
        offsets[k][0] = tarn__water_pan_offset_q32(pans[k]->speed_u, config->time_ms);
        offsets[k][1] = tarn__water_pan_offset_q32(pans[k]->speed_v, config->time_ms);
    }
    w->foam_phase = tarn__water_pan_offset(water->foam_line_speed, config->time_ms);
    half_vector(view, object, w->half_vector);
    for (int c = 0; c < 3; c++) {
        w->light_q8[c] = ((view->light_q16[c] * 255u + 32768u) >> 16) << 8;
        w->fog_q8[c] = (w->features & TARN_WATER_FOG) != 0 ? tarn__water_channel_q8(water->fog_rgb, c) : 0u;
    }
    w->inv_depth_scale = reciprocal_q16(water->depth_scale);
    w->inv_foam_distance = reciprocal_q16(water->foam_distance);
    w->foam_texel_bytes = water->foam_texture != NULL && water->foam_texture->red_only ? 1u : 3u;
    int64_t px = (int64_t)water->refraction * config->width;
    w->refraction_px = px > (int64_t)UINT32_MAX ? UINT32_MAX : (uint32_t)px;
    int64_t threshold = water->sparkle_amount > 0 ? tarn_divide_once_i64((int64_t)1 << 46, (uint32_t)water->sparkle_amount) : INT64_MAX;
    w->sparkle_threshold = threshold > (int64_t)UINT32_MAX ? UINT32_MAX : (uint32_t)threshold;
    w->dark_cosine = (w->features & TARN_WATER_SPECULAR) != 0 ? tarn__water_dark_cosine(water) : -1;
#if TARN_LINK_WATER_PLANE
    if (TARN_LINK_WATER_SHADING) tarn__water_plane_setup(&w->plane, view, config->quality.water_coordinates, object);
#endif
}
