/* water.c: the water pixel, step by step as tarn_water.h numbers them. Colours are
 * Q8.8 per channel (255.0 = 65280) until the final rounding. */
#include "water.h"

#define Q16_ONE 65536u
#define Q15_ONE 32768

/* ---- 32-bit helpers ------------------------------------------------------------ */

/* a * b / 2^16 for unsigned Q16.16 values, saturated to INT32_MAX: 16x16-bit
 * partial products summed in 64 bits (adds only; no divider, no 64-bit multiply). */
uint32_t tarn_water_mul_q16(uint32_t a, uint32_t b)
{
    const uint32_t ah = a >> 16, al = a & 0xFFFFu, bh = b >> 16, bl = b & 0xFFFFu;
    const uint64_t sum = ((uint64_t)(ah * bh) << 16) + ah * bl + al * bh + ((al * bl) >> 16);
    return sum > (uint64_t)INT32_MAX ? (uint32_t)INT32_MAX : (uint32_t)sum;
}

/* (a * b / 2^16) mod 2^16 for texture coordinates: the fraction of a repeat. Only
 * low bits matter, so 16x16-bit products suffice, and negative or wrapped inputs
 * give the right fraction too. */
uint32_t tarn_water_repeat_fraction(uint32_t a, uint32_t b)
{
    const uint32_t ah = a >> 16, al = a & 0xFFFFu, bh = b >> 16, bl = b & 0xFFFFu;
    return (ah * bl + al * bh + ((al * bl) >> 16)) & 0xFFFFu;
}

static uint32_t channel_q8(uint32_t rgb, int c)
{
    return ((rgb >> (16 - 8 * c)) & 0xFFu) << 8;
}

/* A texel's channel decoded to a normal component, (2c - 255) / 255, Q1.15. */
int32_t tarn_water_normal_component(uint8_t c)
{
    return ((2 * (int32_t)c - 255) * 257) / 2;
}

const uint8_t *tarn_water_texel_at(const tarn_texture *t, uint32_t u_fraction, uint32_t v_fraction)
{
    const unsigned log2_w = 31u - tarn_clz32(t->width), log2_h = 31u - tarn_clz32(t->height);
    const uint32_t x = u_fraction >> (16u - log2_w), y = v_fraction >> (16u - log2_h);
    return &t->rgb[3u * ((y << log2_w) + x)];
}

static const uint8_t *panned_texel(const tarn_texture *t, const tarn_panning *pan,
                                   const uint16_t offset[2], const tarn_water_input *in)
{
    uint32_t u = (tarn_water_repeat_fraction(in->u, (uint32_t)pan->scale) + offset[0]) & 0xFFFFu;
    uint32_t v = (tarn_water_repeat_fraction(in->v, (uint32_t)pan->scale) + offset[1]) & 0xFFFFu;
    return tarn_water_texel_at(t, u, v);
}

uint32_t tarn_water_linear_depth(uint32_t iz_q30, tarn_q16 near, tarn_q16 far, unsigned recip_steps)
{
    if (iz_q30 == 0u) return (uint32_t)far;
    const unsigned lz = tarn_clz32(iz_q30);
    const uint32_t recip = tarn_recip_q30(iz_q30 << lz, recip_steps); /* 2^62 / (iz << lz) */
    const unsigned near_shift = tarn_clz32((uint32_t)near);
    /* d = near * recip * 2^(lz - 32), with near pre-shifted for precision */
    const uint32_t scaled = tarn_mul_hi_u32((uint32_t)near << near_shift, recip);
    if (lz >= near_shift) {
        unsigned up = lz - near_shift;
        return up >= 31u || scaled > ((uint32_t)INT32_MAX >> up) ? (uint32_t)INT32_MAX : scaled << up;
    }
    return scaled >> (near_shift - lz);
}

static uint32_t linear_depth(const tarn_water_context *w, uint32_t iz_q30)
{
    return tarn_water_linear_depth(iz_q30, w->near, w->far, w->recip_steps);
}

static uint32_t background_depth_q30(const tarn_water_context *w, int32_t offset)
{
    if (w->depth_bits == 16) return (uint32_t)((const uint16_t *)w->background_depth)[offset] << 14;
    return ((const uint32_t *)w->background_depth)[offset];
}

static int32_t background_offset(const tarn_water_context *w, int32_t i, int32_t j)
{
    return (j - w->background_rect.y0) * w->background_stride + (i - w->background_rect.x0);
}

