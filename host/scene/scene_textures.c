/* scene_textures.c: the loaded scene's textures (scene_textures.h). */
#include "scene_textures.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A texture just read, weighed with the scene's others: "FILE: FIELD (image WxH): the
 * scene would hold...". Read first, since its header alone says its size, and one is
 * at most TARN_TEXTURE_SIZE_MAX squared texels. */
static int weigh_texture(tarn_loader *l, const char *field, const tarn_image *image)
{
    const tarn_scene_cost texels = { 0, 0, 0, (uint64_t)image->width * image->height };
    char what[sizeof l->err->message];
    snprintf(what, sizeof what, "%s: %s (image %ux%u)", l->file, field, image->width, image->height);
    return tarn_scene_cost_charge(&l->out->cost, &texels, what, l->err);
}

/* The texture for `path`, loaded once however many fields (`field` is this one's)
 * name it. */
static int find_or_load_texture(tarn_loader *l, const char *field, const char *path,
                                const tarn_texture **out)
{
    tarn_loaded_scene *s = l->out;
    for (size_t k = 0; k < s->texture_count; k++) {
        if (strcmp(s->texture_paths[k], path) == 0) {
            *out = &s->textures[k];
            return 0;
        }
    }
    size_t k = s->texture_count;
    if (k == s->texture_capacity) { /* the capacity counts every texture field: a bug */
        return tarn_fail(l->err, "%s: more textures than the loader made room for", l->file);
    }
    tarn_image *image = &s->texture_images[k];
    if (tarn_png_read_texture(path, image, l->err)) return -1;
    s->texture_paths[k] = strdup(path);
    s->texture_count++; /* counted now, so that scene_free releases the image */
    if (!s->texture_paths[k]) return tarn_fail(l->err, "%s: out of memory", l->file);
    if (weigh_texture(l, field, image)) return -1;
    s->textures[k].width = image->width;
    s->textures[k].height = image->height;
    s->textures[k].rgb = image->pixels;
    *out = &s->textures[k];
    return 0;
}

int tarn_get_texture(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                     const tarn_texture **out)
{
    char *path, field[TARN_FIELD_PATH_MAX];
    if (tarn_get_asset_path(l, object, parent, key, "a PNG file name", &path)) return -1;
    tarn_join_path(field, parent, key);
    int result = find_or_load_texture(l, field, path, out);
    free(path);
    return result;
}

/* Whether texture t is read as anything but a water's foam map, which reads red alone. */
static int read_beyond_red(const tarn_loaded_scene *s, const tarn_texture *t)
{
    if (s->underwater.normal_map == t) return 1;
    for (size_t k = 0; k < s->material_count; k++) {
        const tarn_material *m = &s->materials[k];
        const tarn_water *w = m->water;
        if (m->texture == t || (w && (w->normal_a == t || w->normal_b == t || w->colour_ramp == t))) return 1;
    }
    return 0;
}

void tarn_narrow_foam_maps(tarn_loaded_scene *s)
{
    for (size_t k = 0; k < s->texture_count; k++) {
        tarn_texture *t = &s->textures[k];
        if (read_beyond_red(s, t)) continue;
        uint8_t *texels = s->texture_images[k].pixels;
        const size_t count = (size_t)t->width * t->height;
        for (size_t n = 0; n < count; n++) texels[n] = texels[3 * n];
        t->red_only = 1;
    }
}
