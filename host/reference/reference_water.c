/* reference_water.c: the float reference's water pixel and underwater view (see
 * reference_water.h), written from the rules in core/include/tarn/tarn_water.h in doubles with
 * libm and none of the core's arithmetic. Step numbers below are the header's. */
#include "reference_water.h"

#include <math.h>
#include <stddef.h>

#include "ref_texel.h"

#define Q16_SCALE 65536.0

static double q16(tarn_q16 v)
{
    return v / Q16_SCALE;
}

static double saturate(double v)
{
    return fmin(1.0, fmax(0.0, v));
}

static int has(const tarn_water *w, uint32_t feature)
{
    return (w->features & feature) != 0;
}

/* ---- validation ------------------------------------------------------------------ */

/* A feature that samples a texture needs one; NULL is valid only where optional. */
static int feature_texture_ok(const tarn_water *w, uint32_t features, const tarn_texture *tex)
{
    return tex != NULL ? tarn_ref_texture_is_valid(tex) : (w->features & features) == 0;
}

int tarn_ref_water_is_valid(const tarn_water *w)
{
    return feature_texture_ok(w, TARN_WATER_NORMALS, w->normal_a)
           && tarn_ref_texture_is_valid(w->normal_b)
           && tarn_ref_texture_is_valid(w->colour_ramp)
           && feature_texture_ok(w, TARN_WATER_FOAM, w->foam_texture)
           && (!has(w, TARN_WATER_DEPTH_COLOUR) || w->depth_scale > 0)
           && (!has(w, TARN_WATER_FOAM) || w->foam_distance > 0);
}

int tarn_ref_underwater_is_valid(const tarn_underwater *u)
{
    return u->normal_map != NULL && tarn_ref_texture_is_valid(u->normal_map);
}

/* ---- panning textures ------------------------------------------------------------- */

/* time_ms / 1000 * speed (Q16.16) is time_ms * speed / PAN_UNIT repeats. */
#define PAN_UNIT (1000 * 65536LL)

/* floor(a / b), b > 0, and a - b * floor(a / b) in [0, b). */
static int64_t floor_div(int64_t a, int64_t b, int64_t *remainder)
{
    int64_t q = a / b, r = a % b;
    if (r < 0) {
        q--;
        r += b;
    }
    *remainder = r;
    return q;
}

/* time * speed less whole repeats, in 1/PAN_UNIT repeats, in (-PAN_UNIT, PAN_UNIT).
 * Whole repeats move no texel (they move floor(u*W) by a multiple of W); dropping
 * them exactly, in integers, keeps the fraction exact at any time and speed. */
static int64_t pan_remainder(uint32_t time_ms, tarn_q16 speed)
{
    return ((int64_t)(time_ms % PAN_UNIT) * speed) % PAN_UNIT; /* < 2^26 * 2^31 */
}

static double pan_offset(uint32_t time_ms, tarn_q16 speed)
{
    return (double)pan_remainder(time_ms, speed) / (double)PAN_UNIT;
}

/* The texel of a panning texture at uv * scale + time * speed. */
static const uint8_t *sample_panned(const tarn_texture *tex, const tarn_panning *pan,
                                    const double uv[2], uint32_t time_ms)
{
    double at[2] = { uv[0] * q16(pan->scale) + pan_offset(time_ms, pan->speed_u),
                     uv[1] * q16(pan->scale) + pan_offset(time_ms, pan->speed_v) };
    return tarn_ref_sample_texel(tex, at);
}

/* A normal-map texel: channel c stands for (2c - 255) / 255, in [-1, 1]. */
static void decode_normal(const uint8_t *texel, double n[3])
{
    for (int k = 0; k < 3; k++) n[k] = (2.0 * texel[k] - 255.0) / 255.0;
}

/* ---- step 1: the normal, and the raw map samples sparkles test ------------------- */

typedef struct {
    double n[3];      /* N in the tangent frame (u, v, up) */
    int a_x, b_x;     /* the maps' x as 2c - 255, for sparkles */
    int has_maps, has_b;
} water_normal;

