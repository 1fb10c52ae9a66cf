/* vertex.c: object space to view space, and per-vertex lighting. */
#include "geometry/geometry_internal.h"

static unsigned bit_length_u64(uint64_t v)
{
    unsigned n = 0;
    while (v != 0) { n++; v >>= 1; }
    return n;
}

/* The view position's row i is floor(S / 2^f), saturated, f = to_view_frac_bits
 * (11..30), where S = sum_k m_k p_k + origin_i 2^f + 2^(f-1): the rounded shift of
 * the products' sum plus the origin, taken in one step (adding a multiple of 2^f
 * before the floor is adding it after). A core with 32x32 -> 64-bit products sums S
 * whole (tarn__vertex_position); the others (tarn__vertex_position_by_halves) take
 * it in 32-bit words, with each product split into four of 16-bit halves:
 *   m = mh 2^16 + ml   (ml in [0, 2^16), mh in [-2^13, 2^13] as |m| <= 2^29)
 *   P = p + 2^31 = ph 2^16 + pl   (the coordinate's bits with the top one flipped:
 *                                  ph, pl in [0, 2^16))
 * so m p = mh ph 2^32 + (mh pl + ml ph) 2^16 + ml pl - m 2^31. The -2^31 sum_k m_k
 * is the same for every vertex, and goes into the start with the origin and the half.
 * Column sums (weights 1, 2^16, 2^32), each product below 2^32 unsigned or 2^29 in
 * magnitude:
 *   low    = start_low + sum lo16(ml pl)                       < 2^18
 *   middle = start_middle + sum (hi16(ml pl) + lo16(ml ph) + mh pl)
 *   high   = start_high + sum (hi16(ml ph) + mh ph)            (modulo 2^32)
 * The three mh pl lie within +-3 2^29, so the middle starts 3 2^29 = 0x6000 2^16 up
 * (and the high 0x6000 down): it stays in [0, 3 2^30 + 2^19), unsigned without
 * wrapping, and its carry into the high word is a plain shift. |S| < 2^63 (|m p| <=
 * 2^60, |origin 2^f| <= 2^61), so the high word, taken modulo 2^32, is S's. */
/* to_view = basis (Q1.30) * scale * rotation (Q16.16 each), kept with as many
 * fraction bits as the largest entry allows (at most 30), split as above with the
 * rows' starts from the object's origin in view space. */
static void object_to_view_matrix(const tarn_view *view, const tarn_object *object,
                                  tarn_object_xform *xform, const tarn_q16 origin[3])
{
    int64_t product[3][3]; /* Q?.46 */
    uint64_t largest = 0;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            int64_t sum = 0;
            for (int k = 0; k < 3; k++) {
                int64_t scaled = tarn_round_shift_i64(tarn_mul_i32_wide(object->scale, object->rotation[k][j]), 16);
                sum += tarn_mul_i32_wide(view->basis[i][k], tarn_sat_i64_to_i32(scaled));
            }
            product[i][j] = sum;
            uint64_t magnitude = sum < 0 ? (uint64_t)0 - (uint64_t)sum : (uint64_t)sum;
            if (magnitude > largest) largest = magnitude;
        }
    }
    /* Entries below 2^29 keep each product with a Q16.16 coordinate under 2^60, so
     * the three-term sums in tarn__vertex_position cannot overflow. */
    unsigned drop = bit_length_u64(largest) > 29 ? bit_length_u64(largest) - 29 : 0;
    if (drop < 16) drop = 16; /* at most 30 fraction bits */
    const unsigned f = 46 - drop;
    xform->to_view_frac_bits = f;
    for (int i = 0; i < 3; i++) {
        int32_t entries = 0; /* within +-3 2^29 */
        for (int j = 0; j < 3; j++) {
            const int32_t m = (int32_t)tarn_round_shift_i64(product[i][j], drop);
            const int32_t low = (int32_t)((uint32_t)m & 0xFFFFu);
            xform->to_view_low[i][j] = (uint16_t)low;
            xform->to_view_high[i][j] = (int16_t)((m - low) / 65536); /* exact */
#if TARN_NATIVE_MUL_HI
            xform->to_view[i][j] = m;
#endif
            entries += m;
        }
        const int64_t rounded_origin = tarn_mul_i32_wide(origin[i], (int32_t)1 << f) + ((int32_t)1 << (f - 1u));
#if TARN_NATIVE_MUL_HI
        xform->row_start[i] = rounded_origin;
#endif
        const uint64_t bits = (uint64_t)(rounded_origin - 2 * tarn_mul_i32_wide(entries, (int32_t)1 << 30));
        xform->row_start_low[i] = (uint16_t)(bits & 0xFFFFu);
        xform->row_start_middle[i] = ((uint32_t)bits >> 16) + 0x60000000u;
        xform->row_start_high[i] = (uint32_t)(bits >> 32) - 0x6000u;
    }
}

