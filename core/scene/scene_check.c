/* scene_check.c: the scene data is checked once a frame so that nothing the walk
 * or the passes read lies outside the arrays the scene gives. */
#include "scene/scene_internal.h"

/* Sides, texels, and red alone only where it may be: a foam map reads no other
 * channel, every other texture all three. */
static int texels_valid(const tarn_texture *t, int red_only_allowed)
{
    return t->rgb != NULL && tarn_is_power_of_two(t->width) && tarn_is_power_of_two(t->height) &&
           t->width <= TARN_TEXTURE_SIZE_MAX && t->height <= TARN_TEXTURE_SIZE_MAX &&
           t->red_only <= (red_only_allowed ? 1u : 0u);
}

static int texture_valid(const tarn_texture *t)
{
    return texels_valid(t, 0);
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
    if ((w->features & (uint32_t)TARN_LINK_WATER_FEATURES_ALL) != (uint32_t)TARN_LINK_WATER_FEATURES_ALL) return 0;
    if ((w->features & TARN_WATER_NORMALS) && w->normal_a == NULL) return 0;
    if ((w->features & TARN_WATER_FOAM) && (w->foam_texture == NULL || w->foam_distance <= 0)) return 0;
    if ((w->features & TARN_WATER_DEPTH_COLOUR) && w->depth_scale <= 0) return 0;
    return optional_texture_valid(w->normal_a) && optional_texture_valid(w->normal_b) &&
           (w->foam_texture == NULL || texels_valid(w->foam_texture, 1)) && optional_texture_valid(w->colour_ramp) &&
           w->specular_power >= 1 && w->specular_power <= 256 &&
           w->normal_strength >= 0 && w->normal_strength <= 8 * TARN_Q16_ONE;
}

/* A plane's numbers within the ranges water_plane.c's products are sized for
 * (a build without it never reads them). */
static int plane_valid(const tarn_uv_plane *p)
{
    if (p == NULL || !TARN_LINK_WATER_PLANE) return 1;
    if (p->uv_gradient_bits > TARN_UV_PLANE_GRADIENT_BITS_MAX) return 0;
    for (int k = 0; k < 3; k++) {
        if (p->normal[k] < -(1 << 30) || p->normal[k] > (1 << 30)) return 0;
        for (int a = 0; a < 2; a++)
            if (p->uv_gradient[a][k] <= -(1 << 24) || p->uv_gradient[a][k] >= (1 << 24)) return 0;
    }
    return 1;
}

/* The clusters are checked even for a mesh without triangles: the walk follows
 * their runs. Positions and normals are read unless static vertices stand in. */
static int mesh_valid(const tarn_mesh *m, int needs_positions)
{
    if (m->triangle_count > 0) {
        if (m->indices == NULL || (needs_positions && (m->positions == NULL || m->normals == NULL))) return 0;
        for (uint32_t i = 0; i < 3u * m->triangle_count; i++)
            if (m->indices[i] >= m->vertex_count) return 0;
    }
    return clusters_valid(m) && plane_valid(m->plane);
}

/* The frame static screen positions were made for: a size and precision a frame
 * may have (tarn__config_check's own limits). */
static int static_view_valid(const tarn_scene *scene)
{
    const tarn_static_view *v = scene->static_view;
    return v->width >= 1u && v->width <= TARN_FRAME_SIZE_MAX && v->height >= 1u &&
           v->height <= TARN_FRAME_SIZE_MAX && v->subpixel_bits >= TARN_SUBPIXEL_BITS_MIN &&
           v->subpixel_bits <= TARN_SUBPIXEL_BITS_MAX &&
           (v->backdrop == NULL || (TARN_LINK_BACKDROP && tarn__backdrop_valid(v->backdrop, scene)));
}

/* A screen coordinate inside the guard band of its frame, as tarn__project_position
 * clamps it: the edge functions' 32-bit bound rests on it. */
static int screen_valid(int32_t subpixels, uint16_t extent, int32_t guard, unsigned s)
{
    return subpixels >= -((guard + 1) << s) && subpixels <= (((int32_t)extent + guard + 1) << s);
}

/* Static vertices hold what a frame would compute, in the ranges it computes them:
 * shading that rasterizes without carrying into the next channel, and projections
 * inside the guard band. */
