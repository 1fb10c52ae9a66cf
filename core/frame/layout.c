/* layout.c: a frame's working memory, found once from the config and the scene:
 * which buffers it needs, how many bytes, and where each lies. */
#include "frame/frame_internal.h"

#include <string.h>

tarn_frame_layout tarn__frame_layout_of(const tarn_frame_config *config, const tarn_scene *scene)
{
    tarn_frame_layout l;
    l.tile = config->quality.tile_size;
    l.underwater = TARN_LINK_UNDERWATER && tarn__underwater_active(scene);
    l.water = (TARN_LINK_WATER && tarn__scene_has_water(scene)) || l.underwater;
    l.under_apron = l.underwater
        ? tarn__apron_limit(tarn__underwater_reach_pixels(scene->underwater, config->width), &config->quality)
        : 0;
    l.refraction_apron = l.water ? tarn_frame_apron_pixels(scene, config) : 0;
    l.backdrop = tarn__backdrop_for(scene, config);
    /* over still water, no water triangle is drawn: no water pass, no copy, and no
     * depth but the backdrop's own; refracted samples read the backdrop's picture
     * wherever they land, so no apron is drawn for them */
    l.still = TARN_LINK_STILL_WATER && l.backdrop != NULL && l.backdrop->still_water;
    l.apron = l.still ? 0 : l.refraction_apron + l.under_apron;
    /* Without an apron a water pixel reads the opaque pass at itself only, and the
     * water pass can draw over it; the underwater view reads the water pass's
     * output displaced, so keeps it apart. */
    l.in_place = l.water && !l.underwater && l.apron == 0;
    l.region = l.tile + 2 * l.apron;
    l.water_region = l.tile + 2 * l.under_apron;
    l.depth_bytes = l.still ? 0u : config->quality.depth_bits / 8u;
    /* the underwater pass reads displaced water pixels over an apron that need not
     * hold whole blocks */
    l.blocks = TARN_LINK_WATER_BLOCKS && l.water && !l.underwater && config->quality.water_block > 1
        ? (uint32_t)l.tile / config->quality.water_block : 0u;
    l.block_bytes = l.still ? sizeof(tarn_still_block) : sizeof(tarn_water_block);
    const int binned = scene != NULL && config->quality.cluster_bins;
    l.static_bins = binned && TARN_LINK_STATIC_VERTICES && tarn__static_screen_applies(scene, config)
        ? scene->static_view->bins : NULL;
    l.bins = TARN_LINK_FOUND_BINS && binned && l.static_bins == NULL ? tarn__cluster_bin_count(scene) : 0u;
    return l;
}

/* Pixels of the water pass's own colour and depth buffers. */
static size_t water_pixels(const tarn_frame_layout *l)
{
    if (!l->water || l->still) return 0u;
    if (l->in_place) return (size_t)l->tile * TARN_WATER_STRIP_ROWS;
    return (size_t)l->water_region * (size_t)l->water_region;
}

static size_t layout_bytes(const tarn_frame_layout *l)
{
    const size_t region = (size_t)l->region * (size_t)l->region;
    const size_t tile = (size_t)l->tile * (size_t)l->tile;
    return (region + water_pixels(l)) * (4u + l->depth_bytes) + (l->underwater ? tile * 4u : 0u) +
           (size_t)l->blocks * l->block_bytes + (size_t)l->bins * sizeof(tarn_cluster_bin);
}

size_t tarn_frame_memory_bytes(const tarn_frame_config *config, const tarn_scene *scene)
{
    if (tarn__config_check(config) != TARN_OK) return 0;
    const tarn_frame_layout l = tarn__frame_layout_of(config, scene);
    return layout_bytes(&l);
}

tarn_frame_buffers tarn__frame_carve(const tarn_frame_layout *l, void *memory)
{
    const size_t region = (size_t)l->region * (size_t)l->region;
    const size_t water = water_pixels(l);
    tarn_frame_buffers b;
    uint8_t *next = memory; /* 4-byte buffers first, so every one stays aligned */
    b.opaque_colour = (uint32_t *)(void *)next;
    next += region * 4u;
    b.water_colour = (uint32_t *)(void *)next;
    next += water * 4u;
    b.final = (uint32_t *)(void *)next;
    next += l->underwater ? (size_t)l->tile * (size_t)l->tile * 4u : 0u;
    b.blocks = l->blocks != 0u && !l->still ? (tarn_water_block *)(void *)next : NULL;
    b.still_blocks = l->blocks != 0u && l->still ? (tarn_still_block *)(void *)next : NULL;
    if (l->blocks != 0u) memset(next, 0, (size_t)l->blocks * l->block_bytes);
    next += (size_t)l->blocks * l->block_bytes;
    b.opaque_depth = next;
    next += region * l->depth_bytes;
    b.water_depth = next;
    next += water * l->depth_bytes;
    b.found_bins = l->bins != 0u ? (tarn_cluster_bin *)(void *)next : NULL;
    return b;
}
