/* water_plane.c: flat water's texture coordinates from its plane (tarn_uv_plane,
 * tarn_scene.h), found once per water object per frame.
 *
 * In view space, the eye at the origin, the ray through a pixel's centre runs along
 *   dir = ((x - W/2) / f, (H/2 - y) / f, 1)       (right, up, forward)
 * and meets the plane n . p = c at p = dir * c / (n . dir), where the map takes
 * u = U + G . p (U the map extended to the eye, G its gradient). So
 *   u = N / D,   D = s (n . dir),   N = s (U (n . dir) + c (G . dir)),   s = sign(c),
 * D positive wherever the plane lies in front; and both are affine functions of
 * the pixel, since dir is. Here they are found, from the focal length's
 * reciprocal to 2^-31 of itself (tarn_view), and a pixel takes N / D through one
 * reciprocal of its own (tarn__plane_coordinates).
 *
 * The vectors are kept as 29-bit mantissas with an exponent, so no product of two
 * passes 2^63 however far the eye stands from the plane or however fine the map:
 * the affine functions are rounded once, at the end, to 32 bits each, D scaled so
 * its largest value over the frame's corners is below 2^30 and N so its own is,
 * the power of two between them kept in uv_shift. 64-bit products are fine here:
 * once a water object a frame; no division (the deepest call chain of the 16 KB
 * board runs through here, where tarn_divide_*'s frames did not fit). */
#include "water/water_internal.h"

#define MANTISSA_BITS 29 /* three products of a mantissa with a 2^33 factor stay below 2^63 */
#define EXTRA_BITS 8     /* fraction bits the affine functions keep before their last rounding:
                           with a 179-degree fov's focal length and the largest frame their
                           values at the corners stay below 2^61 */

/* The number of significant bits of |v|. */
static unsigned bit_length(uint64_t v)
{
    unsigned n = 0;
    while (v != 0u) v >>= 1, n++;
    return n;
}

static uint64_t magnitude(int64_t v)
{
    return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
}

/* v * 2^up, saturated at +-2^62 (which leaves every range this file checks), or
 * v / 2^-up rounded, 0 past 63. */
static int64_t scale_by_power(int64_t v, int up)
{
    if (up < 0) return -up >= 63 ? 0 : tarn_round_shift_i64(v, (unsigned)-up);
    if (v != 0 && bit_length(magnitude(v)) + (unsigned)up > 62u) return v < 0 ? -((int64_t)1 << 62) : (int64_t)1 << 62;
    return v * ((int64_t)1 << up);
}

/* v = out * 2^exponent, out's components at most 2^MANTISSA_BITS in magnitude:
 * shifted down with rounding, or kept whole. */
static TARN_ALWAYS_INLINE int mantissa_of(const int64_t v[3], int32_t out[3])
{
    uint64_t most = 0;
    for (int k = 0; k < 3; k++)
        if (magnitude(v[k]) > most) most = magnitude(v[k]);
    const int exponent = (int)bit_length(most) - MANTISSA_BITS;
    const int down = exponent > 0 ? exponent : 0;
    for (int k = 0; k < 3; k++) out[k] = (int32_t)scale_by_power(v[k], -down);
    return down;
}

/* The same for one number. */
static int32_t scalar_mantissa(int64_t v, int *exponent)
{
    const int down = (int)bit_length(magnitude(v)) - MANTISSA_BITS;
    *exponent = down > 0 ? down : 0;
    return (int32_t)scale_by_power(v, -*exponent);
}

/* rows * v (rows: Q(row_bits) unit vectors), each component rounded by row_bits.
 * Every vector turned here fits 32 bits: held in 64, they took the 16 KB boards'
 * deepest call chain past their stack. */
static void turned(const int32_t rows[3][3], const int32_t v[3], unsigned row_bits, int64_t out[3])
{
    for (int k = 0; k < 3; k++) {
        int64_t sum = 0;
        for (int r = 0; r < 3; r++) sum += (int64_t)rows[k][r] * v[r];
        out[k] = tarn_round_shift_i64(sum, row_bits);
    }
}

/* An affine function of the pixel, f = at + per_i * i + per_j * j, with
 * EXTRA_BITS fraction bits below its vector's units. */
typedef struct {
    int64_t at, per_i, per_j;
} pixel_affine;

/* a / f in units of 2^-EXTRA_BITS, f the focal length (its reciprocal's mantissa
 * is below 2^32 and a's below 2^31: the product stays below 2^63). */
static int64_t over_focal(const tarn_view *view, int32_t a)
{
    return scale_by_power((int64_t)a * view->inv_focal_mantissa, EXTRA_BITS - (int)view->inv_focal_shift);
}

/* a . dir at pixel (i, j) for a view vector of mantissas a (above):
 * a_z + a_x (i + 1/2 - W/2) / f - a_y (j + 1/2 - H/2) / f. */
