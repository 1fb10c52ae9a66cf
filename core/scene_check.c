/* scene_check.c: the scene data is checked once a frame so that nothing the walk
 * or the passes read lies outside the arrays the scene gives. */
#include "pipeline.h"

static int texture_valid(const tarn_texture *t)
{
    return t->rgb != NULL && tarn_is_power_of_two(t->width) && tarn_is_power_of_two(t->height) &&
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

static int optional_texture_valid(const tarn_texture *t)
{
    return t == NULL || texture_valid(t);
}

static int within(tarn_q16 v, tarn_q16 lo, tarn_q16 hi)
{
    return v >= lo && v <= hi;
}

/* A water material this build can draw: its effects linked (TARN_LINK_*), every
 * texture a feature samples there, and the factors the per-pixel code blends with
 * in their documented ranges (checked here once, so no pixel has to); the apron
 * limit is checked against the frame width when a frame is drawn. */
static int water_valid(const tarn_water *w)
{
    if (!within(w->alpha, 0, TARN_Q16_ONE) || !within(w->fresnel, 0, TARN_Q16_ONE) ||
        !within(w->foam_opacity, 0, TARN_Q16_ONE) || !within(w->specular, 0, 4 * TARN_Q16_ONE))
        return 0;
    if (!TARN_LINK_WATER || (w->features & ~(uint32_t)TARN_LINK_WATER_FEATURES) != 0) return 0;
    if ((w->features & TARN_WATER_NORMALS) && w->normal_a == NULL) return 0;
    if ((w->features & TARN_WATER_FOAM) && (w->foam_texture == NULL || w->foam_distance <= 0)) return 0;
    if ((w->features & TARN_WATER_DEPTH_COLOUR) && w->depth_scale <= 0) return 0;
    return optional_texture_valid(w->normal_a) && optional_texture_valid(w->normal_b) &&
           optional_texture_valid(w->foam_texture) && optional_texture_valid(w->colour_ramp) &&
           w->specular_power >= 1 && w->specular_power <= 256 &&
           w->normal_strength >= 0 && w->normal_strength <= 8 * TARN_Q16_ONE;
}

/* The clusters are checked even for a mesh without triangles: the walk follows
 * their runs. */
static int mesh_valid(const tarn_mesh *m)
{
    if (m->triangle_count > 0) {
        if (m->positions == NULL || m->normals == NULL || m->indices == NULL) return 0;
        for (uint32_t i = 0; i < 3u * m->triangle_count; i++)
            if (m->indices[i] >= m->vertex_count) return 0;
    }
    return clusters_valid(m);
}

static int underwater_valid(const tarn_underwater *u)
{
    return TARN_LINK_UNDERWATER && u->normal_map != NULL && texture_valid(u->normal_map);
}

tarn_status tarn_scene_check(const tarn_scene *scene)
{
    if (scene == NULL || (scene->object_count > 0 && scene->objects == NULL)) return TARN_ERR_SCENE;
    if (scene->camera.near <= 0 || scene->camera.far <= scene->camera.near) return TARN_ERR_SCENE;
    if (scene->underwater != NULL && !underwater_valid(scene->underwater)) return TARN_ERR_SCENE;
    for (uint32_t i = 0; i < scene->object_count; i++) {
        const tarn_object *o = &scene->objects[i];
        if (o->mesh == NULL || o->material == NULL || !mesh_valid(o->mesh)) return TARN_ERR_SCENE;
        if (o->material->texture != NULL && !texture_valid(o->material->texture)) return TARN_ERR_SCENE;
        if (o->material->water != NULL && !water_valid(o->material->water)) return TARN_ERR_SCENE;
    }
    return TARN_OK;
}

tarn_status tarn_scene_check_reach(const tarn_scene *scene, const tarn_frame_config *config)
{
    for (uint32_t i = 0; i < scene->object_count; i++)
        if (tarn_water_reach_pixels(scene->objects[i].material->water, config->width) >
            (int32_t)TARN_WATER_APRON_MAX)
            return TARN_ERR_SCENE;
    return TARN_OK;
}

