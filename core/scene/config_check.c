/* config_check.c: whether a frame config is one the core can draw: every quality
 * knob in its range and compiled in (tarn_config.h), and a frame small enough for
 * its subpixel precision. */
#include "scene/scene_internal.h"

int32_t tarn_guard_band_pixels(const tarn_frame_config *config)
{
    uint16_t larger = config->width > config->height ? config->width : config->height;
    return larger / 4 + 16;
}

static int quality_in_range(const tarn_quality *q)
{
    return tarn_is_power_of_two(q->exp2.entries) && q->exp2.entries >= TARN_EXP2_ENTRIES_MIN &&
           q->exp2.entries <= TARN_EXP2_ENTRIES_MAX && q->exp2.interpolate <= 1 &&
           q->recip_newton_steps <= TARN_RECIP_STEPS_MAX &&
           q->subpixel_bits >= TARN_SUBPIXEL_BITS_MIN && q->subpixel_bits <= TARN_SUBPIXEL_BITS_MAX &&
           q->perspective <= TARN_PERSPECTIVE_PIXEL &&
           (TARN_LINK_PERSPECTIVE_AFFINE || q->perspective == TARN_PERSPECTIVE_PIXEL) &&
           (TARN_LINK_PERSPECTIVE_SPAN || q->perspective != TARN_PERSPECTIVE_SPAN) &&
           (TARN_LINK_PERSPECTIVE_PIXEL || q->perspective != TARN_PERSPECTIVE_PIXEL) &&
           tarn_is_power_of_two(q->perspective_span) && q->perspective_span >= 2 && q->perspective_span <= 64 &&
           ((TARN_LINK_DEPTH16 && q->depth_bits == 16) || (TARN_LINK_DEPTH32 && q->depth_bits == 32)) &&
           (q->depth_interpolation == TARN_DEPTH_PLANE ||
            (TARN_LINK_EXACT_DEPTH && q->depth_interpolation == TARN_DEPTH_EXACT)) &&
           q->tile_size >= TARN_TILE_SIZE_MIN && q->tile_size <= TARN_TILE_SIZE_MAX &&
           (q->refraction_apron <= TARN_WATER_APRON_MAX || q->refraction_apron == TARN_APRON_FULL) &&
           (TARN_LINK_APRON || q->refraction_apron == 0) &&
           q->cluster_bins <= 1 &&
           q->fog_argument_bits >= TARN_FOG_ARGUMENT_BITS_MIN && q->fog_argument_bits <= TARN_FOG_ARGUMENT_BITS_MAX &&
           (q->water_block == 1 ||
            (TARN_LINK_WATER_BLOCKS && (q->water_block == 2 || q->water_block == 4) && q->tile_size % q->water_block == 0)) &&
           (q->refraction_normal == TARN_REFRACTION_NORMAL_SHARED ||
            (TARN_LINK_REFRACTION_EXACT && q->refraction_normal == TARN_REFRACTION_NORMAL_EXACT)) &&
           (q->frame_shape == TARN_FRAME_TILES || (TARN_LINK_STRIPS && q->frame_shape == TARN_FRAME_STRIPS)) &&
           q->lit_colour <= TARN_LIT_LINE &&
           /* a build that shades water without the plane's code would draw other
              coordinates than the plane's */
           (q->water_coordinates == TARN_WATER_UV_TRIANGLES ||
            (q->water_coordinates == TARN_WATER_UV_PLANE &&
             (TARN_LINK_WATER_PLANE || !TARN_LINK_WATER || !TARN_LINK_WATER_SHADING))) &&
           (q->vertex_pass == TARN_VERTICES_PER_TILE ||
            (TARN_LINK_VERTEX_PASS && TARN_LINK_STATIC_VERTICES && q->vertex_pass <= TARN_VERTICES_PER_FRAME_VIEW));
}

tarn_status tarn__config_check(const tarn_frame_config *config)
{
    if (config == NULL || config->width < 1 || config->height < 1 ||
        config->width > TARN_FRAME_SIZE_MAX || config->height > TARN_FRAME_SIZE_MAX ||
        !quality_in_range(&config->quality))
        return TARN_ERR_CONFIG;
    /* Edge functions are products of two coordinate differences within the guard
     * box; keeping the box under 2^15 subpixels keeps them below 2^31. */
    int32_t larger = config->width > config->height ? config->width : config->height;
    int32_t box = larger + 2 * tarn_guard_band_pixels(config) + 2;
    if (((int64_t)box << config->quality.subpixel_bits) >= 32768) return TARN_ERR_CONFIG;
    return TARN_OK;
}
