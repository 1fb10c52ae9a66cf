/* water_still.c: the water over a still-water backdrop (tarn_scene.h, "Still
 * water"), which holds steps 3 to 7 of tarn_water.h drawn. No triangle is drawn:
 * the pixels of a tile marked with a water object are walked, and only the terms
 * that move with the clock are found there, from texture coordinates its plane
 * gives: step 1's normal, step 2's refracted sample (read from the picture itself),
 * step 8's highlight, step 9's foam lines and step 10's sparkles. */
#include "water/water_internal.h"
#include "tile/tile_internal.h"

#define Q16_ONE 65536u

int tarn__still_keeps_depth(const tarn_water *water, int refracts)
{
    /* a foam band one unit deep or deeper holds every pixel whose refraction is
     * cut by saturate(db - ds), so its places serve both */
    return refracts && !((water->features & TARN_WATER_FOAM) != 0u && water->foam_distance >= (tarn_q16)Q16_ONE);
}

/* The surface's near/d at pixel (i, j), within the depth buffer's [1, 2^30]. */
static uint32_t plane_inv_depth(const tarn_still_plane *p, int32_t i, int32_t j)
{
    return tarn__plane_denominator(tarn__pixel_affine_at(p->depth, i, j));
}

/* What a water pixel's moving terms read, from the plane at pixel (i, j): the
 * surface's near/d, and the texture coordinates through one reciprocal of it.
 * Inline in both kinds of water pixel: called, it cost the beach 15 instructions a
 * pixel on the M0 (this and sharp_at). */
static TARN_ALWAYS_INLINE tarn_water_input plane_input(const tarn_still_plane *p, unsigned recip_steps, int32_t i,
                                                      int32_t j)
{
    tarn_water_input in;
    in.lit[0] = in.lit[1] = in.lit[2] = 0u; /* drawn into the still colour */
    in.fresnel = 0u;
    in.inv_depth = plane_inv_depth(p, i, j);
    tarn__plane_coordinates(in.inv_depth, tarn__pixel_affine_at(p->u, i, j), tarn__pixel_affine_at(p->v, i, j),
                            p->uv_shift, recip_steps, &in);
    return in;
}

/* Step 8's highlight (Q8.8 a channel) from a pixel's normal. */
static void highlight_of(const tarn_water_context *w, tarn_water_normal *n, uint32_t highlight[3])
{
    for (int c = 0; c < 3; c++) highlight[c] = 0u;
    if (tarn__water_uses(w, TARN_WATER_SPECULAR)) (void)tarn__water_specular(w, n, highlight);
}

/* The bits of a still colour (marks included) that say a sharp feature could show
 * at its pixel: any, since sparkles can show anywhere; TARN_BACKDROP_STILL_FOAM,
 * where the backdrop marks that foam can; none without either. */
static uint32_t sharp_bits(const tarn_water_context *w)
{
    if (tarn__water_sparkles_possible(w)) return UINT32_MAX;
    return tarn__water_uses(w, TARN_WATER_FOAM) ? TARN_BACKDROP_STILL_FOAM : 0u;
}

/* What one walk reads: the backdrop, the object's plane, the walk's number, and
 * where it is. */
typedef struct {
    const tarn_backdrop *backdrop;
    const tarn_still_plane *plane;
    uint32_t number;
    uint32_t mark;       /* the object's TARN_BACKDROP_STILL_OBJECT bits */
    uint32_t sharp_bits; /* sharp_bits() */
    int specular;        /* the object has a highlight: without, only sharp features move */
    int keeps_depth;     /* tarn__still_keeps_depth */
    int32_t x0;          /* the tile's first column */
    int32_t block_row;   /* the top row of the blocks of the row walked */
    tarn_water_input surface; /* what the still terms read of a pixel: the plane's lit
                                 colour, and no fresnel term (the backdrop keeps none) */
    uint32_t endless;    /* the still colour over water of endless depth, 0xRRGGBB */
} still_walk;

/* What the backdrop keeps at water pixel (i, j) as Q16.16 (tarn_backdrop's depth:
 * Q2.14), 0xFFFF << TARN_BACKDROP_KEPT_SHIFT or more where it keeps none. */
static uint32_t kept_q16(const still_walk *walk, int32_t i, int32_t j)
{
    return tarn__backdrop_kept(walk->backdrop, i, j) << TARN_BACKDROP_KEPT_SHIFT;
}

