/* frame.c: configuration, working memory and the tile loop. */
#include "pipeline.h"

#include <string.h>

tarn_quality tarn_quality_default(void)
{
    tarn_quality q;
    q.exp2.entries = 64;
    q.exp2.interpolate = 1;
    q.recip_newton_steps = 2;
    q.subpixel_bits = 4;
    q.perspective = TARN_PERSPECTIVE_PIXEL;
    q.perspective_span = 16;
    q.depth_bits = 32;
    q.tile_size = 32;
    q.refraction_apron = 1;
    return q;
}

const char *tarn_status_text(tarn_status status)
{
    switch (status) {
    case TARN_OK: return "ok";
    case TARN_ERR_CONFIG: return "frame or quality setting out of range";
    case TARN_ERR_MEMORY: return "working memory smaller than tarn_frame_memory_bytes()";
    case TARN_ERR_SCENE: return "malformed scene data";
    case TARN_ERR_SINK: return "the tile sink stopped the frame";
    }
    return "unknown status";
}

static int is_power_of_two(uint32_t v)
{
    return v != 0 && (v & (v - 1u)) == 0;
}

static int quality_in_range(const tarn_quality *q)
{
    return is_power_of_two(q->exp2.entries) && q->exp2.entries >= TARN_EXP2_ENTRIES_MIN &&
           q->exp2.entries <= TARN_EXP2_ENTRIES_MAX && q->exp2.interpolate <= 1 &&
           q->recip_newton_steps <= TARN_RECIP_STEPS_MAX &&
           q->subpixel_bits >= TARN_SUBPIXEL_BITS_MIN && q->subpixel_bits <= TARN_SUBPIXEL_BITS_MAX &&
           q->perspective <= TARN_PERSPECTIVE_PIXEL &&
           is_power_of_two(q->perspective_span) && q->perspective_span >= 2 && q->perspective_span <= 64 &&
           (q->depth_bits == 16 || q->depth_bits == 32) &&
           q->tile_size >= TARN_TILE_SIZE_MIN && q->tile_size <= TARN_TILE_SIZE_MAX &&
           q->refraction_apron <= 1;
}

tarn_status tarn_config_check(const tarn_frame_config *config)
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

size_t tarn_frame_memory_bytes(const tarn_frame_config *config, const tarn_scene *scene)
{
    (void)scene;
    if (tarn_config_check(config) != TARN_OK) return 0;
    size_t pixels = (size_t)config->quality.tile_size * config->quality.tile_size;
    return pixels * sizeof(uint32_t) + pixels * (config->quality.depth_bits / 8u);
}

static int texture_valid(const tarn_texture *t)
{
    return t->rgb != NULL && is_power_of_two(t->width) && is_power_of_two(t->height) &&
           t->width <= TARN_TEXTURE_SIZE_MAX && t->height <= TARN_TEXTURE_SIZE_MAX;
}

/* Clusters, when given, must cover the triangles exactly once and in order. */
static int clusters_valid(const tarn_mesh *m)
{
    if (m->clusters == NULL) return 1;
    uint32_t next = 0;
    for (uint32_t c = 0; c < m->cluster_count; c++) {
        if (m->clusters[c].first_triangle != next || m->clusters[c].radius < 0) return 0;
        next += m->clusters[c].triangle_count;
    }
    return next == m->triangle_count;
}

static int mesh_valid(const tarn_mesh *m)
{
    if (m->triangle_count == 0) return 1;
    if (m->positions == NULL || m->normals == NULL || m->indices == NULL) return 0;
    for (uint32_t i = 0; i < 3u * m->triangle_count; i++)
        if (m->indices[i] >= m->vertex_count) return 0;
    return clusters_valid(m);
}

tarn_status tarn_scene_check(const tarn_scene *scene)
{
    if (scene == NULL || (scene->object_count > 0 && scene->objects == NULL)) return TARN_ERR_SCENE;
    if (scene->camera.near <= 0 || scene->camera.far <= scene->camera.near) return TARN_ERR_SCENE;
    for (uint32_t i = 0; i < scene->object_count; i++) {
        const tarn_object *o = &scene->objects[i];
        if (o->mesh == NULL || o->material == NULL || !mesh_valid(o->mesh)) return TARN_ERR_SCENE;
        if (o->material->texture != NULL && !texture_valid(o->material->texture)) return TARN_ERR_SCENE;
    }
    return TARN_OK;
}

static void raster_into_tile(void *ctx, const tarn_screen_vertex vertex[3], const tarn_object *object)
{
    tarn_raster_triangle(ctx, vertex, object);
}

static void clear_tile(tarn_tile_target *tile, uint32_t background, int depth_bits, size_t pixels)
{
    for (size_t i = 0; i < pixels; i++) tile->colour[i] = background;
    memset(tile->depth, 0, pixels * (size_t)(depth_bits / 8));
}

tarn_status tarn_render_frame(const tarn_scene *scene, const tarn_frame_config *config,
                              void *memory, size_t memory_bytes, tarn_tile_sink sink, void *user)
{
    if (tarn_config_check(config) != TARN_OK) return TARN_ERR_CONFIG;
    if (memory == NULL || memory_bytes < tarn_frame_memory_bytes(config, scene)) return TARN_ERR_MEMORY;
    tarn_status status = tarn_scene_check(scene);
    if (status != TARN_OK) return status;

    const tarn_quality *quality = &config->quality;
    const int32_t size = quality->tile_size;
    const size_t pixels = (size_t)size * (size_t)size;
    tarn_view view;
    tarn_view_setup(scene, config, &view);
    tarn_tile_target tile;
    tile.colour = memory;
    tile.depth = tile.colour + pixels;
    tile.stride = size;
    tile.quality = quality;
    for (int32_t y = 0; y < config->height; y += size) {
        for (int32_t x = 0; x < config->width; x += size) {
            tile.rect.x0 = x;
            tile.rect.y0 = y;
            tile.rect.x1 = x + size < config->width ? x + size : config->width;
            tile.rect.y1 = y + size < config->height ? y + size : config->height;
            clear_tile(&tile, scene->background_rgb & 0xFFFFFFu, quality->depth_bits, pixels);
            tarn_walk_triangles(scene, &view, &tile.rect, raster_into_tile, &tile);
            tarn_tile out = {(uint16_t)x, (uint16_t)y, (uint16_t)(tile.rect.x1 - x),
                             (uint16_t)(tile.rect.y1 - y), tile.colour, tile.depth,
                             (uint16_t)size, quality->depth_bits};
            if (sink != NULL && sink(user, &out) != 0) return TARN_ERR_SINK;
        }
    }
    return TARN_OK;
}

typedef struct {
    tarn_triangle_visitor visit;
    void *user;
} visit_context;

static void forward_to_visitor(void *ctx, const tarn_screen_vertex vertex[3], const tarn_object *object)
{
    const visit_context *v = ctx;
    v->visit(v->user, vertex, object);
}

tarn_status tarn_visit_screen_triangles(const tarn_scene *scene, const tarn_frame_config *config,
                                        tarn_triangle_visitor visit, void *user)
{
    if (tarn_config_check(config) != TARN_OK) return TARN_ERR_CONFIG;
    tarn_status status = tarn_scene_check(scene);
    if (status != TARN_OK) return status;
    tarn_view view;
    tarn_view_setup(scene, config, &view);
    visit_context ctx = {visit, user};
    tarn_walk_triangles(scene, &view, NULL, forward_to_visitor, &ctx);
    return TARN_OK;
}
