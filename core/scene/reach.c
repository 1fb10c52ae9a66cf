/* reach.c: how far from its pixel the water may sample the opaque scene, which
 * sizes the apron each tile draws around itself: refraction's reach
 * (tarn_water.h), the underwater view's displacement, and the quality's cut. */
#include "scene/scene_internal.h"

int tarn__scene_has_water(const tarn_scene *scene)
{
    for (uint32_t i = 0; scene != NULL && i < scene->object_count; i++)
        if (scene->objects[i].material != NULL && scene->objects[i].material->water != NULL) return 1;
    return 0;
}

int32_t tarn_water_reach_pixels(const tarn_water *water, uint16_t frame_width)
{
    if (water == NULL || !(water->features & TARN_WATER_REFRACTION)) return 0;
    /* refraction (Q16) * width * normal_xy_max (Q16): pixels in Q32, rounded up; one
     * more for the rounding of the offset to a whole pixel. Both factors are cut to
     * [0, 1] first, their documented range: a malformed scene reaches at most the
     * frame's width instead of wrapping around to a small reach. */
    const uint64_t refraction = (uint64_t)tarn_clamp_i32(water->refraction, 0, TARN_Q16_ONE);
    const uint64_t xy_max = (uint64_t)tarn_clamp_i32(water->normal_xy_max, 0, TARN_Q16_ONE);
    const uint64_t q32 = refraction * frame_width * xy_max;
    return (int32_t)((q32 + 0xFFFFFFFFu) >> 32) + 1;
}

int32_t tarn__apron_limit(int32_t reach, const tarn_quality *q)
{
    const int32_t limit = q->refraction_apron == TARN_APRON_FULL ? (int32_t)TARN_WATER_APRON_MAX : q->refraction_apron;
    return tarn_clamp_i32(reach, 0, limit);
}

int32_t tarn_frame_apron_pixels(const tarn_scene *scene, const tarn_frame_config *config)
{
    int32_t apron = 0;
    if (scene == NULL) return 0;
    for (uint32_t i = 0; i < scene->object_count; i++) {
        const tarn_material *m = scene->objects[i].material;
        int32_t reach = m != NULL ? tarn_water_reach_pixels(m->water, config->width) : 0;
        if (reach > apron) apron = reach;
    }
    return tarn__apron_limit(apron, &config->quality);
}

/* ---- the underwater view ------------------------------------------------------ */

int tarn__underwater_active(const tarn_scene *scene)
{
    return scene != NULL && scene->underwater != NULL && scene->underwater->normal_map != NULL &&
           scene->camera.position.y < scene->underwater->level;
}

int32_t tarn__underwater_reach_pixels(const tarn_underwater *under, uint16_t frame_width)
{
    /* |N.x|, |N.y| <= 1; one more pixel for rounding the offset */
    uint64_t q16 = (uint64_t)(uint32_t)under->distortion * frame_width;
    return (int32_t)((q16 + 0xFFFFu) >> 16) + 1;
}
