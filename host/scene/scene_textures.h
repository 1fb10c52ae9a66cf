/* scene_textures.h: the textures a scene file's fields name, kept in the loaded
 * scene (scene_load.h): each image file read once, however many fields name it.
 * The loader's materials and water blocks (water_load.c) read them through here. */
#ifndef TARN_HOST_SCENE_TEXTURES_H
#define TARN_HOST_SCENE_TEXTURES_H

#include "scene_fields.h"
#include "scene_load.h"

/* A required PNG file name, relative to the scene, loaded as a texture (power-of-two
 * sides) into l->out's textures once however many fields name it. */
int tarn_get_texture(tarn_loader *l, const json_t *object, const char *parent, const char *key,
                     const tarn_texture **out);

/* Each texture read only as a water's foam map, which reads red alone, kept as its
 * red bytes (tarn_texture.red_only): a third of the flash a bake gives it. Called
 * once every field that names a texture is loaded. */
void tarn_narrow_foam_maps(tarn_loaded_scene *s);

#endif