static void object_origin_in_view(const tarn_view *view, const tarn_object *object, tarn_q16 origin[3])
{
    const int64_t offset[3] = {(int64_t)object->position.x - view->eye.x,
                               (int64_t)object->position.y - view->eye.y,
                               (int64_t)object->position.z - view->eye.z};
    for (int i = 0; i < 3; i++) {
        int64_t sum = 0;
        for (int k = 0; k < 3; k++) sum += view->basis[i][k] * offset[k];
        origin[i] = tarn_sat_i64_to_i32(tarn_round_shift_i64(sum, 30));
    }
}

/* basis (Q1.30) * rotation (Q16.16) in Q1.30: rotates object normals into view space. */
static void normal_to_view_matrix(const tarn_view *view, const tarn_object *object,
                                  tarn_object_xform *xform)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int64_t sum = 0;
            for (int k = 0; k < 3; k++) sum += tarn_mul_i32_wide(view->basis[i][k], object->rotation[k][j]);
            xform->normal_to_view[i][j] = tarn_sat_i64_to_i32(tarn_round_shift_i64(sum, 16));
        }
}

/* What lighting a vertex takes: the light in object space, the material's tint,
 * and for fresnel water the normals' rotation into view space. */
static void object_lighting_setup(const tarn_view *view, const tarn_object *object, tarn_object_xform *xform)
{
    const tarn_water *water = object->material->water;
    xform->fresnel = TARN_LINK_WATER && water != NULL && (TARN_LINK_WATER_FEATURES & TARN_WATER_FRESNEL) != 0 &&
                     (water->features & TARN_WATER_FRESNEL);
    if (xform->fresnel) normal_to_view_matrix(view, object, xform);
    /* The rotation is orthonormal: object-space light = rotation^T * light. */
    const tarn_q16 light[3] = {view->light_dir.x, view->light_dir.y, view->light_dir.z};
    for (int j = 0; j < 3; j++) {
        int64_t sum = 0;
        for (int k = 0; k < 3; k++) sum += tarn_mul_i32_wide(object->rotation[k][j], light[k]);
        xform->light_dir[j] = tarn_sat_i64_to_i32(tarn_round_shift_i64(sum, 16));
    }
    xform->unlit = object->material->unlit != 0;
    const uint32_t tint = object->material->colour_rgb;
    for (int c = 0; c < 3; c++)
        xform->tint_q16[c] = ((((tint >> (16 - 8 * c)) & 0xFFu) * 65536u) + 127u) / 255u;
}

void tarn__object_xform_setup(const tarn_view *view, const tarn_object *object,
                             tarn_object_xform *xform)
{
    tarn_q16 origin[3];
    object_origin_in_view(view, object, origin);
    object_to_view_matrix(view, object, xform, origin);
    /* static vertices come lit */
    if (TARN_LINK_COMPUTED_VERTICES &&
        !(TARN_LINK_STATIC_VERTICES && view->static_vertices && object->static_vertices != NULL))
        object_lighting_setup(view, object, xform);
}