/* The maps are sampled only with TARN_WATER_NORMALS (step 1): without it there is no
 * a or b, and no sparkles (step 10). With one map, b is taken as the flat (0, 0, 1):
 * strength * (a.xy + 0), a.z * 1 is "a alone" with the same strength and
 * normalisation. A decoded z is never 0 ((2c - 255) is odd): N never vanishes. */
static water_normal sample_normal(const tarn_water *w, const double uv[2], uint32_t time_ms)
{
    water_normal r = { { 0, 0, 1 }, 0, 0, 0, 0 };
    r.has_maps = has(w, TARN_WATER_NORMALS) && w->normal_a != NULL;
    if (!r.has_maps) return r;
    const uint8_t *ta = sample_panned(w->normal_a, &w->pan_a, uv, time_ms);
    double a[3], b[3] = { 0, 0, 1 };
    decode_normal(ta, a);
    r.a_x = 2 * ta[0] - 255;
    r.has_b = w->normal_b != NULL;
    if (r.has_b) {
        const uint8_t *tb = sample_panned(w->normal_b, &w->pan_b, uv, time_ms);
        decode_normal(tb, b);
        r.b_x = 2 * tb[0] - 255;
    }
    double strength = q16(w->normal_strength);
    double v[3] = { strength * (a[0] + b[0]), strength * (a[1] + b[1]), a[2] * b[2] };
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++) r.n[k] = v[k] / len;
    return r;
}

/* ---- steps 2-5: what shows through ------------------------------------------------ */

static double clamp_index(double v, int size)
{
    return fmin(size - 1.0, fmax(0.0, v));
}

/* Step 2: the pixel q the background is read from (an index into the frame). A
 * shift of o pixels rounds to floor(o + 0.5), halves up; the clamp comes before the
 * integer conversion so no offset can overflow it. */
static size_t refracted_pixel(const tarn_ref_water_view *view, const tarn_water *w,
                              const double n[3], int i, int j, double ds)
{
    size_t p = (size_t)j * view->width + i;
    if (!has(w, TARN_WATER_REFRACTION)) return p;
    double pixels = q16(w->refraction) * view->width * saturate(view->depth[p] - ds);
    double qi = clamp_index(i + floor(n[0] * pixels + 0.5), view->width);
    double qj = clamp_index(j + floor(n[1] * pixels + 0.5), view->height);
    size_t q = (size_t)qj * view->width + (size_t)qi;
    return view->depth[q] < ds ? p : q; /* what lies in front of the water is not behind it */
}

/* Steps 4 and 5 on the background colour B, given diff. */
static void tint_background(const tarn_water *w, double diff, double b[3])
{
    if (has(w, TARN_WATER_FOG)) {
        double keep = exp2(-q16(w->fog_density) * diff);
        for (int c = 0; c < 3; c++) {
            double fog = tarn_ref_channel(w->fog_rgb, c);
            b[c] = fog + (b[c] - fog) * keep;
        }
    }
    if (has(w, TARN_WATER_ABSORPTION)) {
        double x = w->absorption_squared ? diff * diff : diff;
        double absorbed = 1.0 - exp2(-q16(w->absorption) * x);
        for (int c = 0; c < 3; c++)
            b[c] = fmax(0.0, b[c] - (255.0 - tarn_ref_channel(w->absorb_rgb, c)) * absorbed);
    }
}

/* ---- steps 6-7: the surface over it ------------------------------------------------ */

/* Step 6: S before lighting. The ramp is read only with DEPTH_COLOUR: it stands in
 * for the shallow and deep colours. */
static void surface_colour(const tarn_water *w, double diff, double s[3])
{
    if (!has(w, TARN_WATER_DEPTH_COLOUR)) {
        for (int c = 0; c < 3; c++) s[c] = tarn_ref_channel(w->albedo_rgb, c);
        return;
    }
    double t = saturate(diff / q16(w->depth_scale));
    if (w->colour_ramp != NULL) {
        size_t x = (size_t)floor(t * (w->colour_ramp->width - 1) + 0.5);
        const uint8_t *texel = w->colour_ramp->rgb + 3 * x; /* first row */
        for (int c = 0; c < 3; c++) s[c] = texel[c];
        return;
    }
    for (int c = 0; c < 3; c++) {
        double shallow = tarn_ref_channel(w->shallow_rgb, c);
        s[c] = shallow + (tarn_ref_channel(w->deep_rgb, c) - shallow) * t;
    }
}

