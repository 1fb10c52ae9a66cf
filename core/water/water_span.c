/* water_span.c: water triangles. The rasterizer (core/raster/) sets each one up
 * and hands out its covered pixels row by row; this draws them, and is where the
 * quality's water_block 2 or 4 lets a block of pixels share the effects its
 * top-left pixel found (tarn_water_block). */
#include "water/water_internal.h"

/* A texture coordinate's T value (below 2^31; Q16.16 shifted up by `shift`, at most
 * 46) as Q16.16, added to the triangle's base, and the 16 fraction bits below (zero
 * past T's own). */
static uint32_t coordinate_q16(uint32_t t, unsigned shift, uint32_t base, uint16_t *low)
{
    *low = (uint16_t)(shift >= 16u ? t >> (shift - 16u) : t << (16u - shift));
    return (shift >= 31u ? 0u : t >> shift) + base;
}

/* Whether the object's texture coordinates come from its plane this frame: then
 * its triangles interpolate none, and the fresnel term takes their place. */
static int coordinates_from_plane(const tarn_water_context *w)
{
#if TARN_LINK_WATER_PLANE
    return w->plane.holds;
#else
    (void)w;
    return 0;
#endif
}

/* Texture coordinates from the object's plane (tarn_water_plane), with every
 * Newton step: a plane's coordinates are whole, where a triangle's quotient spans
 * its own corners' and the quality's steps suffice. Out of line: inlined, its
 * locals grew the water triangle's frame, at the bottom of the 16 KB board's
 * deepest call chain, past the board's stack. */
#if TARN_LINK_WATER_PLANE
static TARN_NOINLINE void plane_coordinates(const tarn_water_context *w, int32_t i, int32_t j, tarn_water_input *in)
{
    const tarn_water_plane *p = &w->plane;
    tarn__plane_coordinates(tarn__plane_denominator(tarn__fine_affine_at(&p->denominator, i, j)),
                            tarn__fine_affine_at(&p->u, i, j), tarn__fine_affine_at(&p->v, i, j), p->uv_shift,
                            TARN_RECIP_STEPS_MAX, in);
}
#else
/* Never called: a build without the plane takes no coordinates from it. */
static void plane_coordinates(const tarn_water_context *w, int32_t i, int32_t j, tarn_water_input *in)
{
    (void)w, (void)i, (void)j, (void)in;
}
#endif

/* The water pixel (i, j)'s inputs from the interpolated attributes and, with one,
 * its object's plane. */
static tarn_water_input water_input(const tarn_water_context *w, const tarn_attribute_set *set,
                                    const uint32_t values[TARN_ATTRIBUTES_MAX], uint32_t inv_depth, int32_t i,
                                    int32_t j)
{
    tarn_water_input in;
    in.inv_depth = inv_depth;
    for (int c = 0; c < 3; c++) in.lit[c] = values[c] >> set->t_shift[c];
    int fresnel = TARN_ATTRIBUTE_FRESNEL;
    if (coordinates_from_plane(w)) {
        plane_coordinates(w, i, j, &in);
        fresnel = TARN_ATTRIBUTE_U;
    } else {
        in.u = coordinate_q16(values[TARN_ATTRIBUTE_U], set->t_shift[TARN_ATTRIBUTE_U], set->u_base, &in.u_low);
        in.v = coordinate_q16(values[TARN_ATTRIBUTE_V], set->t_shift[TARN_ATTRIBUTE_V], set->v_base, &in.v_low);
    }
    in.fresnel = set->count > fresnel ? values[fresnel] >> set->t_shift[fresnel] : 0u;
    return in;
}

/* Whether a pixel's background (near/d, Q1.30) lies as deep as its block's. */
static int as_deep_as(uint32_t depth_q30, const tarn_water_block *block)
{
    const uint32_t apart = depth_q30 > block->depth_q30 ? depth_q30 - block->depth_q30 : block->depth_q30 - depth_q30;
    return apart <= block->depth_q30 >> TARN_WATER_BLOCK_DEPTH_SHIFT;
}

/* The slot of the block of water pixel (i, j), in a frame with water blocks. */
static tarn_water_block *block_slot(const tarn_water_pass *pass, int32_t i)
{
    return &pass->water->blocks[(i - pass->target.rect.x0) >> pass->water->block_shift];
}

/* Whether pixel (i, j), its background at depth_q30, takes its block's effects:
 * this triangle found them at the block's top-left pixel over as deep a
 * background (tarn_water_block). Which pixels share depends on the triangles
 * alone: even tiles hold whole blocks. */
static int shares_block(const tarn_water_context *w, const tarn_water_block *block, int32_t j, uint32_t depth_q30)
{
    return block->serial == w->triangle_serial && block->row == (j >> w->block_shift << w->block_shift) &&
           as_deep_as(depth_q30, block);
}

/* The effects of a pixel that does not share its block's: its own, kept in the
 * block's slot when it is the block's top-left pixel, unless they refract: a
 * refracted sample moves with each pixel's own normal, and shared it would move
 * the block's other pixels by the top-left pixel's. */
static const tarn_water_effects *own_effects(const tarn_water_pass *pass, int32_t i, int32_t j,
                                             const tarn_water_input *in, uint32_t surface_depth, uint32_t depth_q30,
                                             tarn_water_effects *own)
{
    tarn_water_context *w = pass->water;
    tarn_water_block *block = block_slot(pass, i);
    const int top_left = ((i | j) & ((1 << w->block_shift) - 1)) == 0;
    tarn_water_effects *e = top_left ? &block->effects : own;
    tarn__water_effects_at(w, i, j, in, surface_depth, e);
    if (top_left) {
        const int refracts = TARN_LINK_APRON && (e->offset[0] | e->offset[1]) != 0;
        block->serial = refracts ? 0u : w->triangle_serial;
        block->row = j;
        block->depth_q30 = depth_q30;
    }
    return e;
}