void tarn__vertex_position_by_halves(const tarn_object_xform *xform, const tarn_vec3 *p,
                                     tarn_view_vertex *out)
{
    /* the arithmetic and its bounds: above object_to_view_matrix. Each coordinate's
     * bits with the top one flipped, p + 2^31, in 16-bit halves. */
    const uint32_t x = (uint32_t)p->x ^ 0x80000000u, y = (uint32_t)p->y ^ 0x80000000u,
                   z = (uint32_t)p->z ^ 0x80000000u;
    const uint32_t half[6] = {x & 0xFFFFu, x >> 16, y & 0xFFFFu, y >> 16, z & 0xFFFFu, z >> 16};
    const unsigned f = xform->to_view_frac_bits;
    tarn_q16 *dest[3] = {&out->x, &out->y, &out->d};
    out->x_low = out->y_low = out->d_low = 0u;
    for (int i = 0; i < 3; i++) {
        uint32_t low = xform->row_start_low[i], middle = xform->row_start_middle[i],
                 high = xform->row_start_high[i];
        for (int k = 0; k < 3; k++) {
            const uint32_t ml = xform->to_view_low[i][k];
            const int32_t mh = xform->to_view_high[i][k];
            const uint32_t pl = half[2 * k], ph = half[2 * k + 1];
            const uint32_t ll = ml * pl, lh = ml * ph;
            low += ll & 0xFFFFu;
            middle += (ll >> 16) + (lh & 0xFFFFu) + (uint32_t)(mh * (int32_t)pl);
            high += (lh >> 16) + (uint32_t)(mh * (int32_t)ph);
        }
        middle += low >> 16;
        high += middle >> 16;
        const uint32_t word = (middle << 16) | (low & 0xFFFFu);
        /* floor(S / 2^f) = high 2^(32-f) + floor(word / 2^f) when that fits 32 bits,
         * which is when the signed high word lies in [-2^(f-1), 2^(f-1)) */
        int32_t v;
        if (((high + (1u << (f - 1u))) >> f) == 0u)
            v = (int32_t)((high << (32u - f)) | (word >> f));
        else
            v = (high >> 31) ? INT32_MIN : INT32_MAX;
        *dest[i] = v;
    }
}

#if TARN_NATIVE_MUL_HI
/* floor(v / 2^s) for s < 64, without >> of a negative number: a negative v's floor
 * is -(~v >> s) - 1, ~v being -v - 1, not negative. */
static int64_t floor_shift_i64(int64_t v, unsigned s)
{
    return v >= 0 ? (int64_t)((uint64_t)v >> s) : -(int64_t)(~(uint64_t)v >> s) - 1;
}

void tarn__vertex_position(const tarn_object_xform *xform, const tarn_vec3 *p, tarn_view_vertex *out)
{
    /* |S| < 2^63: the bounds above object_to_view_matrix */
    const int32_t c[3] = {p->x, p->y, p->z};
    tarn_q16 *dest[3] = {&out->x, &out->y, &out->d};
    out->x_low = out->y_low = out->d_low = 0u;
    for (int i = 0; i < 3; i++) {
        int64_t sum = xform->row_start[i];
        for (int k = 0; k < 3; k++) sum += (int64_t)xform->to_view[i][k] * c[k];
        *dest[i] = tarn_sat_i64_to_i32(floor_shift_i64(sum, xform->to_view_frac_bits));
    }
}
#endif

/* (a * b + 2^15) >> 16, for a result within 32 bits: one 32-bit product when both
 * are below 2^16 (a shade, a colour, a unit dot product: nearly always), which
 * the Cortex-M0 takes in one instruction instead of four and their carries. */
static uint32_t mul_q16_rounded(uint32_t a, uint32_t b)
{
    if ((a | b) < 65536u) return (a * b + 32768u) >> 16; /* below 2^32 - 2^16 before the shift */
    if (a == 65536u) return b; /* times one, a white tint: (2^16 b + 2^15) >> 16 */
    return (uint32_t)((tarn_mul_u32_wide(a, b) + 32768u) >> 16);
}

/* shade = min(1, ambient + light * max(0, N.L)), Q0.16 per channel. */
static uint32_t shade_q16(const tarn_view *view, int channel, int32_t n_dot_l_q16)
{
    uint32_t diffuse = n_dot_l_q16 > 0 ? mul_q16_rounded(view->light_q16[channel], (uint32_t)n_dot_l_q16) : 0u;
    uint32_t shade = view->ambient_q16[channel] + diffuse;
    return shade > 65536u ? 65536u : shade;
}

/* (1 - n.v)^2 in Q1.15: n the vertex normal in view space, v the unit vector from
 * the vertex (already in view space, `at`) toward the camera at the origin. */