/* Step 7: the lit surface over the background. */
static void blend_surface(const tarn_water *w, const tarn_ref_water_surface *surf, double diff,
                          const double b[3], double out[3])
{
    double s[3];
    surface_colour(w, diff, s);
    double alpha = saturate(q16(w->alpha));
    if (has(w, TARN_WATER_FRESNEL))
        alpha = saturate(alpha + (1.0 - alpha) * q16(w->fresnel) * surf->fresnel);
    for (int c = 0; c < 3; c++) out[c] = s[c] * surf->lit[c] / 255.0 * alpha + b[c] * (1.0 - alpha);
}

/* ---- steps 8-10: highlights on top ------------------------------------------------- */

/* Column `axis` of the object's rotation: that object axis in the world. */
static double axis_dot(const tarn_object *o, int axis, const double v[3])
{
    return q16(o->rotation[0][axis]) * v[0] + q16(o->rotation[1][axis]) * v[1]
           + q16(o->rotation[2][axis]) * v[2];
}

/* Step 8. h = normalize(L + V) in the world, then in the tangent frame (object x,
 * object z, object y). L = -V has no half vector: h is then taken as the up axis. */
static void add_specular(const tarn_ref_water_view *view, const tarn_object *o,
                         const double n[3], double colour[3])
{
    const tarn_water *w = o->material->water;
    double l[3] = { q16(view->light->direction.x), q16(view->light->direction.y),
                    q16(view->light->direction.z) };
    double h[3];
    for (int k = 0; k < 3; k++) h[k] = l[k] + view->backward[k];
    double len = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    double n_dot_h = n[2];
    if (len > 0)
        n_dot_h = (n[0] * axis_dot(o, 0, h) + n[1] * axis_dot(o, 2, h) + n[2] * axis_dot(o, 1, h))
                  / len;
    double highlight = q16(w->specular) * pow(fmax(0.0, n_dot_h), w->specular_power);
    for (int c = 0; c < 3; c++)
        colour[c] += tarn_ref_channel(view->light->colour_rgb, c) * highlight;
}

/* Step 9. The band's lines move by time * foam_line_speed band widths; sin has a
 * whole number of periods per band width, so whole widths drop out (pan_offset). */
static void add_foam(const tarn_water *w, const double uv[2], double diff, uint32_t time_ms,
                     double colour[3])
{
    double f = saturate(diff / q16(w->foam_distance));
    double phase = f - pan_offset(time_ms, w->foam_line_speed);
    double lines = saturate(sin(2.0 * acos(-1.0) * w->foam_line_count * phase)) * (1.0 - f);
    double t = sample_panned(w->foam_texture, &w->foam_pan, uv, time_ms)[0] / 255.0;
    if (!(f < 1.0 && t >= f - lines)) return;
    double opacity = saturate(q16(w->foam_opacity));
    for (int c = 0; c < 3; c++)
        colour[c] += (tarn_ref_channel(w->foam_rgb, c) - colour[c]) * opacity;
}

/* x^2 * amount > 1 for a map's x = (2c - 255) / 255, in integers: round amounts
 * meet the threshold exactly (25 and c = 102 give 0.2^2 * 25 = 1, no sparkle),
 * which a double would decide by its rounding. The product is below 2^47. */
static int sparkles_at(int x_code, tarn_q16 amount)
{
    return (int64_t)x_code * x_code * amount > (int64_t)255 * 255 * 65536;
}

/* Step 10, on the raw samples of the maps (not the blended normal). */
static void add_sparkles(const tarn_water *w, const water_normal *nm, double colour[3])
{
    if (!nm->has_maps || !sparkles_at(nm->a_x, w->sparkle_amount)) return;
    if (nm->has_b && !sparkles_at(nm->b_x, w->sparkle_amount)) return;
    for (int c = 0; c < 3; c++) colour[c] += tarn_ref_channel(w->sparkle_rgb, c);
}

/* ---- the pixel --------------------------------------------------------------------- */