/* Step 9's place in the foam band at pixel (i, j), from what the backdrop keeps
 * where foam can show; beyond the band (Q16_ONE) elsewhere. */
static uint32_t foam_band(const tarn_water_context *w, const still_walk *walk, uint32_t still, int32_t i, int32_t j)
{
    if (!tarn__water_uses(w, TARN_WATER_FOAM) || (still & TARN_BACKDROP_STILL_FOAM) == 0u) return Q16_ONE;
    const uint32_t kept = kept_q16(walk, i, j);
    return walk->keeps_depth ? tarn__water_foam_band(w, kept) : kept;
}

/* The depth of water db - ds beneath water pixel (x, y), Q16.16, where the
 * backdrop keeps it (the depth itself, or from the place in a foam band at least
 * one unit deep); DEEP where it keeps none (between kept pixels, all ones), the
 * water there being deeper than that. */
#define DEEP UINT32_MAX
static uint32_t kept_depth(const tarn_water_context *w, const still_walk *walk, int32_t x, int32_t y)
{
    const uint32_t kept = kept_q16(walk, x, y);
    if (kept >= 0xFFFFu << TARN_BACKDROP_KEPT_SHIFT) return DEEP;
    return walk->keeps_depth ? kept : tarn__water_mul_q16(kept, (uint32_t)w->water->foam_distance);
}

/* Where a pixel's refracted sample reads the still picture: its colour there as
 * this pixel's still terms would have it, and step 9's place in the foam band over
 * the depth of water the sample lies under, seen from the pixel. */
typedef struct {
    uint32_t colour;
    uint32_t band;
} still_sample;

/* A sample whose opaque surface lies at linear depth `opaque` (Q16.16) under a
 * water pixel whose surface lies at `surface`: step 3's diff is db there less ds
 * here. Where that is below 0 the surface lies in front of this pixel's water, and
 * the sample is not taken (0 returned); else its place in the foam band is found
 * over that depth. */
static int sample_behind(const tarn_water_context *w, uint32_t opaque, uint32_t surface, still_sample *s)
{
    if (opaque < surface) return 0;
    if (tarn__water_uses(w, TARN_WATER_FOAM)) s->band = tarn__water_foam_band(w, opaque - surface);
    return 1;
}

/* The sample that lands at water pixel (x, y) of the walk's object, still colour
 * `still`, for a water pixel whose surface lies at `surface`: its opaque surface
 * lies its own depth of water below its surface. Where the backdrop keeps no depth
 * of water there, it is deep: behind, and beyond any foam band. Its colour's fog
 * saw it from its own surface, and is moved to this one's. */
static int moved_sample(const tarn_water_context *w, const still_walk *walk, int32_t x, int32_t y,
                        uint32_t still, uint32_t surface, still_sample *s)
{
    const uint32_t below = kept_depth(w, walk, x, y);
    const int fog = tarn__water_uses(w, TARN_WATER_FOG);
    s->band = Q16_ONE;
    s->colour = still;
    if (below == DEEP && !fog) return 1;
    const uint32_t landing = tarn__water_depth_of(w, plane_inv_depth(walk->plane, x, y));
    if (below != DEEP && !sample_behind(w, landing + below, surface, s)) return 0;
    if (fog) s->colour = tarn__water_fog_moved(w, still, walk->endless, surface, landing);
    return 1;
}

/* The sample that lands at pixel (x, y) where no water draws (the bank behind the
 * water, an object standing in it), opaque colour `opaque`: taken where the
 * backdrop keeps its near/d there (a tarn_depth16 code) and it lies behind the
 * water at `surface`, its colour this pixel's still terms over it. */
static int beside_sample(const tarn_water_context *w, const still_walk *walk, int32_t x, int32_t y,
                         uint32_t opaque, uint32_t surface, still_sample *s)
{
    const uint32_t code = tarn__backdrop_kept(walk->backdrop, x, y);
    s->band = Q16_ONE;
    if (code >= 0xFFFFu) return 0;
    const uint32_t below = tarn__water_depth_of(w, tarn_depth16_decode((uint16_t)code));
    if (!sample_behind(w, below, surface, s)) return 0;
    s->colour = tarn__water_still_over(w, &walk->surface, below - surface, opaque);
    return 1;
}

