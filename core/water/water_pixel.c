/* water_pixel.c: the water pixel, step by step as tarn_water.h numbers them: its
 * effects gathered into a gain and a base per channel, then applied to its
 * background. Colours are Q8.8 per channel (255.0 = 65280) until the final rounding. */
#include "water/water_internal.h"

#define Q16_ONE 65536u

/* Step 7's surface: S * lit / 255 in Q8.8 per channel. */
static void lit_surface(const tarn_water_input *in, const uint32_t surface[3], uint32_t lit[3])
{
    for (int c = 0; c < 3; c++) {
        /* product / 65280, as product * 257 / 2^24 (fits: < 2^32) */
        const uint32_t product = surface[c] * in->lit[c];
        lit[c] = (product + (product >> 8) + 32768u) >> 16;
    }
}

/* Step 7's opacity, Q1.15: the material's, raised by the fresnel term. */
static uint32_t surface_alpha(const tarn_water_context *w, const tarn_water_input *in)
{
    const uint32_t alpha = (uint32_t)w->water->alpha >> 1; /* Q1.15; [0, 1] by the scene check */
    return tarn__water_uses(w, TARN_WATER_FRESNEL) ? tarn__water_fresnel_alpha(w, in, alpha) : alpha;
}

/* Steps 4 to 8 gathered into the effects' gain, through, base and lift from the
 * fog keep (Q1.15), the lit surface and its alpha and the specular (Q8.8 each).
 * Every product stays below 2^32: each share is at most 65280 * 32768. */
static TARN_ALWAYS_INLINE void gather(const tarn_water_context *w, uint32_t diff, uint32_t keep,
                                      const uint32_t surface[3], uint32_t alpha, const uint32_t highlight[3],
                                      tarn_water_effects *e)
{
    const uint32_t through = 32768u - alpha;
    e->through = (uint16_t)through;
    if (tarn__water_uses(w, TARN_WATER_ABSORPTION)) {
        uint16_t loss[3];
        tarn__water_absorb(w, diff, loss);
        e->gain = (uint16_t)keep;
        for (int c = 0; c < 3; c++) {
            e->lift[c] = (int32_t)((w->fog_q8[c] * (32768u - keep)) >> 15) - (int32_t)loss[c];
            e->base[c] = ((surface[c] * alpha) >> 15) + highlight[c];
        }
        return;
    }
    e->gain = (uint16_t)((keep * through) >> 15);
    for (int c = 0; c < 3; c++) {
        const uint32_t fog_share = (w->fog_q8[c] * (32768u - keep)) >> 15;
        e->lift[c] = 0;
        e->base[c] = ((surface[c] * alpha + fog_share * through) >> 15) + highlight[c];
    }
}

/* Sparkles from the normal's map components. */
unsigned tarn__water_sharp_at(const tarn_water_context *w, const tarn_water_input *in, uint32_t foam_band,
                             const tarn_water_normal *n)
{
    unsigned sharp = 0u;
    if (tarn__water_uses(w, TARN_WATER_FOAM) && tarn__water_foam(w, in, foam_band)) sharp |= TARN_WATER_SHOWS_FOAM;
    if (tarn__water_uses(w, TARN_WATER_SPARKLES) && tarn__water_sparkles(w, n)) sharp |= TARN_WATER_SHOWS_SPARKLES;
    return sharp;
}

/* Step 4's fog keep (Q1.15, returned) and step 6's surface lit as step 7 lights
 * it, over `diff` of water (Q16.16) for a pixel with inputs `in`. */
static TARN_ALWAYS_INLINE uint32_t lit_surface_over(const tarn_water_context *w, const tarn_water_input *in,
                                                    uint32_t diff, uint32_t lit[3])
{
    const uint32_t keep = tarn__water_uses(w, TARN_WATER_FOG) ? tarn__water_fog(w, diff) : 32768u;
    uint32_t surface[3];
    if (tarn__water_uses(w, TARN_WATER_DEPTH_COLOUR))
        tarn__water_depth_colour(w, diff, surface);
    else
        for (int c = 0; c < 3; c++) surface[c] = tarn__water_channel_q8(w->water->albedo_rgb, c);
    lit_surface(in, surface, lit);
    return keep;
}

void tarn__water_effects_at(const tarn_water_context *w, int32_t i, int32_t j, const tarn_water_input *in,
                           uint32_t surface_depth, tarn_water_effects *e)
{
    tarn_water_normal n;
    tarn__water_pixel_normal(w, in, &n);
    /* without an apron a refracted sample may not move (offset_limit 0): it is the
     * pixel's own, and the M0's fast preset would pay a third of the water pixel for it */
    const tarn_water_sample below = tarn__water_refracts(w) ? tarn__water_refract(w, i, j, &n, surface_depth)
                                                            : tarn__water_background(w, i, j);
    e->offset[0] = (int8_t)(below.x - i); /* within the apron, at most TARN_WATER_APRON_MAX */
    e->offset[1] = (int8_t)(below.y - j);
    const uint32_t diff = below.depth > surface_depth ? below.depth - surface_depth : 0u;
    uint32_t lit[3], highlight[3] = {0, 0, 0};
    const uint32_t keep = lit_surface_over(w, in, diff, lit);
    if (tarn__water_uses(w, TARN_WATER_SPECULAR)) (void)tarn__water_specular(w, &n, highlight);
    gather(w, diff, keep, lit, surface_alpha(w, in), highlight, e);
    e->foam_band = tarn__water_uses(w, TARN_WATER_FOAM) ? tarn__water_foam_band(w, diff) : Q16_ONE;
    e->sharp = (uint8_t)tarn__water_sharp_at(w, in, e->foam_band, &n);
}