/* How a water pixel gets its effects: its block's, when it shares them, or its own. */
typedef struct {
    tarn_water_block *block; /* NULL without water blocks */
    uint32_t depth_q30;      /* the background's near/d, with blocks */
    int shares;
} water_choice;

static water_choice water_choice_at(const tarn_water_pass *pass, int32_t i, int32_t j)
{
    water_choice c = {NULL, 0u, 0};
    const tarn_water_context *w = pass->water;
    if (!TARN_LINK_WATER_BLOCKS || w->blocks == NULL) return c;
    c.block = block_slot(pass, i);
    c.depth_q30 = tarn__water_background_q30(w, i, j);
    c.shares = shares_block(w, c.block, j, c.depth_q30);
    return c;
}

/* Whether a water pixel needs inputs of its own: all but one that shares its
 * block's effects where no sharp feature can show, which needs no attributes. */
static int water_needs_inputs(const tarn_water_context *w, const water_choice *c)
{
    return !c->shares || tarn__water_sharp_possible(w, &c->block->effects);
}

/* ds, the surface's linear depth at a water pixel (Q16.16), from the reciprocal of
 * its near/d the perspective divide found, where it found one (pixel perspective:
 * q holds near/d to more bits than the depth, and a reciprocal is spared), else
 * from near/d, `inv_depth`. */
static uint32_t surface_depth_of(const tarn_water_context *w, const tarn_depth_reciprocal *surface, uint32_t inv_depth)
{
    if (TARN_LINK_PERSPECTIVE_PIXEL && surface->recip != 0u) return tarn__water_linear_depth_of(surface, &w->linear);
    return tarn__water_depth_of(w, inv_depth);
}

/* The colour of water pixel (i, j) from its attributes `values` and its surface's
 * near/d by its reciprocal, `surface` (found only where water_needs_inputs). */
static uint32_t water_colour(const tarn_water_pass *pass, const water_choice *c, const tarn_attribute_set *set,
                             const uint32_t values[TARN_ATTRIBUTES_MAX], uint32_t inv_depth,
                             const tarn_depth_reciprocal *surface, int32_t i, int32_t j)
{
    tarn_water_context *w = pass->water;
    if (c->shares) {
        const tarn_water_effects *shared = &c->block->effects;
        if (!tarn__water_sharp_possible(w, shared)) return tarn__water_apply(w, shared, 0u, i, j);
        const tarn_water_input in = water_input(w, set, values, inv_depth, i, j);
        return tarn__water_apply(w, shared, tarn__water_sharp_features(w, &in, shared), i, j);
    }
    const tarn_water_input in = water_input(w, set, values, inv_depth, i, j);
    const uint32_t surface_depth = surface_depth_of(w, surface, inv_depth);
    if (c->block == NULL) return tarn__water_shade(w, i, j, &in, surface_depth);
    tarn_water_effects own;
    const tarn_water_effects *e = own_effects(pass, i, j, &in, surface_depth, c->depth_q30, &own);
    return tarn__water_apply(w, e, e->sharp, i, j);
}

/* A water pixel's colour, found or shared, and its mark: a pass in place (mark set)
 * marks each pixel it writes, and writing a marked one again means this pixel read
 * the other water pixel as its background, not the opaque pass's; the frame then
 * draws the tile's water again from a copy. Skipping a pixel's attributes is safe
 * in every perspective mode: a span is filled for whichever pixel first reaches it. */
static TARN_ALWAYS_INLINE uint32_t water_pixel(void *pass_ctx, tarn_span *s, int32_t i, int32_t index,
                                              uint32_t inv_depth)
{
    tarn_water_pass *pass = pass_ctx;
    const water_choice choice = water_choice_at(pass, i, s->j);
    tarn_depth_reciprocal surface;
    surface.recip = 0u; /* none found, unless in pixel perspective: a build without it asks for none */
    if (water_needs_inputs(pass->water, &choice))
        tarn__span_attributes(s, i, TARN_LINK_PERSPECTIVE_PIXEL ? &surface : NULL);
    const uint32_t rgb = water_colour(pass, &choice, s->set, s->values, inv_depth, &surface, i, s->j);
    pass->overlap |= pass->target.colour[index] & pass->mark;
    return rgb | pass->mark;
}

void tarn__water_draw_triangle(void *pass_ctx, const tarn_screen_vertex vertex[3], const tarn_object *object)
{
    tarn_water_pass *pass = pass_ctx;
    tarn_triangle_rows rows;
    if (!tarn__triangle_enters_tile(&rows, &pass->target, vertex, object->material->cull)) return;
    if (pass->water->object != object) tarn__water_context_setup(pass->water, pass->view, pass->config, object);
    pass->water->triangle_serial++;
    const tarn_attribute_request request = {NULL, !coordinates_from_plane(pass->water),
                                            (object->material->water->features & TARN_WATER_FRESNEL) != 0, 0};
    tarn__triangle_rows_begin(&rows, &request);
    for (tarn_span *s; (s = tarn__triangle_next_span(&rows)) != NULL;) tarn__span_draw(s, water_pixel, pass);
}

void tarn__water_clear_marks(const tarn_tile_target *t)
{
    for (int32_t j = t->rect.y0; j < t->rect.y1; j++) {
        const int32_t row = (j - t->origin_y) * t->stride - t->origin_x;
        for (int32_t i = t->rect.x0; i < t->rect.x1; i++) t->colour[row + i] &= ~TARN_WATER_MARK;
    }
}
