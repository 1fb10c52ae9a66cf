/* scene_textures.c: the loaded scene's textures (scene_textures.h). */
#include "scene_textures.h"

#include <stdlib.h>
#include <string.h>

/* The texture for `path`, loaded once however many materials use it. */
static int find_or_load_texture(tarn_loader *l, const char *path, const tarn_texture **out)
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
    s->textures[k].width = image->width;
    s->textures[k].height = image->height;
    s->textures[k].rgb = image->pixels;
    *out = &s->textures[k];
    return 0;
}

int tarn_get_texture(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                     const tarn_texture **out)
{
    char *path;
    if (tarn_get_asset_path(l, object, parent, key, "a PNG file name", &path)) return -1;
    int result = find_or_load_texture(l, path, out);
    free(path);
    return result;
}
