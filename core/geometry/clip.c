/* clip.c: Sutherland-Hodgman clipping in view space against the near and far
 * planes and the guard band, so projected coordinates stay small enough for
 * 32-bit edge functions. Runs per clipped triangle, never per pixel. */
#include "geometry/geometry_internal.h"

enum { PLANE_NEAR, PLANE_FAR, PLANE_LEFT, PLANE_RIGHT, PLANE_TOP, PLANE_BOTTOM, PLANE_COUNT };

/* Signed distances to every plane, positive inside; a plane's units are its own.
 * The four guard-band planes share four products, each taken once. */
static void plane_distances(const tarn_view *view, const tarn_view_vertex *v, int64_t distance[PLANE_COUNT])
{
    const int64_t x_focal = tarn_mul_i32_wide(v->x, view->focal_q12); /* Q28: below 2^59 */
    const int64_t y_focal = tarn_mul_i32_wide(v->y, view->focal_q12);
    const int64_t x_extent = tarn_mul_i32_wide(view->half_extent_q12[0], v->d);
    const int64_t y_extent = tarn_mul_i32_wide(view->half_extent_q12[1], v->d);
    distance[PLANE_NEAR] = (int64_t)v->d - view->near;
    distance[PLANE_FAR] = (int64_t)view->far - v->d;
    distance[PLANE_LEFT] = x_focal + x_extent;
    distance[PLANE_RIGHT] = x_extent - x_focal;
    distance[PLANE_TOP] = y_extent - y_focal;
    distance[PLANE_BOTTOM] = y_focal + y_extent;
}

/* 1 when |offset| <= (d >> 8) * slope_q8, for d > 0: then |offset| * focal <=
 * d * half_extent, and the vertex is inside both guard planes of the axis. 32-bit:
 * (d >> 8) is below 2^23 and the slope below 2^9. */
static int within_guard_slope(int32_t offset, tarn_q16 d, uint16_t slope_q8)
{
    const uint32_t magnitude = offset < 0 ? (uint32_t)0 - (uint32_t)offset : (uint32_t)offset;
    return magnitude <= ((uint32_t)d >> 8) * slope_q8;
}

unsigned tarn__clip_outcode(const tarn_view *view, const tarn_view_vertex *v)
{
    /* most vertices lie well inside every plane: four wide products spared */
    if (v->d >= view->near && v->d <= view->far && within_guard_slope(v->x, v->d, view->guard_slope_q8[0]) &&
        within_guard_slope(v->y, v->d, view->guard_slope_q8[1]))
        return 0;
    int64_t distance[PLANE_COUNT];
    plane_distances(view, v, distance);
    unsigned code = 0;
    for (int plane = 0; plane < PLANE_COUNT; plane++)
        if (distance[plane] < 0) code |= 1u << plane;
    return code;
}

/* num / den in Q1.30 for 0 <= num <= den, den > 0. */
static int64_t ratio_q30(int64_t num, int64_t den)
{
    while (den >= ((int64_t)1 << 32)) {
        num >>= 1;
        den >>= 1;
    }
    const tarn_divisor divisor = tarn_divisor_of((uint32_t)den);
    return (int64_t)tarn_divide_u64((uint64_t)num << 30, &divisor, NULL);
}

static int32_t lerp_q30(int32_t from, int32_t to, int64_t t_q30)
{
    return (int32_t)(from + tarn_round_shift_i64(((int64_t)to - from) * t_q30, 30));
}

/* A coordinate of the crossing: *value, with its 16 bits below Q16.16 in *low, at t
 * (Q1.30) from the inside vertex's (value, low) toward the outside's, in Q16.32. The
 * difference reaches 2^48: taken as its part above the 16 low bits (below 2^32 but
 * for coordinates 32768 units apart, which take the 64-bit product) and those bits. */
static void lerp_fine_q30(tarn_q16 *value, uint16_t *low, tarn_q16 to_value, uint16_t to_low, int64_t t_q30)
{
    const int64_t from = (int64_t)*value * 65536 + *low, to = (int64_t)to_value * 65536 + to_low;
    const int64_t delta = to - from; /* within 2^48 */
    const uint32_t delta_low = (uint32_t)((uint64_t)delta & 0xFFFFu);
    /* floor(delta / 2^16): the bits shifted down, where the sign (bit 47 of the
       shifted pattern, the bits above it zero) is extended by flipping it and taking
       it away; delta reaches 2^48, so this may pass 32 bits */
    const int64_t delta_high = (int64_t)(((uint64_t)delta >> 16) ^ 0x800000000000ull) - 0x800000000000ll;
    const int64_t high = delta_high == (int32_t)delta_high ? tarn_mul_i32_wide((int32_t)delta_high, (int32_t)t_q30)
                                                            : delta_high * t_q30;
    /* the low part's product is not negative: rounded with a half and a shift */
    const uint64_t below = (tarn_mul_u32_wide(delta_low, (uint32_t)t_q30) + ((uint64_t)1 << 29)) >> 30;
    const int64_t v = from + tarn_round_shift_i64(high, 14) + (int64_t)below;
    /* between from and to, so its Q16.16 part fits: the low word of v / 2^16 */
    *low = (uint16_t)((uint64_t)v & 0xFFFFu);
    *value = (tarn_q16)(uint32_t)((uint64_t)v >> 16);
}