/* The background colour under the effects' offset, 0x00RRGGBB. The offset was
 * kept inside the frame for the pixel that found it, and only that pixel applies
 * an offset: blocks share no refracted effects. */
static uint32_t moved_background(const tarn_water_context *w, const tarn_water_effects *e, int32_t i, int32_t j)
{
    if (TARN_LINK_APRON) {
        /* over a backdrop a moved sample is read from its picture; the pixel's own
         * from the tile (a build without backdrops asks nothing more a pixel) */
        if (TARN_LINK_BACKDROP && w->flash != NULL && (e->offset[0] | e->offset[1]) != 0)
            return tarn__backdrop_colour_at(w->flash, (uint16_t)w->sample_rect.x1, i + e->offset[0], j + e->offset[1]);
        i += e->offset[0];
        j += e->offset[1];
    }
    return w->background[tarn__water_background_offset(w, i, j)];
}

/* Steps 4 to 8 of effects `e` over background colour `rgb_below` (0x00RRGGBB),
 * Q8.8 a channel. */
static TARN_ALWAYS_INLINE void blend(const tarn_water_context *w, const tarn_water_effects *e, uint32_t rgb_below,
                                     uint32_t colour[3])
{
    for (int c = 0; c < 3; c++) {
        const uint32_t below = tarn__water_channel_q8(rgb_below, c);
        if (tarn__water_uses(w, TARN_WATER_ABSORPTION)) {
            const int32_t mid = (int32_t)((below * e->gain) >> 15) + e->lift[c];
            colour[c] = e->base[c] + ((uint32_t)(mid > 0 ? mid : 0) * e->through >> 15);
        } else {
            colour[c] = e->base[c] + ((below * e->gain) >> 15);
        }
    }
}

uint32_t tarn__water_apply(const tarn_water_context *w, const tarn_water_effects *e, unsigned sharp, int32_t i,
                          int32_t j)
{
    uint32_t colour[3];
    blend(w, e, moved_background(w, e, i, j), colour);
    return tarn__water_finish(w, sharp, colour);
}

uint32_t tarn__water_still_over(const tarn_water_context *w, const tarn_water_input *in, uint32_t diff,
                               uint32_t rgb_below)
{
    static const uint32_t dark[3] = {0u, 0u, 0u};
    uint32_t lit[3];
    const uint32_t keep = lit_surface_over(w, in, diff, lit);
    tarn_water_effects e;
    gather(w, diff, keep, lit, surface_alpha(w, in), dark, &e);
    uint32_t colour[3];
    blend(w, &e, rgb_below, colour);
    return tarn__water_finish(w, 0u, colour);
}

uint32_t tarn__water_finish(const tarn_water_context *w, unsigned sharp, uint32_t colour[3])
{
    if (sharp & TARN_WATER_SHOWS_FOAM) tarn__water_foam_over(w, colour);
    if (sharp & TARN_WATER_SHOWS_SPARKLES)
        for (int c = 0; c < 3; c++) colour[c] += tarn__water_channel_q8(w->water->sparkle_rgb, c);
    uint32_t rgb = 0;
    for (int c = 0; c < 3; c++) {
        uint32_t byte = (colour[c] + 128u) >> 8;
        rgb = (rgb << 8) | (byte > 255u ? 255u : byte);
    }
    return rgb;
}

int tarn__water_sharp_possible(const tarn_water_context *w, const tarn_water_effects *e)
{
    return tarn__water_sparkles_possible(w) || (tarn__water_uses(w, TARN_WATER_FOAM) && e->foam_band < Q16_ONE);
}

unsigned tarn__water_sharp_features(const tarn_water_context *w, const tarn_water_input *in,
                                   const tarn_water_effects *e)
{
    tarn_water_normal n;
    if (tarn__water_sparkles_possible(w)) tarn__water_map_x(w, in, &n); else tarn__water_flat_normal(&n);
    return tarn__water_sharp_at(w, in, e->foam_band, &n);
}

uint32_t tarn__water_shade(const tarn_water_context *w, int32_t i, int32_t j, const tarn_water_input *in,
                          uint32_t surface_depth)
{
    tarn_water_effects e;
    tarn__water_effects_at(w, i, j, in, surface_depth, &e);
    return tarn__water_apply(w, &e, e.sharp, i, j);
}