/* 2^(-rate * x) for rate, x >= 0 (Q16.16), Q0.16. */
static uint32_t decay(const tarn_water_context *w, uint32_t rate, uint32_t x)
{
    return tarn_exp2_neg_q16(-(tarn_q16)tarn_water_mul_q16(rate, x), w->exp2);
}

/* ---- the steps ------------------------------------------------------------------- */

typedef struct {
    int32_t x, y, z;     /* N, Q1.15 */
    int32_t a_x, b_x;    /* the maps' own x components, for sparkles */
    int has_b;
} water_normal;

static void decode_normal(const uint8_t *texel, int32_t out[3])
{
    for (int k = 0; k < 3; k++) out[k] = tarn_water_normal_component(texel[k]);
}

/* Step 1: N = normalize(strength * (a.xy + b.xy), a.z * b.z). */
static water_normal surface_normal(const tarn_water_context *w, const tarn_water_input *in)
{
    const tarn_water *water = w->water;
    water_normal n = {0, 0, Q15_ONE, 0, 0, 0};
    if (!(water->features & TARN_WATER_NORMALS) || water->normal_a == NULL) return n;
    int32_t a[3], b[3] = {0, 0, Q15_ONE};
    decode_normal(panned_texel(water->normal_a, &water->pan_a, w->pan_a, in), a);
    n.has_b = water->normal_b != NULL;
    if (n.has_b) decode_normal(panned_texel(water->normal_b, &water->pan_b, w->pan_b, in), b);
    n.a_x = a[0];
    n.b_x = b[0];
    /* strength (Q16.16) times a sum of two Q1.15 components, in Q2.14 with all of
     * the strength's bits: (a + b) * 2^15 * strength / 2^32 */
    const uint32_t strength = (uint32_t)water->normal_strength;
    int32_t v[3] = {tarn_mul_hi_s32_u32((a[0] + b[0]) * 32768, strength),
                    tarn_mul_hi_s32_u32((a[1] + b[1]) * 32768, strength), (a[2] * b[2]) >> 16};
    /* the largest component to [2^13, 2^14): read as Q2.13, |v| is in [1, 2 sqrt 3) */
    int32_t largest = 0;
    for (int k = 0; k < 3; k++) largest |= v[k] < 0 ? -v[k] : v[k];
    if (largest == 0) return n;
    const int shift = (int)(31u - tarn_clz32((uint32_t)largest)) - 13;
    for (int k = 0; k < 3; k++) v[k] = shift >= 0 ? tarn_floor_shift(v[k], (unsigned)shift) : v[k] * (1 << -shift);
    const uint32_t length2 = (uint32_t)(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); /* Q4.26, < 2^30 */
    const int32_t inverse = (int32_t)tarn_rsqrt_q16(length2 >> 10);            /* 1/|v|, Q16.16 <= 1 */
    n.x = (v[0] * inverse) >> 14; /* Q2.13 * Q16.16 -> Q1.15 */
    n.y = (v[1] * inverse) >> 14;
    n.z = (v[2] * inverse) >> 14;
    return n;
}

typedef struct {
    uint32_t colour[3]; /* B, Q8.8 */
    uint32_t depth;     /* db, Q16.16 world units */
} background_sample;

static background_sample sample_background(const tarn_water_context *w, int32_t i, int32_t j)
{
    background_sample s;
    const int32_t offset = background_offset(w, i, j);
    const uint32_t rgb = w->background[offset];
    for (int c = 0; c < 3; c++) s.colour[c] = channel_q8(rgb, c);
    s.depth = linear_depth(w, background_depth_q30(w, offset));
    return s;
}

