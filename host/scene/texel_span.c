/* texel_span.c: see texel_span.h. */
#include "texel_span.h"

#include <stdio.h>

#include "scene_load.h"

/* The most any one triangle of the mesh spans along u and along v, in repeats of
 * its texture coordinates. */
static void widest_triangle(const tarn_mesh *mesh, double span[2])
{
    span[0] = span[1] = 0;
    if (mesh->uvs == NULL) return;
    for (uint32_t t = 0; t < mesh->triangle_count; t++) {
        const uint16_t *corner = &mesh->indices[3 * t];
        for (int axis = 0; axis < 2; axis++) {
            int32_t low = INT32_MAX, high = INT32_MIN;
            for (int k = 0; k < 3; k++) {
                const tarn_uv *uv = &mesh->uvs[corner[k]];
                const int32_t c = axis == 0 ? uv->u : uv->v;
                low = c < low ? c : low;
                high = c > high ? c : high;
            }
            const double repeats = ((double)high - low) / 65536.0;
            if (repeats > span[axis]) span[axis] = repeats;
        }
    }
}

/* The texels of `texture` the widest triangle crosses, its coordinates times `scale`. */
static double texels_crossed(const double span[2], const tarn_texture *texture, double scale)
{
    const double across = span[0] * scale * texture->width, down = span[1] * scale * texture->height;
    return across > down ? across : down;
}

static int refuse(tarn_loader *l, const char *field, double texels, const char *what, size_t index)
{
    return tarn_fail_field(l, field,
                           "a triangle of objects[%zu] spans %.0f texels of %s; the core interpolates at most "
                           "%.0f precisely enough (use smaller triangles or a smaller scale)",
                           index, texels, what, TARN_TEXEL_SPAN_MAX);
}

/* A water map (normal map or foam texture) under the mesh's widest triangle. */
static int check_map(tarn_loader *l, const double span[2], const tarn_texture *map, const tarn_panning *pan,
                     const char *map_field, size_t index, const char *uv_field)
{
    if (map == NULL) return 0;
    const double scale = pan->scale / 65536.0, texels = texels_crossed(span, map, scale);
    if (texels <= TARN_TEXEL_SPAN_MAX) return 0;
    /* a mesh within the limit at scale 1 is the scale's doing */
    if (texels_crossed(span, map, 1.0) <= TARN_TEXEL_SPAN_MAX) {
        char field[TARN_FIELD_PATH_MAX];
        snprintf(field, sizeof field, "%s.scale", map_field);
        return refuse(l, field, texels, "the map", index);
    }
    return refuse(l, uv_field, texels, map_field, index);
}

int tarn_check_texel_spans(tarn_loader *l, const tarn_object *object, size_t index, const char *uv_field)
{
    const tarn_material *material = object->material;
    double span[2];
    widest_triangle(object->mesh, span);
    if (material->texture != NULL) {
        const double texels = texels_crossed(span, material->texture, 1.0);
        if (texels > TARN_TEXEL_SPAN_MAX) return refuse(l, uv_field, texels, "its texture", index);
    }
    const tarn_water *water = material->water;
    if (water == NULL) return 0;
    const size_t k = (size_t)(material - l->out->materials);
    char water_field[TARN_FIELD_PATH_MAX], map_field[TARN_FIELD_PATH_MAX + 32];
    snprintf(water_field, sizeof water_field, "materials.%s.water", l->out->material_names[k]);
    snprintf(map_field, sizeof map_field, "%s.normal_maps[0]", water_field);
    if (check_map(l, span, water->normal_a, &water->pan_a, map_field, index, uv_field)) return -1;
    snprintf(map_field, sizeof map_field, "%s.normal_maps[1]", water_field);
    if (check_map(l, span, water->normal_b, &water->pan_b, map_field, index, uv_field)) return -1;
    snprintf(map_field, sizeof map_field, "%s.foam", water_field);
    return check_map(l, span, water->foam_texture, &water->foam_pan, map_field, index, uv_field);
}