/* The crossing point, always measured from the inside vertex so that the two
 * triangles sharing a clipped edge get bit-identical new vertices. Its position and
 * texture coordinates keep 16 bits below Q16.16 (the projection and the raster read
 * them): at the near plane a bit of Q16.16 is many pixels. */
static tarn_view_vertex crossing(const tarn_view_vertex *inside, int64_t dist_inside,
                                 const tarn_view_vertex *outside, int64_t dist_outside)
{
    int64_t t = ratio_q30(dist_inside, dist_inside - dist_outside);
    tarn_view_vertex v = *inside;
    lerp_fine_q30(&v.x, &v.x_low, outside->x, outside->x_low, t);
    lerp_fine_q30(&v.y, &v.y_low, outside->y, outside->y_low, t);
    lerp_fine_q30(&v.d, &v.d_low, outside->d, outside->d_low, t);
    lerp_fine_q30(&v.uv.u, &v.uv_low[0], outside->uv.u, outside->uv_low[0], t);
    lerp_fine_q30(&v.uv.v, &v.uv_low[1], outside->uv.v, outside->uv_low[1], t);
    /* between two values in range, so in range */
    for (int c = 0; c < 3; c++) v.lit[c] = (uint16_t)lerp_q30(inside->lit[c], outside->lit[c], t);
    v.fresnel = (uint16_t)lerp_q30(inside->fresnel, outside->fresnel, t);
    return v;
}

static int clip_against(const tarn_view *view, int plane,
                        tarn_view_vertex polygon[TARN_CLIP_POLYGON_MAX], int count)
{
    tarn_view_vertex input[TARN_CLIP_POLYGON_MAX];
    int64_t dist[TARN_CLIP_POLYGON_MAX];
    for (int i = 0; i < count; i++) {
        int64_t distance[PLANE_COUNT];
        input[i] = polygon[i];
        plane_distances(view, &input[i], distance);
        dist[i] = distance[plane];
    }
    int out = 0;
    for (int i = 0; i < count; i++) {
        int j = i + 1 == count ? 0 : i + 1;
        int in_i = dist[i] >= 0, in_j = dist[j] >= 0;
        if (in_i) polygon[out++] = input[i];
        if (in_i && !in_j) polygon[out++] = crossing(&input[i], dist[i], &input[j], dist[j]);
        if (!in_i && in_j) polygon[out++] = crossing(&input[j], dist[j], &input[i], dist[i]);
    }
    /* Rounding must not leave a new vertex a hair outside the depth range. */
    for (int i = 0; i < out; i++) {
        if (plane == PLANE_NEAR && polygon[i].d < view->near) {
            polygon[i].d = view->near;
            polygon[i].d_low = 0u;
        }
        if (plane == PLANE_FAR && (polygon[i].d > view->far || (polygon[i].d == view->far && polygon[i].d_low))) {
            polygon[i].d = view->far;
            polygon[i].d_low = 0u;
        }
    }
    return out;
}

int tarn__clip_polygon(const tarn_view *view, unsigned planes,
                      tarn_view_vertex polygon[TARN_CLIP_POLYGON_MAX], int count)
{
    for (int plane = 0; plane < PLANE_COUNT && count > 0; plane++)
        if (planes & (1u << plane)) count = clip_against(view, plane, polygon, count);
    return count;
}

/* A function of its own, not inlined into the walk: the polygon stays off the
 * stack of the common, unclipped path. */
void tarn__clip_and_emit(const tarn_view *view, unsigned planes, const tarn_view_vertex v[3],
                        const tarn_object *object, tarn_triangle_sink sink, void *ctx)
{
    tarn_view_vertex polygon[TARN_CLIP_POLYGON_MAX]; /* the corners past count unread: not zeroed */
    for (int i = 0; i < 3; i++) polygon[i] = v[i];
    const int count = tarn__clip_polygon(view, planes, polygon, 3);
    if (count < 3) return;
    /* a fan around the first corner: each corner projected once, in one place */
    tarn_screen_vertex fan[3];
    for (int i = 0; i < count; i++) {
        if (i >= 2) fan[1] = fan[2];
        tarn_screen_vertex *corner = &fan[i == 0 ? 0 : 2];
        tarn__project_position(view, &polygon[i], corner);
        tarn__project_attributes(&polygon[i], corner);
        if (i >= 2) sink(ctx, fan, object);
    }
}