static int static_vertices_valid(const tarn_static_view *view, const tarn_static_vertex *vertices, uint32_t count)
{
    tarn_frame_config frame = {0};
    frame.width = view->width;
    frame.height = view->height;
    const int32_t guard = tarn_guard_band_pixels(&frame);
    for (uint32_t i = 0; i < count; i++) {
        const tarn_static_vertex *v = &vertices[i];
        if (v->lit[0] > 65280u || v->lit[1] > 65280u || v->lit[2] > 65280u || v->fresnel > 32768u) return 0;
        if (v->inv_depth == 0u) { /* the planes it lies outside, and nothing else, where read */
            if (TARN_LINK_VERTEX_PASS && ((uint16_t)v->screen_x > TARN_CLIP_PLANE_BITS || v->screen_y != 0)) return 0;
            continue;
        }
        if (v->inv_depth > (1u << 30) || !screen_valid(v->screen_x, view->width, guard, view->subpixel_bits) ||
            !screen_valid(v->screen_y, view->height, guard, view->subpixel_bits))
            return 0;
    }
    return 1;
}

/* An object's static vertices, where they apply, must be valid; where they do not,
 * its mesh must have the positions and normals a frame computes them from, and
 * where they have no view positions beside them, the positions a clipped triangle
 * finds them from. */
static int object_vertices_valid(const tarn_scene *scene, const tarn_object *o, int static_view_applies)
{
    const int uses_static = TARN_LINK_STATIC_VERTICES && o->static_vertices != NULL && static_view_applies;
    if (!uses_static && !TARN_LINK_COMPUTED_VERTICES) return 0;
    if (uses_static && !static_vertices_valid(scene->static_view, o->static_vertices, o->mesh->vertex_count))
        return 0;
    const int clips_from_mesh = uses_static && scene->static_view->positions == NULL && o->mesh->triangle_count > 0;
    if (clips_from_mesh && (!TARN_LINK_COMPUTED_VERTICES || o->mesh->positions == NULL)) return 0;
    return mesh_valid(o->mesh, !uses_static);
}

static int underwater_valid(const tarn_underwater *u)
{
    return TARN_LINK_UNDERWATER && u->normal_map != NULL && texture_valid(u->normal_map);
}

tarn_status tarn__scene_check(const tarn_scene *scene)
{
    if (scene == NULL || (scene->object_count > 0 && scene->objects == NULL)) return TARN_ERR_SCENE;
    if (scene->camera.near <= 0 || scene->camera.far <= scene->camera.near) return TARN_ERR_SCENE;
    if (scene->underwater != NULL && !underwater_valid(scene->underwater)) return TARN_ERR_SCENE;
    if (TARN_LINK_MOTION ? !tarn__motion_valid(scene) : tarn_scene_moves(scene)) return TARN_ERR_SCENE;
    if (TARN_LINK_STATIC_VERTICES && scene->static_view != NULL && !static_view_valid(scene))
        return TARN_ERR_SCENE;
    const int static_view_applies = tarn__static_view_applies(scene);
    for (uint32_t i = 0; i < scene->object_count; i++) {
        const tarn_object *o = &scene->objects[i];
        if (o->mesh == NULL || o->material == NULL || !object_vertices_valid(scene, o, static_view_applies))
            return TARN_ERR_SCENE;
        if (o->material->texture != NULL && !texture_valid(o->material->texture)) return TARN_ERR_SCENE;
        if (o->material->water != NULL && !water_valid(o->material->water)) return TARN_ERR_SCENE;
        if (!TARN_LINK_OPAQUE_OBJECTS && o->material->water == NULL) return TARN_ERR_SCENE;
    }
    return TARN_OK;
}

tarn_status tarn__scene_check_reach(const tarn_scene *scene, const tarn_frame_config *config)
{
    /* the objects a backdrop stands for are gone from the scene */
    const tarn_backdrop *backdrop = tarn__backdrop_for(scene, config);
    if (scene->static_view != NULL && scene->static_view->backdrop != NULL && backdrop == NULL)
        return TARN_ERR_SCENE;
    /* without the water shading linked, water draws only over still water */
    const int still = backdrop != NULL && backdrop->still_water;
    for (uint32_t i = 0; i < scene->object_count; i++) {
        const tarn_water *water = scene->objects[i].material->water;
        if (tarn_water_reach_pixels(water, config->width) > (int32_t)TARN_WATER_APRON_MAX) return TARN_ERR_SCENE;
        if (!TARN_LINK_WATER_SHADING && water != NULL && !still) return TARN_ERR_SCENE;
    }
    return TARN_OK;
}

tarn_status tarn_scene_pose(const tarn_scene *scene, uint32_t time_ms, tarn_scene *posed, tarn_object *objects)
{
    const tarn_status status = tarn__scene_check(scene);
    if (status != TARN_OK) return status;
    tarn__scene_pose(scene, time_ms, posed, scene->object_count > 0u ? objects : NULL);
    return TARN_OK;
}