static pixel_affine along_ray(const tarn_view *view, const int32_t a[3])
{
    pixel_affine f;
    f.per_i = over_focal(view, a[0]);
    f.per_j = -over_focal(view, a[1]);
    f.at = a[2] * ((int64_t)1 << EXTRA_BITS) +
           tarn_round_shift_i64(f.per_i * (1 - (int32_t)view->width) - f.per_j * ((int32_t)view->height - 1), 1u);
    return f;
}

/* The largest |f| over the frame's pixels: at a corner, since f is affine. */
static uint64_t largest_at_corners(const tarn_view *view, const pixel_affine *f)
{
    uint64_t most = 0;
    for (int corner = 0; corner < 4; corner++) {
        const int64_t i = (corner & 1) ? view->width - 1 : 0, j = (corner & 2) ? view->height - 1 : 0;
        const uint64_t v = magnitude(f->at + f->per_i * i + f->per_j * j);
        if (v > most) most = v;
    }
    return most;
}

/* f / 2^down as a fine affine function: its origin rounded, its steps floored
 * with their next 16 bits kept (within 2^31 but for a per-pixel step of a frame
 * one pixel across, never taken). */
static void store(const pixel_affine *f, unsigned down, tarn_fine_affine *out)
{
    out->at = tarn_sat_i64_to_i32(tarn_round_shift_i64(f->at, down));
    const int64_t steps[2] = {f->per_i, f->per_j};
    int32_t *whole[2] = {&out->per_i, &out->per_j};
    uint16_t *fraction[2] = {&out->fraction_i, &out->fraction_j};
    for (int k = 0; k < 2; k++) {
        /* the step in units of 2^-16, floored (down + 16 bits below the whole) */
        const int64_t fine = down >= 16u ? tarn_round_shift_i64(steps[k], down - 16u) : steps[k] * ((int64_t)1 << (16u - down));
        *whole[k] = tarn_sat_i64_to_i32(tarn_round_shift_i64(fine - 32768, 16u)); /* floor */
        *fraction[k] = (uint16_t)((uint64_t)fine & 0xFFFFu);
    }
}

/* What the plane gives in view space: n (Q1.30), c (Q16.16 world units) and the
 * eye's offset to the object's origin (Q16.16). */
typedef struct {
    int32_t normal[3];
    int64_t c;
    int64_t to_object[3];
} plane_in_view;

/* a . b for a within 2^31 and b within 2^33 (each product below 2^63; a unit a keeps
 * the sum there too). */