/* Step 2 over still water: the sample of water pixel (i, j), with inputs `in` and
 * normal `n`: where its refracted sample lands, when the opaque surface there lies
 * behind this pixel's water and the walk's object's water draws there or none
 * does; else the pixel's own (`still`), as the scene drawn whole keeps a sample
 * that lands in front. On the water the picture holds that pixel's still terms,
 * found over its own depth of water: the fog's share is moved to the depth seen
 * from here, and the rest (the surface colour, absorption) kept, as they change
 * slowly across the water. Beside it the picture holds the opaque colour, and this
 * pixel's still terms are found over it. Neither takes the fresnel raise of
 * alpha, which the backdrop does not keep. */
static still_sample refracted_sample(const tarn_water_context *w, const still_walk *walk, const tarn_water_input *in,
                                     tarn_water_normal *n, uint32_t still, int32_t i, int32_t j)
{
    const uint32_t below = kept_depth(w, walk, i, j);
    const uint32_t reach = below < Q16_ONE ? below : Q16_ONE; /* saturate(db - ds) */
    int32_t target[2];
    tarn__water_refracted_pixel(w, i, j, n, reach, target);
    still_sample moved = {0u, Q16_ONE};
    if (target[0] != i || target[1] != j) {
        const uint32_t there = tarn__backdrop_colour_at(walk->backdrop, w->width, target[0], target[1]);
        const uint32_t water = there & TARN_BACKDROP_STILL_OBJECT;
        const uint32_t surface = tarn__water_depth_of(w, in->inv_depth);
        if (water == walk->mark && moved_sample(w, walk, target[0], target[1], there, surface, &moved)) return moved;
        if (water == 0u && beside_sample(w, walk, target[0], target[1], there, surface, &moved)) return moved;
    }
    const still_sample own = {still, foam_band(w, walk, still, i, j)};
    return own;
}

/* The sharp features at water pixel (i, j) with its inputs, `n` its normal when it
 * found one, else NULL. */
static TARN_ALWAYS_INLINE unsigned sharp_at(const tarn_water_context *w, const still_walk *walk,
                                            const tarn_water_input *in, const tarn_water_normal *n, uint32_t still,
                                            int32_t i, int32_t j)
{
    tarn_water_normal maps;
    if (n == NULL && tarn__water_sparkles_possible(w)) tarn__water_map_x(w, in, &maps); else tarn__water_flat_normal(&maps);
    return tarn__water_sharp_at(w, in, foam_band(w, walk, still, i, j), n != NULL ? n : &maps);
}

/* The still colour (0xRRGGBB below the marks of `still`) with a highlight and the
 * sharp features over it, 0x00RRGGBB. */
static uint32_t over_still(const tarn_water_context *w, uint32_t still, const uint32_t highlight[3], unsigned sharp)
{
    if ((highlight[0] | highlight[1] | highlight[2] | sharp) == 0u) return still & 0xFFFFFFu;
    uint32_t colour[3];
    for (int c = 0; c < 3; c++) colour[c] = tarn__water_channel_q8(still, c) + highlight[c];
    return tarn__water_finish(w, sharp, colour);
}

/* The slot of pixel (i, j)'s block, in a tile whose rect starts at column x0;
 * NULL without water blocks. */
static tarn_still_block *block_at(const tarn_water_context *w, int32_t i, int32_t x0)
{
    return w->still_blocks != NULL ? &w->still_blocks[(i - x0) >> w->block_shift] : NULL;
}

/* Step 8's highlight at water pixel (i, j) with normal `n`: its block's when it
 * shares it, else its own, kept for the block when it is the block's top-left
 * pixel. */
static void pixel_highlight(const tarn_water_context *w, const still_walk *walk, tarn_still_block *block, int shared,
                            tarn_water_normal *n, int32_t i, int32_t j, uint32_t highlight[3])
{
    if (shared) {
        for (int c = 0; c < 3; c++) highlight[c] = block->highlight[c];
        return;
    }
    highlight_of(w, n, highlight);
    if (!walk->specular || block == NULL || ((i | j) & ((1 << w->block_shift) - 1)) != 0) return;
    for (int c = 0; c < 3; c++) block->highlight[c] = highlight[c];
    block->lit = highlight[0] | highlight[1] | highlight[2];
    block->walk = walk->number;
    block->row = j;
}

/* Water pixel (i, j) of a walk that refracts: every pixel finds its own normal,
 * since its refracted sample moves with it, and takes the still colour where that
 * sample lands and the place in the foam band over it. */
