/* view.c: per-frame camera and light constants. Divisions here run once a frame. */
#include "geometry/geometry_internal.h"

static int32_t mul_q30(int32_t a, int32_t b)
{
    return (int32_t)tarn_round_shift_i64((int64_t)a * b, 30);
}

static void cross_q30(const int32_t a[3], const int32_t b[3], int32_t out[3])
{
    out[0] = mul_q30(a[1], b[2]) - mul_q30(a[2], b[1]);
    out[1] = mul_q30(a[2], b[0]) - mul_q30(a[0], b[2]);
    out[2] = mul_q30(a[0], b[1]) - mul_q30(a[1], b[0]);
}

/* Forward, right and up as the public header defines them. */
static void camera_basis(const tarn_camera *camera, int32_t basis[3][3])
{
    const int64_t forward[3] = {
        (int64_t)camera->target.x - camera->position.x,
        (int64_t)camera->target.y - camera->position.y,
        (int64_t)camera->target.z - camera->position.z};
    if (!tarn_normalise_q30(forward, basis[2])) {
        /* target == position: look down -z rather than fail mid-frame */
        basis[2][0] = 0; basis[2][1] = 0; basis[2][2] = -(1 << 30);
    }
    /* right = forward x Y; with Y = (0,1,0) that is (-fz, 0, fx) */
    int64_t right[3] = {-forward[2], 0, forward[0]};
    if (forward[0] == 0 && forward[2] == 0) {
        /* looking straight up or down: Y = (0,0,-1), right = (-fy, fx, 0) */
        right[0] = -forward[1]; right[1] = forward[0]; right[2] = 0;
        if (forward[1] == 0) right[0] = 1 << 30;
    }
    tarn_normalise_q30(right, basis[0]);
    cross_q30(basis[0], basis[2], basis[1]);
}

/* Focal length in pixels (Q20.12): (height / 2) / tan(fov / 2). */
/* The focal length height / 2 / tan(fov / 2) in pixels, Q20.12, and its reciprocal
 * 2 tan(fov / 2) / height as a normalised mantissa. */
static void focal_length(const tarn_camera *camera, uint16_t height, tarn_view *view)
{
    const int64_t pi_q32 = 13493037705; /* pi * 2^32, rounded */
    tarn_q16 fov = tarn_clamp_i32(camera->fov_y_degrees, TARN_Q16_ONE, 179 * TARN_Q16_ONE);
    /* half the fov in radians, Q2.30: fov_q16 * pi / 360 */
    int32_t half_angle = (int32_t)tarn_divide_once_i64((int64_t)fov * pi_q32 + (180 << 17), 360u << 18);
    int32_t sine, cosine;
    tarn_sin_cos_q30(half_angle, &sine, &cosine);
    view->focal_q12 = tarn_sat_i64_to_i32(tarn_divide_once_i64((int64_t)height * 2048 * cosine + sine / 2, (uint32_t)sine));
    if (!TARN_LINK_WATER_PLANE) return; /* its one reader: the reciprocal stays unset */
    /* tan in Q32 (below 2^39 up to 179 degrees), then 2 tan / height in Q48 */
    const int64_t tan_q32 = tarn_divide_once_i64((int64_t)sine * ((int64_t)1 << 32) + cosine / 2, (uint32_t)cosine);
    const uint64_t inverse_q48 = (uint64_t)tarn_divide_once_i64(tan_q32 * 131072 + height / 2, height);
    const uint32_t high = (uint32_t)(inverse_q48 >> 32);
    const unsigned bits = high != 0u ? 64u - tarn_clz32(high) : 32u - tarn_clz32((uint32_t)inverse_q48);
    view->inv_focal_mantissa =
        bits > 32u ? (uint32_t)(inverse_q48 >> (bits - 32u)) : (uint32_t)inverse_q48 << (32u - bits);
    view->inv_focal_shift = 80u - bits; /* inverse = mantissa * 2^(bits - 32) / 2^48 */
}

static uint32_t channel_q16(uint32_t rgb, int channel)
{
    uint32_t value = (rgb >> (16 - 8 * channel)) & 0xFFu;
    return (value * 65536u + 127u) / 255u;
}



void tarn__view_setup(const tarn_scene *scene, const tarn_frame_config *config, tarn_view *view)
{
    const tarn_camera *camera = &scene->camera;
    camera_basis(camera, view->basis);
    view->eye = camera->position;
    view->width = config->width;
    view->height = config->height;
    view->subpixel_bits = config->quality.subpixel_bits;
    focal_length(camera, config->height, view);
    view->near = camera->near > 0 ? camera->near : 1;
    view->far = camera->far > view->near ? camera->far : view->near;
    /* focal_q12 is at least 17 (one row, a 179-degree fov), so it normalises */
    view->focal_shift = tarn_clz32((uint32_t)view->focal_q12);
    view->focal_mantissa = (uint32_t)view->focal_q12 << view->focal_shift;
    view->near_shift = tarn_clz32((uint32_t)view->near);
    view->near_mantissa = (uint32_t)view->near << view->near_shift;
    view->guard_pixels = (int16_t)tarn_guard_band_pixels(config);
    view->half_extent_q12[0] = config->width * 2048 + view->guard_pixels * 4096;
    view->half_extent_q12[1] = config->height * 2048 + view->guard_pixels * 4096;
    /* f / 256 < (f >> 8) + 1, so the quotient is at most h * 256 / f, as it must be */
    for (int axis = 0; axis < 2; axis++) {
        const uint32_t slope = (uint32_t)view->half_extent_q12[axis] / (((uint32_t)view->focal_q12 >> 8) + 1u);
        view->guard_slope_q8[axis] = (uint16_t)(slope > 511u ? 511u : slope);
    }
    for (int c = 0; c < 3; c++) {
        view->light_q16[c] = channel_q16(scene->light.colour_rgb, c);
        view->ambient_q16[c] = channel_q16(scene->light.ambient_rgb, c);
    }
    view->light_dir = tarn__unit_vector_bounded(&scene->light.direction);
    view->static_vertices = (uint8_t)tarn__static_view_applies(scene);
    view->static_screen = (uint8_t)tarn__static_screen_applies(scene, config);
}
