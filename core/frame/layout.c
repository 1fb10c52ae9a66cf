/* layout.c: a frame's working memory, found once from the config and the scene:
 * which buffers it needs, how many bytes, and where each lies. */
#include "frame/frame_internal.h"

#include <string.h>

/* The layout with the underwater view on or off as asked. */
static tarn_frame_layout layout_of(const tarn_frame_config *config, const tarn_scene *scene, int underwater)
{
    tarn_frame_layout l;
    l.tile = config->quality.tile_size;
    l.underwater = TARN_LINK_UNDERWATER && underwater;
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
    /* over an opaque backdrop, which holds the whole opaque picture in flash, a
     * refracted sample is read there wherever it lands: no apron either */
    const int flash = TARN_LINK_BACKDROP && l.backdrop != NULL && !l.still && !l.underwater;
    l.apron = l.still || flash ? 0 : l.refraction_apron + l.under_apron;
    /* Without an apron a water pixel reads the opaque pass at itself only, and the
     * water pass can draw over it; the underwater view reads the water pass's
     * output displaced, so keeps it apart. */
    l.in_place = l.water && !l.underwater && l.apron == 0;
    /* strips keep the opaque pass of every strip a water pixel can sample: the
     * apron, rounded up to whole strips, above and below */
    const int strips = TARN_LINK_STRIPS && config->quality.frame_shape == TARN_FRAME_STRIPS && !l.underwater &&
                       l.backdrop == NULL;
    l.piece_width = strips ? (int32_t)config->width : l.tile;
    l.ring_strips = strips ? 1 + 2 * ((l.apron + l.tile - 1) / l.tile) : 0;
    l.region_width = strips ? l.piece_width : l.tile + 2 * l.apron;
    l.water_region = l.tile + 2 * l.under_apron;
    l.depth_bytes = l.still ? 0u : config->quality.depth_bits / 8u;
    /* the underwater pass reads displaced water pixels over an apron that need not
     * hold whole blocks */
    l.blocks = TARN_LINK_WATER_BLOCKS && l.water && !l.underwater && config->quality.water_block > 1
        ? ((uint32_t)l.piece_width + config->quality.water_block - 1u) / config->quality.water_block : 0u;
    l.block_bytes = l.still ? sizeof(tarn_still_block) : sizeof(tarn_water_block);
    const int binned = scene != NULL && config->quality.cluster_bins;
    l.static_bins = binned && TARN_LINK_STATIC_VERTICES && tarn__static_screen_applies(scene, config)
        ? scene->static_view->bins : NULL;
    l.bins = TARN_LINK_FOUND_BINS && binned && l.static_bins == NULL ? tarn__cluster_bin_count(scene) : 0u;
    return l;
}

tarn_frame_layout tarn__frame_layout_of(const tarn_frame_config *config, const tarn_scene *scene)
{
    return layout_of(config, scene, tarn__underwater_active(scene));
}

tarn_frame_layout tarn__frame_strips_layout(const tarn_frame_config *config, const tarn_scene *scene)
{
    return layout_of(config, scene, 0);
}

/* Rows of the opaque buffers: the tile's square, or the ring's strips. */
static int32_t region_height(const tarn_frame_layout *l)
{
    return TARN_LINK_STRIPS && l->ring_strips != 0 ? l->ring_strips * l->tile : l->region_width;
}

size_t tarn__frame_water_pixels(const tarn_frame_layout *l)
{
    if (!l->water || l->still) return 0u;
    if (l->in_place) return (size_t)l->piece_width * TARN_WATER_STRIP_ROWS;
    if (TARN_LINK_STRIPS && l->ring_strips != 0) return (size_t)l->piece_width * (size_t)l->tile;
    return (size_t)l->water_region * (size_t)l->water_region;
}

static size_t layout_bytes(const tarn_frame_layout *l)
{
    const size_t region = (size_t)l->region_width * (size_t)region_height(l);
    const size_t tile = (size_t)l->tile * (size_t)l->tile;
    return (region + tarn__frame_water_pixels(l)) * (4u + l->depth_bytes) + (l->underwater ? tile * 4u : 0u) +
           (size_t)l->blocks * l->block_bytes + (size_t)l->bins * sizeof(tarn_cluster_bin);
}

