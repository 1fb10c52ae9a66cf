/* underwater_setup.c: the underwater view's constants for a frame: pan offsets from
 * the frame's time, the screen's texture step, the displacement in pixels. 64-bit
 * products and divisions through tarn_divide_* are fine here, once a frame;
 * underwater.c, per pixel, has neither. */
#include "water/underwater_internal.h"

void tarn__underwater_setup(tarn_underwater_context *u, const tarn_view *view,
                           const tarn_frame_config *config, const tarn_underwater *under)
{
    u->under = under;
    tarn__linear_depth_setup(&u->linear, view->near, view->far, config->quality.recip_newton_steps);
    u->exp2 = config->quality.exp2;
    u->fog_argument_bits = config->quality.fog_argument_bits;
    u->pan[0] = tarn__water_pan_offset_q32(under->pan.speed_u, config->time_ms);
    u->pan[1] = tarn__water_pan_offset_q32(under->pan.speed_v, config->time_ms);
    /* rounded up: a pixel centre exactly on a texel edge must land on the texel
     * above it, as floor() puts it, not a hair below */
    u->screen_u_per_half = (uint32_t)tarn_divide_once_i64(((int64_t)1 << 32) + 2 * config->width - 1,
                                                           2u * config->width);
    int64_t px = (int64_t)under->distortion * config->width;
    u->distortion_px = px > (int64_t)UINT32_MAX ? UINT32_MAX : (uint32_t)px;
}
