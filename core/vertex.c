/* vertex.c: object space to view space, and per-vertex lighting. */
#include "pipeline.h"

static unsigned bit_length_u64(uint64_t v)
{
    unsigned n = 0;
    while (v != 0) { n++; v >>= 1; }
    return n;
}

/* to_view = basis (Q1.30) * scale * rotation (Q16.16 each), kept with as many
 * fraction bits as the largest entry allows (at most 30). */
static void object_to_view_matrix(const tarn_view *view, const tarn_object *object,
                                  tarn_object_xform *xform)
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
     * the three-term sums in tarn_vertex_position cannot overflow. */
    unsigned drop = bit_length_u64(largest) > 29 ? bit_length_u64(largest) - 29 : 0;
    if (drop < 16) drop = 16; /* at most 30 fraction bits */
    xform->to_view_frac_bits = 46 - drop;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            xform->to_view[i][j] = (int32_t)tarn_round_shift_i64(product[i][j], drop);
}

static void object_origin_in_view(const tarn_view *view, const tarn_object *object,
                                  tarn_object_xform *xform)
{
    const int64_t offset[3] = {(int64_t)object->position.x - view->eye.x,
                               (int64_t)object->position.y - view->eye.y,
                               (int64_t)object->position.z - view->eye.z};
    for (int i = 0; i < 3; i++) {
        int64_t sum = 0;
        for (int k = 0; k < 3; k++) sum += view->basis[i][k] * offset[k];
        xform->origin[i] = tarn_sat_i64_to_i32(tarn_round_shift_i64(sum, 30));
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

void tarn_object_xform_setup(const tarn_view *view, const tarn_object *object,
                             tarn_object_xform *xform)
{
    object_to_view_matrix(view, object, xform);
    const tarn_water *water = object->material->water;
    xform->fresnel = TARN_LINK_WATER && water != NULL && (TARN_LINK_WATER_FEATURES & TARN_WATER_FRESNEL) != 0 &&
                     (water->features & TARN_WATER_FRESNEL);
    if (xform->fresnel) normal_to_view_matrix(view, object, xform);
    object_origin_in_view(view, object, xform);
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

void tarn_vertex_position(const tarn_object_xform *xform, const tarn_vec3 *p,
                          tarn_view_vertex *out)
{
    tarn_q16 *dest[3] = {&out->x, &out->y, &out->d};
    for (int i = 0; i < 3; i++) {
        int64_t sum = tarn_mul_i32_wide(xform->to_view[i][0], p->x) + tarn_mul_i32_wide(xform->to_view[i][1], p->y) +
                      tarn_mul_i32_wide(xform->to_view[i][2], p->z);
        int64_t view_q16 = tarn_round_shift_i64(sum, xform->to_view_frac_bits) + xform->origin[i];
        *dest[i] = tarn_sat_i64_to_i32(view_q16);
    }
}

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
        /* the normal is bounded (tarn_unit_vector_bounded), so with any rotation the
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
tarn_vec3 tarn_unit_vector_bounded(const tarn_vec3 *v)
{
    const int32_t limit = 2 * TARN_Q16_ONE;
    const tarn_vec3 bounded = {tarn_clamp_i32(v->x, -limit, limit), tarn_clamp_i32(v->y, -limit, limit),
                               tarn_clamp_i32(v->z, -limit, limit)};
    return bounded;
}

void tarn_vertex_shade(const tarn_view *view, const tarn_object_xform *xform,
                       const tarn_mesh *mesh, uint16_t index, tarn_view_vertex *out)
{
    const tarn_vec3 normal = tarn_unit_vector_bounded(&mesh->normals[index]);
    const tarn_vec3 *n = &normal;
    int64_t dot = tarn_mul_i32_wide(n->x, xform->light_dir[0]) + tarn_mul_i32_wide(n->y, xform->light_dir[1]) +
                  tarn_mul_i32_wide(n->z, xform->light_dir[2]);
    int32_t n_dot_l = tarn_sat_i64_to_i32(tarn_round_shift_i64(dot, 16));
    uint32_t vertex_rgb = mesh->colours ? mesh->colours[index] : 0xFFFFFFu;
    for (int c = 0; c < 3; c++) {
        uint32_t shade = xform->unlit ? 65536u : shade_q16(view, c, n_dot_l);
        uint32_t factor = mul_q16_rounded(xform->tint_q16[c], shade);
        uint32_t vertex_channel = (vertex_rgb >> (16 - 8 * c)) & 0xFFu;
        out->lit[c] = (int32_t)((vertex_channel * factor + 128u) >> 8); /* Q8.8 */
    }
    out->uv = tarn_vertex_uv(mesh, index);
    out->fresnel = xform->fresnel ? fresnel_q15(xform, n, out) : 0;
}

tarn_uv tarn_vertex_uv(const tarn_mesh *mesh, uint16_t index)
{
    const tarn_uv none = {0, 0};
    return mesh->uvs != NULL ? mesh->uvs[index] : none;
}