/* Step 2: the refracted sample, or the pixel's own when it would land in front. */
static background_sample refracted(const tarn_water_context *w, int32_t i, int32_t j,
                                   const water_normal *n, uint32_t surface_depth)
{
    background_sample own = sample_background(w, i, j);
    if (!(w->water->features & TARN_WATER_REFRACTION)) return own;
    uint32_t reach = own.depth > surface_depth ? own.depth - surface_depth : 0u;
    if (reach > Q16_ONE) reach = Q16_ONE; /* saturate(db - ds), Q0.16 */
    const int32_t normal[2] = {n->x, n->y};
    int32_t target[2] = {i, j};
    for (int k = 0; k < 2; k++) {
        /* N (Q1.15) * pixels per unit normal (Q16.16) / 2^23 -> pixels, Q24.8 */
        int32_t offset_q8 = tarn_mul_hi_s32_u32(normal[k] * 512, w->refraction_px);
        offset_q8 = tarn_clamp_i32(offset_q8, -(64 << 8), 64 << 8);
        offset_q8 = (offset_q8 * (int32_t)(reach >> 1)) / Q15_ONE; /* times saturate(db - ds) */
        target[k] += tarn_floor_shift(offset_q8 + 128, 8);
    }
    target[0] = tarn_clamp_i32(target[0], w->sample_rect.x0, w->sample_rect.x1 - 1);
    target[1] = tarn_clamp_i32(target[1], w->sample_rect.y0, w->sample_rect.y1 - 1);
    background_sample shifted = sample_background(w, target[0], target[1]);
    return shifted.depth < surface_depth ? own : shifted;
}

/* Steps 4 and 5: fog and absorption by the water between surface and background. */
static void fog_and_absorb(const tarn_water_context *w, uint32_t diff, uint32_t colour[3])
{
    const tarn_water *water = w->water;
    if (water->features & TARN_WATER_FOG) {
        const int32_t keep = (int32_t)(decay(w, (uint32_t)water->fog_density, diff) >> 1); /* Q1.15 */
        for (int c = 0; c < 3; c++) {
            const int32_t fog = (int32_t)channel_q8(water->fog_rgb, c);
            colour[c] = (uint32_t)(fog + (((int32_t)colour[c] - fog) * keep) / Q15_ONE);
        }
    }
    if (water->features & TARN_WATER_ABSORPTION) {
        const uint32_t x = water->absorption_squared ? tarn_water_mul_q16(diff, diff) : diff;
        const uint32_t absorbed = (Q16_ONE - decay(w, (uint32_t)water->absorption, x)) >> 1; /* Q1.15 */
        for (int c = 0; c < 3; c++) {
            const uint32_t inverse = 65280u - channel_q8(water->absorb_rgb, c);
            const uint32_t loss = (inverse * absorbed) >> 15;
            colour[c] = colour[c] > loss ? colour[c] - loss : 0u;
        }
    }
}

/* Step 6: the surface colour S, Q8.8. */
static void surface_colour(const tarn_water_context *w, uint32_t diff, uint32_t out[3])
{
    const tarn_water *water = w->water;
    if (!(water->features & TARN_WATER_DEPTH_COLOUR)) {
        for (int c = 0; c < 3; c++) out[c] = channel_q8(water->albedo_rgb, c);
        return;
    }
    uint32_t t = tarn_water_mul_q16(diff, w->inv_depth_scale);
    if (t > Q16_ONE) t = Q16_ONE;
    if (water->colour_ramp != NULL) {
        const tarn_texture *ramp = water->colour_ramp;
        const uint32_t x = (t * (uint32_t)(ramp->width - 1u) + 32768u) >> 16;
        for (int c = 0; c < 3; c++) out[c] = (uint32_t)ramp->rgb[3u * x + (uint32_t)c] << 8;
        return;
    }
    for (int c = 0; c < 3; c++) {
        const int32_t shallow = (int32_t)channel_q8(water->shallow_rgb, c);
        const int32_t deep = (int32_t)channel_q8(water->deep_rgb, c);
        out[c] = (uint32_t)(shallow + ((deep - shallow) * (int32_t)(t >> 1)) / Q15_ONE);
    }
}

/* Step 7: lit surface over the background by (fresnel-raised) alpha. */
static void compose(const tarn_water_context *w, const tarn_water_input *in, const uint32_t surface[3],
                    uint32_t colour[3])
{
    const tarn_water *water = w->water;
    uint32_t alpha = (uint32_t)water->alpha >> 1; /* Q1.15 */
    if (water->features & TARN_WATER_FRESNEL) {
        const uint32_t raise = ((uint32_t)water->fresnel >> 1) * in->fresnel >> 15;
        alpha += ((32768u - alpha) * raise) >> 15;
    }
    for (int c = 0; c < 3; c++) {
        /* S * lit / 255 in Q8.8: product / 65280, as product * 257 / 2^24 (fits: < 2^32) */
        const uint32_t product = surface[c] * in->lit[c];
        const uint32_t surface_lit = (product + (product >> 8) + 32768u) >> 16;
        colour[c] = (surface_lit * alpha + colour[c] * (32768u - alpha)) >> 15;
    }
}

