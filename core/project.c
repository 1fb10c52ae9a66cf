/* project.c: view space to the snapped screen grid. One division per coordinate
 * per vertex; the guard band bounds every result (see tarn_frame_memory_bytes). */
#include "pipeline.h"

/* centre + offset_q28 / depth, in 1/2^subpixel_bits pixels, rounded, clamped to the
 * guard band. `centre_q12` is in the same subpixel units, Q12. */
static int32_t screen_coordinate(const tarn_view *view, int64_t offset_q28, tarn_q16 depth,
                                 int64_t centre_q12, int32_t frame_extent)
{
    const unsigned s = view->subpixel_bits;
    /* after guard clipping |offset| <= (width/2 + guard) * depth: below 2^52, times 2^8 */
    int64_t along_q12 = (offset_q28 * ((int64_t)1 << s)) / depth; /* subpixels, Q12 */
    int64_t snapped = tarn_round_shift_i64(centre_q12 + along_q12, 12);
    int64_t low = -(((int64_t)view->guard_pixels + 1) << s);
    int64_t high = (int64_t)(frame_extent + view->guard_pixels + 1) << s;
    return (int32_t)(snapped < low ? low : (snapped > high ? high : snapped));
}

void tarn_project(const tarn_view *view, const tarn_view_vertex *in, tarn_screen_vertex *out)
{
    const unsigned s = view->subpixel_bits;
    const tarn_q16 depth = in->d >= view->near ? in->d : view->near;
    const int64_t x_focal = (int64_t)in->x * view->focal_q12;
    const int64_t y_focal = (int64_t)in->y * view->focal_q12;
    out->x = screen_coordinate(view, x_focal, depth, (int64_t)view->width << (s + 11), view->width);
    out->y = screen_coordinate(view, -y_focal, depth, (int64_t)view->height << (s + 11), view->height);
    int64_t inv_depth = ((int64_t)view->near << 30) / depth; /* near/d, Q1.30 */
    out->inv_depth = (uint32_t)(inv_depth < 1 ? 1 : (inv_depth > (1 << 30) ? (1 << 30) : inv_depth));
    tarn_project_attributes(in, out);
}

void tarn_project_attributes(const tarn_view_vertex *in, tarn_screen_vertex *out)
{
    out->uv = in->uv;
    for (int c = 0; c < 3; c++)
        out->lit[c] = (uint16_t)tarn_clamp_i32(in->lit[c], 0, 65280);
    out->fresnel = (uint16_t)tarn_clamp_i32(in->fresnel, 0, 32768);
}