static uint32_t refracting_pixel(const tarn_water_context *w, const still_walk *walk, tarn_still_block *block,
                                 int shared, uint32_t still, int32_t i, int32_t j)
{
    const tarn_water_input in = plane_input(walk->plane, w->linear.recip_steps, i, j);
    tarn_water_normal n;
    tarn__water_pixel_normal(w, &in, &n);
    uint32_t highlight[3];
    pixel_highlight(w, walk, block, shared, &n, i, j, highlight);
    const still_sample s = refracted_sample(w, walk, &in, &n, still, i, j);
    const int sharp = tarn__water_sparkles_possible(w) || s.band < Q16_ONE;
    return over_still(w, s.colour, highlight, sharp ? tarn__water_sharp_at(w, &in, s.band, &n) : 0u);
}

/* Water pixel (i, j) of a walk: its block's highlight when this walk found it at
 * the block's top-left pixel, else its own, kept for the block when it is that
 * pixel. */
static uint32_t water_pixel(tarn_water_context *w, const still_walk *walk, uint32_t still, int32_t i, int32_t j)
{
    tarn_still_block *block = block_at(w, i, walk->x0);
    const int shared = block != NULL && block->walk == walk->number && block->row == walk->block_row;
    if (tarn__water_refracts(w)) return refracting_pixel(w, walk, block, shared, still, i, j);
    const int sharp = (still & walk->sharp_bits) != 0u;
    if (shared && !sharp) return block->lit ? over_still(w, still, block->highlight, 0u) : still & 0xFFFFFFu;
    if (!walk->specular && !sharp) return still & 0xFFFFFFu; /* nothing moves here */
    const tarn_water_input in = plane_input(walk->plane, w->linear.recip_steps, i, j);
    if (shared || !walk->specular) {
        static const uint32_t dark[3] = {0u, 0u, 0u};
        return over_still(w, still, shared ? block->highlight : dark, sharp_at(w, walk, &in, NULL, still, i, j));
    }
    tarn_water_normal n;
    tarn__water_pixel_normal(w, &in, &n);
    uint32_t highlight[3];
    pixel_highlight(w, walk, block, 0, &n, i, j, highlight);
    return over_still(w, still, highlight, sharp ? sharp_at(w, walk, &in, &n, still, i, j) : 0u);
}

/* What the still terms read of a pixel of plane `p`: its lit colour, no fresnel
 * term. */
static tarn_water_input surface_input(const tarn_still_plane *p)
{
    tarn_water_input in = {0};
    for (int c = 0; c < 3; c++) in.lit[c] = p->lit[c];
    return in;
}

/* A depth of water past every exp2's reach and every depth colour's scale: the fog
 * keeps nothing of the background there. */
#define ENDLESS UINT32_MAX

/* The first pixel of [from, end) that carries `mark`, or `end`: the walk's own
 * loop, kept apart from the water pixel's work. */
static uint32_t *next_marked(uint32_t *from, const uint32_t *end, uint32_t mark)
{
    while (from != end && (*from & TARN_BACKDROP_STILL_OBJECT) != mark) from++;
    return from;
}

void tarn__water_still_tile(tarn_water_context *w, const tarn_backdrop *backdrop, uint32_t object,
                           tarn_tile_target *tile)
{
    const tarn_pixel_rect r = tile->rect;
    const uint32_t mark = (object + 1u) << TARN_BACKDROP_STILL_SHIFT;
    const int refracts = tarn__water_refracts(w);
    const tarn_still_plane *plane = &backdrop->planes[object];
    still_walk walk = {backdrop, plane, ++w->still_walks, mark, sharp_bits(w), tarn__water_uses(w, TARN_WATER_SPECULAR),
                       tarn__still_keeps_depth(w->water, refracts), r.x0, 0, surface_input(plane), 0u};
    if (refracts && tarn__water_uses(w, TARN_WATER_FOG))
        walk.endless = tarn__water_still_over(w, &walk.surface, ENDLESS, 0u);
    for (int32_t j = r.y0; j < r.y1; j++) {
        walk.block_row = j >> w->block_shift << w->block_shift;
        uint32_t *first = &tile->colour[(j - tile->origin_y) * tile->stride + (r.x0 - tile->origin_x)];
        const uint32_t *end = first + (r.x1 - r.x0);
        for (uint32_t *pixel = first; (pixel = next_marked(pixel, end, mark)) != end; pixel++)
            *pixel = water_pixel(w, &walk, *pixel, r.x0 + (int32_t)(pixel - first), j);
    }
}