static int64_t dot(const int32_t a[3], const int64_t b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The components of v, within 2^31. */
static void narrowed(const int64_t v[3], int32_t out[3])
{
    for (int k = 0; k < 3; k++) out[k] = (int32_t)v[k];
}

static void place_plane(const tarn_view *view, const tarn_object *object, const tarn_uv_plane *p,
                        plane_in_view *out)
{
    int64_t turned_normal[3];
    int32_t world[3]; /* Q1.30 */
    turned(object->rotation, p->normal, 16u, turned_normal);
    narrowed(turned_normal, world);
    turned(view->basis, world, 30u, turned_normal);
    narrowed(turned_normal, out->normal);
    out->to_object[0] = (int64_t)object->position.x - view->eye.x;
    out->to_object[1] = (int64_t)object->position.y - view->eye.y;
    out->to_object[2] = (int64_t)object->position.z - view->eye.z;
    /* n . (origin - eye) + scale * offset: a unit n keeps the dot below 2^63 */
    out->c = tarn_round_shift_i64(dot(world, out->to_object), 30u) +
             tarn_round_shift_i64((int64_t)object->scale * p->offset, 16u);
}

/* The gradient of map `axis` in world space, rotation * g / scale, as mantissas
 * into gm and their exponent returned: gm * 2^exponent repeats per world unit.
 * The scale's reciprocal, not a division: 2^-29 of the gradient is 2^-29 of a
 * coordinate's distance from the eye's. `v` is room for the sums, the caller's,
 * so that no second three 64-bit words take the stack. */
static int world_gradient(const tarn_object *object, const tarn_uv_plane *p, int axis, int32_t gm[3], int64_t v[3])
{
    /* rotation * g, Q(16 + bits) repeats per object unit: below 2^42 */
    turned(object->rotation, p->uv_gradient[axis], 0u, v);
    const int turned_exponent = mantissa_of(v, gm);
    const unsigned lz = tarn_clz32((uint32_t)object->scale);
    const uint32_t recip = tarn_recip_q30((uint32_t)object->scale << lz, TARN_RECIP_STEPS_MAX); /* 2^62 / (scale << lz) */
    for (int k = 0; k < 3; k++) v[k] = (int64_t)gm[k] * recip;
    /* 1 / scale (Q16.16) = recip * 2^(lz - 62 + 16) per world unit */
    return mantissa_of(v, gm) + turned_exponent + (int)lz - 46 - 16 - (int)p->uv_gradient_bits;
}

/* The map `axis` as the vector m = U n + c G (mantissas into m, their exponent
 * returned, in units of 2^-46: Q16.16 coordinates times Q1.30), or 0 into *fits
 * when U, the map at the eye, leaves Q16.16. U keeps 16 bits below Q16.16: rounded
 * there, it moved every coordinate of the frame by up to half its last bit, and
 * a row of pixels level with a foam texel's edge tipped over it. */
static int map_vector(const plane_in_view *pl, const tarn_view *view, const tarn_object *object,
                      const tarn_uv_plane *p, int axis, int32_t m[3], int *fits)
{
    int32_t gm[3];
    int64_t sum[3];
    const int eg = world_gradient(object, p, axis, gm, sum);
    /* U = uv_origin - g . (origin - eye), Q16.32 */
    const int64_t origin = axis == 0 ? p->uv_origin.u : p->uv_origin.v;
    const int64_t eye = origin * 65536 - scale_by_power(dot(gm, pl->to_object), eg + 16);
    if (magnitude(eye) >= (uint64_t)1 << 47) *fits = 0;
    int eu, ec;
    const int64_t um = scalar_mantissa(eye, &eu), cm = scalar_mantissa(pl->c, &ec);
    const int e1 = eu - 16;      /* U n = um * n * 2^e1 in units of 2^-46 */
    const int e2 = ec + eg + 30; /* c G = cm * g_view * 2^(ec - 16 + eg) repeats: 2^e2 units */
    turned(view->basis, gm, 30u, sum);
    const int common = e1 > e2 ? e1 : e2;
    for (int k = 0; k < 3; k++)
        sum[k] = scale_by_power(um * pl->normal[k], e1 - common) + scale_by_power(cm * sum[k], e2 - common);
    return mantissa_of(sum, m) + common;
}

/* Map `axis` as an affine function of the pixel: s m . dir, its exponent into
 * *exponent. Found twice, once for its extent and once to store, so that no two are
 * held at once: this runs at the bottom of the 16 KB board's deepest call chain. */
static pixel_affine map_affine(const plane_in_view *pl, const tarn_view *view, const tarn_object *object,
                               const tarn_uv_plane *p, int axis, int *exponent, int *fits)
{
    int32_t m[3];
    *exponent = map_vector(pl, view, object, p, axis, m, fits);
    for (int k = 0; k < 3; k++) m[k] = pl->c > 0 ? m[k] : -m[k];
    return along_ray(view, m);
}

void tarn__water_plane_setup(tarn_water_plane *out, const tarn_view *view, uint8_t coordinates,
                             const tarn_object *object)
{
    out->holds = 0u;
    const tarn_uv_plane *p = object->mesh->plane;
    if (!TARN_LINK_WATER_PLANE || coordinates != TARN_WATER_UV_PLANE || p == NULL) return;
    plane_in_view pl;
    place_plane(view, object, p, &pl);
    if (pl.c == 0) return; /* the eye on the plane sees it edge on */
    int32_t d[3];
    for (int k = 0; k < 3; k++) d[k] = (int32_t)(pl.c > 0 ? pl.normal[k] : -pl.normal[k]);
    pixel_affine f = along_ray(view, d);
    const int d_down = (int)bit_length(largest_at_corners(view, &f)) - 30;
    const unsigned d_shift = d_down > 0 ? (unsigned)d_down : 0u;
    store(&f, d_shift, &out->denominator);
    /* both maps at one exponent, the larger, so they share uv_shift */
    int fits = 1, exponent[2];
    uint64_t most[2];
    for (int axis = 0; axis < 2; axis++) {
        f = map_affine(&pl, view, object, p, axis, &exponent[axis], &fits);
        most[axis] = largest_at_corners(view, &f);
    }
    const int e = exponent[0] > exponent[1] ? exponent[0] : exponent[1];
    const uint64_t larger = (most[0] >> (e - exponent[0] > 63 ? 63 : e - exponent[0])) |
                            (most[1] >> (e - exponent[1] > 63 ? 63 : e - exponent[1]));
    /* the map holds N 2^(46 - e + EXTRA_BITS), D N's denominator 2^(30 + EXTRA_BITS);
     * stored shifted down by n_down and d_shift, u = N / D in Q16.16 is
     * u_plane * 2^uv_shift / denominator with uv_shift = e + n_down - d_shift
     * (the larger of two maps' bit lengths is their OR's) */
    int n_down = (int)bit_length(larger) - 30;
    if (n_down < 0) n_down = 0;
    int uv_shift = e + n_down - (int)d_shift;
    if (uv_shift < 0) n_down -= uv_shift, uv_shift = 0;
    if (!fits || uv_shift > 31 || n_down > 62) return;
    for (int axis = 0; axis < 2; axis++) {
        f = map_affine(&pl, view, object, p, axis, &exponent[axis], &fits);
        const int down = n_down + e - exponent[axis];
        f.at = scale_by_power(f.at, n_down - down); /* to the shared exponent first, then stored */
        f.per_i = scale_by_power(f.per_i, n_down - down);
        f.per_j = scale_by_power(f.per_j, n_down - down);
        store(&f, (unsigned)n_down, axis == 0 ? &out->u : &out->v);
    }
    out->uv_shift = (uint8_t)uv_shift;
    out->holds = 1u;
}