void tarn_ref_shade_water(const tarn_ref_water_view *view, const tarn_object *object, int i,
                          int j, const tarn_ref_water_surface *surface, uint8_t out[3])
{
    const tarn_water *w = object->material->water;
    water_normal nm = sample_normal(w, surface->uv, view->time_ms);
    size_t q = refracted_pixel(view, w, nm.n, i, j, surface->depth);
    double diff = fmax(0.0, view->depth[q] - surface->depth);
    double b[3], colour[3];
    for (int c = 0; c < 3; c++) b[c] = view->rgb[3 * q + c];
    tint_background(w, diff, b);
    blend_surface(w, surface, diff, b, colour);
    if (has(w, TARN_WATER_SPECULAR)) add_specular(view, object, nm.n, colour);
    if (has(w, TARN_WATER_FOAM)) add_foam(w, surface->uv, diff, view->time_ms, colour);
    if (has(w, TARN_WATER_SPARKLES)) add_sparkles(w, &nm, colour);
    for (int c = 0; c < 3; c++) out[c] = (uint8_t)tarn_ref_round_to_byte(colour[c]);
}

/* ---- underwater -------------------------------------------------------------------- */

/* The map's texel index along one axis at pixel centre k + 0.5 of a frame `width`
 * wide: floor(((k + 0.5) / width * scale + time * speed) * size) mod size. Pixel
 * centres, frame widths and scales are round numbers, so the true value often
 * lands exactly on a texel edge, where doubles could round to either side: it is
 * worked out in integers as floor(A / d1 + B / d2), every product below 2^54. */
static int64_t screen_texel(int k, int width, tarn_q16 scale, uint32_t time_ms, tarn_q16 speed,
                            int size)
{
    int64_t d1 = 2 * (int64_t)width * 65536, d2 = PAN_UNIT, r1, r2;
    int64_t q1 = floor_div((2 * (int64_t)k + 1) * scale * size, d1, &r1);
    int64_t q2 = floor_div(pan_remainder(time_ms, speed) * size, d2, &r2);
    int64_t t = (q1 + q2 + (r1 * d2 + r2 * d1 >= d1 * d2)) % size;
    return t < 0 ? t + size : t;
}

/* Pixels shifted by a map texel channel c: round((2c - 255) / 255 * distortion * width),
 * halves up, in integers for the same reason (the numerator is below 2^50). */
static int64_t screen_shift(uint8_t c, tarn_q16 distortion, int width)
{
    int64_t num = (int64_t)(2 * c - 255) * distortion * width, den = 255 * 65536LL, r;
    return floor_div(2 * num + den, 2 * den, &r);
}

/* The pixel whose colour lands on (i, j): the map is read at the pixel centre in
 * frame widths (both axes: the waves stay round on a wide frame), and its texel is
 * used as decoded, not renormalised. */
static size_t displaced_pixel(const tarn_underwater *u, int width, int height, uint32_t time_ms,
                              int i, int j)
{
    const tarn_texture *map = u->normal_map;
    int64_t tx = screen_texel(i, width, u->pan.scale, time_ms, u->pan.speed_u, map->width);
    int64_t ty = screen_texel(j, width, u->pan.scale, time_ms, u->pan.speed_v, map->height);
    const uint8_t *texel = map->rgb + 3 * ((size_t)ty * map->width + (size_t)tx);
    double qi = clamp_index((double)(i + screen_shift(texel[0], u->distortion, width)), width);
    double qj = clamp_index((double)(j + screen_shift(texel[1], u->distortion, width)), height);
    return (size_t)qj * width + (size_t)qi;
}

void tarn_ref_apply_underwater(const tarn_underwater *u, int width, int height, uint32_t time_ms,
                               const uint8_t *rgb, const double *depth, uint8_t *out)
{
    for (int j = 0; j < height; j++)
        for (int i = 0; i < width; i++) {
            size_t q = displaced_pixel(u, width, height, time_ms, i, j);
            double tint = 1.0 - exp2(-q16(u->tint_density) * depth[q]);
            uint8_t *o = out + 3 * ((size_t)j * width + i);
            for (int c = 0; c < 3; c++) {
                double cq = rgb[3 * q + c], target = tarn_ref_channel(u->tint_rgb, c);
                o[c] = (uint8_t)tarn_ref_round_to_byte(cq + (target - cq) * tint);
            }
        }
}
