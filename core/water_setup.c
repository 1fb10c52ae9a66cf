/* water_setup.c: what a water context holds for one object in one tile (pan
 * offsets from the frame's time, the half vector in the object's tangent frame,
 * reciprocals of the material's distances), and the underwater view's per-frame
 * constants. 64-bit products are fine here, and divisions through tarn_divide_*;
 * water.c and underwater.c, per pixel, have neither. */
#include "water.h"
#include "underwater.h"

#define Q15_ONE 32768

/* floor(speed * time_ms / 1000) modulo one repeat, Q0.16. */
uint16_t tarn_water_pan_offset(tarn_q16 speed, uint32_t time_ms)
{
    int64_t travelled = (int64_t)speed * time_ms; /* |speed| <= 2^20: below 2^52 */
    const tarn_divisor thousand = tarn_divisor_of(1000);
    int64_t q16 = tarn_divide_floor_i64(travelled, &thousand, NULL);
    return (uint16_t)((uint64_t)q16 & 0xFFFFu);
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

void tarn_water_context_setup(tarn_water_context *w, const tarn_view *view,
                              const tarn_frame_config *config, const tarn_object *object)
{
    const tarn_water *water = object->material->water;
    w->water = water;
    w->object = object;
    w->features = TARN_LINK_WATER_FEATURES & water->features;
    w->width = config->width;
    w->height = config->height;
    w->near = view->near;
    w->far = view->far;
    w->exp2 = config->quality.exp2;
    w->fog_argument_bits = config->quality.fog_argument_bits;
    w->recip_steps = config->quality.recip_newton_steps;
    w->block_shift = (uint8_t)(config->quality.water_block == 4 ? 2u : config->quality.water_block == 2 ? 1u : 0u);
    const tarn_panning *pans[3] = {&water->pan_a, &water->pan_b, &water->foam_pan};
    uint16_t *offsets[3] = {w->pan_a, w->pan_b, w->foam_pan};
    for (int k = 0; k < 3; k++) {
        offsets[k][0] = tarn_water_pan_offset(pans[k]->speed_u, config->time_ms);
        offsets[k][1] = tarn_water_pan_offset(pans[k]->speed_v, config->time_ms);
    }
    w->foam_phase = tarn_water_pan_offset(water->foam_line_speed, config->time_ms);
    half_vector(view, object, w->half_vector);
    for (int c = 0; c < 3; c++) {
        w->light_q8[c] = ((view->light_q16[c] * 255u + 32768u) >> 16) << 8;
        w->fog_q8[c] = (w->features & TARN_WATER_FOG) != 0 ? tarn_water_channel_q8(water->fog_rgb, c) : 0u;
    }
    w->inv_depth_scale = reciprocal_q16(water->depth_scale);
    w->inv_foam_distance = reciprocal_q16(water->foam_distance);
    int64_t px = (int64_t)water->refraction * config->width;
    w->refraction_px = px > (int64_t)UINT32_MAX ? UINT32_MAX : (uint32_t)px;
    int64_t threshold = water->sparkle_amount > 0 ? tarn_divide_once_i64((int64_t)1 << 46, (uint32_t)water->sparkle_amount) : INT64_MAX;
    w->sparkle_threshold = threshold > (int64_t)UINT32_MAX ? UINT32_MAX : (uint32_t)threshold;
    w->dark_cosine = (w->features & TARN_WATER_SPECULAR) != 0 ? tarn_water_dark_cosine(water) : -1;
}

int32_t tarn_water_reach_pixels(const tarn_water *water, uint16_t frame_width)
{
    if (water == NULL || !(water->features & TARN_WATER_REFRACTION)) return 0;
    /* refraction (Q16) * width * normal_xy_max (Q16): pixels in Q32, rounded up; one
     * more for the rounding of the offset to a whole pixel. Both factors are cut to
     * [0, 1] first, their documented range: a malformed scene reaches at most the
     * frame's width instead of wrapping around to a small reach. */
    const uint64_t refraction = (uint64_t)tarn_clamp_i32(water->refraction, 0, TARN_Q16_ONE);
    const uint64_t xy_max = (uint64_t)tarn_clamp_i32(water->normal_xy_max, 0, TARN_Q16_ONE);
    const uint64_t q32 = refraction * frame_width * xy_max;
    return (int32_t)((q32 + 0xFFFFFFFFu) >> 32) + 1;
}

/* ---- the underwater view ----------------------------------------------------------- */

int tarn_underwater_active(const tarn_scene *scene)
{
    return scene != NULL && scene->underwater != NULL && scene->underwater->normal_map != NULL &&
           scene->camera.position.y < scene->underwater->level;
}

int32_t tarn_underwater_reach_pixels(const tarn_underwater *under, uint16_t frame_width)
{
    /* |N.x|, |N.y| <= 1; one more pixel for rounding the offset */
    uint64_t q16 = (uint64_t)(uint32_t)under->distortion * frame_width;
    return (int32_t)((q16 + 0xFFFFu) >> 16) + 1;
}

void tarn_underwater_setup(tarn_underwater_context *u, const tarn_view *view,
                           const tarn_frame_config *config, const tarn_underwater *under)
{
    u->under = under;
    u->near = view->near;
    u->far = view->far;
    u->exp2 = config->quality.exp2;
    u->fog_argument_bits = config->quality.fog_argument_bits;
    u->recip_steps = config->quality.recip_newton_steps;
    u->pan[0] = tarn_water_pan_offset(under->pan.speed_u, config->time_ms);
    u->pan[1] = tarn_water_pan_offset(under->pan.speed_v, config->time_ms);
    /* rounded up: a pixel centre exactly on a texel edge must land on the texel
     * above it, as floor() puts it, not a hair below */
    u->screen_u_per_half = (uint32_t)tarn_divide_once_i64(((int64_t)1 << 32) + 2 * config->width - 1,
                                                           2u * config->width);
    int64_t px = (int64_t)under->distortion * config->width;
    u->distortion_px = px > (int64_t)UINT32_MAX ? UINT32_MAX : (uint32_t)px;
}