static int32_t fresnel_q15(const tarn_object_xform *xform, const tarn_vec3 *normal,
                           const tarn_view_vertex *at)
{
    const int32_t n_object[3] = {normal->x, normal->y, normal->z};
    const int32_t position[3] = {at->x, at->y, at->d};
    int64_t n_dot_p = 0; /* Q16.16 * Q16.16 */
    uint64_t length2 = 0;
    /* every product has 32-bit operands: tarn_mul_i32_wide, not a 64x64 multiply */
    for (int i = 0; i < 3; i++) {
        int64_t n_view = 0;
        for (int k = 0; k < 3; k++) n_view += tarn_mul_i32_wide(xform->normal_to_view[i][k], n_object[k]);
        /* the normal is bounded (tarn__unit_vector_bounded), so with any rotation the
         * component stays below 2^20 and the sum within 64 bits */
        n_dot_p += tarn_mul_i32_wide((int32_t)tarn_round_shift_i64(n_view, 30), position[i]);
        length2 += (uint64_t)tarn_mul_i32_wide(position[i], position[i]);
    }
    int64_t length = (int64_t)tarn_isqrt_u64(length2); /* Q16.16 */
    if (length == 0) return 0;
    /* n.v = -(n.p)/|p|, as Q1.15 (truncated, as C's / would), clamped to [-1, 1] */
    int64_t n_dot_v = tarn_divide_once_i64(-n_dot_p, (uint32_t)length) / 2;
    n_dot_v = n_dot_v > 32768 ? 32768 : (n_dot_v < -32768 ? -32768 : n_dot_v);
    uint32_t one_minus = (uint32_t)(32768 - n_dot_v); /* 0..65536 */
    if (one_minus > 32768u) one_minus = 32768u; /* saturate(1 - n.v) */
    return (int32_t)((one_minus * one_minus + 16384u) >> 15);
}

/* A unit vector's components lie within +-1; one far longer (the scene's normals and
 * light are unit vectors by contract) has its components cut at +-2, which keeps the
 * three-term 64-bit sums it enters from overflowing. */
tarn_vec3 tarn__unit_vector_bounded(const tarn_vec3 *v)
{
    const int32_t limit = 2 * TARN_Q16_ONE;
    const tarn_vec3 bounded = {tarn_clamp_i32(v->x, -limit, limit), tarn_clamp_i32(v->y, -limit, limit),
                               tarn_clamp_i32(v->z, -limit, limit)};
    return bounded;
}

void tarn__vertex_shade(const tarn_view *view, const tarn_object_xform *xform,
                       const tarn_mesh *mesh, uint16_t index, tarn_view_vertex *out)
{
    const tarn_vec3 normal = tarn__unit_vector_bounded(&mesh->normals[index]);
    const tarn_vec3 *n = &normal;
    int64_t dot = tarn_mul_i32_wide(n->x, xform->light_dir[0]) + tarn_mul_i32_wide(n->y, xform->light_dir[1]) +
                  tarn_mul_i32_wide(n->z, xform->light_dir[2]);
    int32_t n_dot_l = tarn_sat_i64_to_i32(tarn_round_shift_i64(dot, 16));
    uint32_t vertex_rgb = mesh->colours ? mesh->colours[index] : 0xFFFFFFu;
    for (int c = 0; c < 3; c++) {
        uint32_t shade = xform->unlit ? 65536u : shade_q16(view, c, n_dot_l);
        uint32_t factor = mul_q16_rounded(xform->tint_q16[c], shade);
        uint32_t vertex_channel = (vertex_rgb >> (16 - 8 * c)) & 0xFFu;
        out->lit[c] = (uint16_t)((vertex_channel * factor + 128u) >> 8); /* Q8.8, at most 65280 */
    }
    out->uv = tarn__vertex_uv(mesh, index);
    out->uv_low[0] = out->uv_low[1] = 0u;
    out->fresnel = (uint16_t)(xform->fresnel ? fresnel_q15(xform, n, out) : 0);
}

tarn_uv tarn__vertex_uv(const tarn_mesh *mesh, uint16_t index)
{
    const tarn_uv none = {0, 0};
    return mesh->uvs != NULL ? mesh->uvs[index] : none;
}