/* The scene the frame draws lies at the start of the frame's memory when it is not
 * the caller's, aligned for the pointers it holds (the memory is only 4-byte
 * aligned): a moving scene posed, then its objects when some move; with the vertex
 * pass, the scene and all its objects copied, the static view made for the frame,
 * and every vertex. */
#define SCENE_ALIGN sizeof(void *)

/* Whether the frame finds its vertices once into its memory: asked, and no static
 * view (a baked still scene's) holds them already. */
static int vertex_pass_applies(const tarn_frame_config *config, const tarn_scene *scene)
{
    return TARN_LINK_VERTEX_PASS && TARN_LINK_STATIC_VERTICES && scene != NULL &&
           config->quality.vertex_pass != TARN_VERTICES_PER_TILE && !tarn__static_view_applies(scene);
}

/* Whether the pass keeps each vertex's view position too. */
static int pass_keeps_positions(const tarn_frame_config *config)
{
    return config->quality.vertex_pass == TARN_VERTICES_PER_FRAME_VIEW;
}

/* The bytes of every vertex the pass finds: its record and, where the quality
 * keeps them, its view position. */
static size_t vertex_bytes(const tarn_frame_config *config)
{
    return sizeof(tarn_static_vertex) + (pass_keeps_positions(config) ? sizeof(tarn_vec3) : 0u);
}

static size_t scene_bytes(const tarn_frame_config *config, const tarn_scene *scene)
{
    const int moves = TARN_LINK_MOTION && tarn_scene_moves(scene);
    const int pass = vertex_pass_applies(config, scene);
    if (!moves && !pass) return 0u;
    const int objects = pass || tarn__objects_move(scene);
    size_t bytes = SCENE_ALIGN - 4u + sizeof(tarn_scene) + (objects ? scene->object_count * sizeof(tarn_object) : 0u);
    if (pass) bytes += sizeof(tarn_static_view) + tarn__scene_vertex_count(scene) * vertex_bytes(config);
    return (bytes + 3u) & ~(size_t)3u;
}

size_t tarn_frame_memory_bytes(const tarn_frame_config *config, const tarn_scene *scene)
{
    if (tarn__config_check(config) != TARN_OK) return 0;
    const tarn_frame_layout l = tarn__frame_layout_of(config, scene);
    size_t bytes = layout_bytes(&l);
    if (TARN_LINK_MOTION && scene != NULL && scene->camera_path != NULL && scene->underwater != NULL) {
        /* the camera may cross the water's level: room for the view either side */
        const tarn_frame_layout other = layout_of(config, scene, !l.underwater);
        if (layout_bytes(&other) > bytes) bytes = layout_bytes(&other);
    }
    return scene_bytes(config, scene) + bytes;
}

const tarn_scene *tarn__frame_scene(const tarn_scene *scene, const tarn_frame_config *config, void **memory)
{
    const size_t bytes = scene_bytes(config, scene);
    if (bytes == 0u) return scene;
    uint8_t *start = *memory;
    tarn_scene *own = (tarn_scene *)(void *)(start + ((0u - (uintptr_t)start) & (SCENE_ALIGN - 1u)));
    const int pass = vertex_pass_applies(config, scene);
    tarn_object *objects = pass || tarn__objects_move(scene) ? (tarn_object *)(void *)(own + 1) : NULL;
    if (TARN_LINK_MOTION && tarn_scene_moves(scene)) {
        tarn__scene_pose(scene, config->time_ms, own, objects);
    } else {
        *own = *scene;
        for (uint32_t i = 0; objects != NULL && i < scene->object_count; i++) objects[i] = scene->objects[i];
    }
    if (pass) {
        own->objects = objects;
        tarn_static_view *made = (tarn_static_view *)(void *)(objects + scene->object_count);
        tarn_static_vertex *vertices = (tarn_static_vertex *)(void *)(made + 1);
        tarn_vec3 *positions = pass_keeps_positions(config)
                                   ? (tarn_vec3 *)(void *)(vertices + tarn__scene_vertex_count(scene))
                                   : NULL;
        tarn__vertex_pass(own, objects, config, made, vertices, positions);
    }
    *memory = start + bytes;
    return own;
}

tarn_frame_buffers tarn__frame_carve(const tarn_frame_layout *l, void *memory)
{
    const size_t region = (size_t)l->region_width * (size_t)region_height(l);
    const size_t water = tarn__frame_water_pixels(l);
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
