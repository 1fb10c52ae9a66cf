/* static_view.c: whether a scene's static view (tarn_scene.h), the vertices a bake
 * computed for one camera and light, applies to a frame. */
#include "scene/scene_internal.h"

static int same_vec3(const tarn_vec3 *a, const tarn_vec3 *b)
{
    return a->x == b->x && a->y == b->y && a->z == b->z;
}

static int same_camera(const tarn_camera *a, const tarn_camera *b)
{
    return same_vec3(&a->position, &b->position) && same_vec3(&a->target, &b->target) &&
           a->fov_y_degrees == b->fov_y_degrees && a->near == b->near && a->far == b->far;
}

static int same_light(const tarn_light *a, const tarn_light *b)
{
    return same_vec3(&a->direction, &b->direction) && a->colour_rgb == b->colour_rgb &&
           a->ambient_rgb == b->ambient_rgb;
}

int tarn__static_view_applies(const tarn_scene *scene)
{
    const tarn_static_view *s = scene->static_view;
    return TARN_LINK_STATIC_VERTICES && s != NULL && !tarn__view_moves(scene) && same_camera(&s->camera, &scene->camera) && same_light(&s->light, &scene->light);
}

int tarn__static_screen_applies(const tarn_scene *scene, const tarn_frame_config *config)
{
    const tarn_static_view *s = scene->static_view;
    return tarn__static_view_applies(scene) && s->width == config->width && s->height == config->height &&
           s->subpixel_bits == config->quality.subpixel_bits;
}