/* max(0, N.h)^power, Q1.15. */
static uint32_t specular_term(const tarn_water_context *w, const water_normal *n)
{
    int32_t dot = (n->x * w->half_vector[0] + n->y * w->half_vector[1] + n->z * w->half_vector[2]) >> 15;
    if (dot <= 0) return 0u;
    uint32_t base = (uint32_t)(dot > Q15_ONE ? Q15_ONE : dot), result = Q15_ONE;
    for (unsigned power = w->water->specular_power; power != 0u; power >>= 1) {
        if (power & 1u) result = (result * base) >> 15;
        base = (base * base) >> 15;
    }
    return result;
}

/* Step 8. */
static void add_specular(const tarn_water_context *w, const water_normal *n, uint32_t colour[3])
{
    if (!(w->water->features & TARN_WATER_SPECULAR)) return;
    const uint32_t amount = (specular_term(w, n) * ((uint32_t)w->water->specular >> 2)) >> 15; /* Q2.14 */
    for (int c = 0; c < 3; c++) colour[c] += (w->light_q8[c] * (amount >> 2)) >> 12;
}

/* Step 9. */
static void add_foam(const tarn_water_context *w, const tarn_water_input *in, uint32_t diff,
                     uint32_t colour[3])
{
    const tarn_water *water = w->water;
    if (!(water->features & TARN_WATER_FOAM) || water->foam_texture == NULL) return;
    uint32_t f = tarn_water_mul_q16(diff, w->inv_foam_distance);
    if (f >= Q16_ONE) return;
    const uint16_t turns = (uint16_t)(water->foam_line_count * (f - w->foam_phase));
    int32_t wave = tarn_sin_q15(turns);
    uint32_t lines = wave > 0 ? ((uint32_t)wave * ((Q16_ONE - f) >> 1)) >> 14 : 0u; /* Q0.16 */
    /* foam where red / 255 >= f - lines: compared exactly, red * 2^16 against 255 * (f - lines) */
    const int32_t red = panned_texel(water->foam_texture, &water->foam_pan, w->foam_pan, in)[0];
    if (red * 65536 < 255 * ((int32_t)f - (int32_t)lines)) return; /* both below 2^24 */
    const int32_t opacity = (int32_t)((uint32_t)water->foam_opacity >> 1);
    for (int c = 0; c < 3; c++) {
        const int32_t foam = (int32_t)channel_q8(water->foam_rgb, c);
        colour[c] = (uint32_t)((int32_t)colour[c] + ((foam - (int32_t)colour[c]) * opacity) / Q15_ONE);
    }
}

/* Step 10. */
static void add_sparkles(const tarn_water_context *w, const water_normal *n, uint32_t colour[3])
{
    if (!(w->water->features & TARN_WATER_SPARKLES)) return;
    const uint32_t ax2 = (uint32_t)(n->a_x * n->a_x), bx2 = (uint32_t)(n->b_x * n->b_x);
    if (ax2 <= w->sparkle_threshold || (n->has_b && bx2 <= w->sparkle_threshold)) return;
    for (int c = 0; c < 3; c++) colour[c] += channel_q8(w->water->sparkle_rgb, c);
}

uint32_t tarn_water_shade(const tarn_water_context *w, int32_t i, int32_t j, const tarn_water_input *in)
{
    const uint32_t surface_depth = linear_depth(w, in->inv_depth);
    const water_normal n = surface_normal(w, in);
    background_sample below = refracted(w, i, j, &n, surface_depth);
    const uint32_t diff = below.depth > surface_depth ? below.depth - surface_depth : 0u;
    uint32_t colour[3] = {below.colour[0], below.colour[1], below.colour[2]};
    fog_and_absorb(w, diff, colour);
    uint32_t surface[3];
    surface_colour(w, diff, surface);
    compose(w, in, surface, colour);
    add_specular(w, &n, colour);
    add_foam(w, in, diff, colour);
    add_sparkles(w, &n, colour);
    uint32_t rgb = 0;
    for (int c = 0; c < 3; c++) {
        uint32_t byte = (colour[c] + 128u) >> 8;
        rgb = (rgb << 8) | (byte > 255u ? 255u : byte);
    }
    return rgb;
}

