/* scene_budget.h: how much one scene may hold, weighed while it loads, before the
 * work of building what it asks for.
 *
 * A scene file of a few hundred kilobytes can ask for tens of millions of triangles
 * (5,000 spheres of 64 segments and 64 rings), and building them took seconds and a
 * gigabyte before anything said no. So the loader weighs every part before it builds
 * it: planes, boxes and spheres from their fields, all of them before any object is
 * built; a heightfield from its image's size; an OBJ file line by line as it is read;
 * a texture or water map as it is read (one holds at most TARN_TEXTURE_SIZE_MAX
 * squared texels, 3 MB). The part that crosses a limit is refused with one line:
 *   scenes/bad.json: objects[496] (sphere, segments 64, rings 64): the scene would
 *   hold 4,007,808 triangles; the limit is 4,000,000
 *
 * Each limit holds the largest scene of scenes/ 15 to 25 times over (the texels far
 * more: see TARN_SCENE_TEXELS_MAX), and each can be reached without the others: the
 * memory limit stops a scene near all three at once. The largest scene,
 * scenes/extremes/tiny.json, weighs 257,600 triangles, 130,800 vertices and some
 * 7.1 MB; scenes/beach.json holds the most texels, 16,416. */
#ifndef TARN_HOST_SCENE_BUDGET_H
#define TARN_HOST_SCENE_BUDGET_H

#include <stddef.h>
#include <stdint.h>
#include "error.h"

/* Triangles and vertices over every object's mesh, as the generators reserve them
 * (a heightfield before its level squares merge) and as OBJ files hold them. */
#define TARN_SCENE_TRIANGLES_MAX 4000000u
#define TARN_SCENE_VERTICES_MAX 3000000u
/* Texels over every distinct texture and water map: sixteen of the largest a
 * texture may be (48 MB), so that a scene may use that size for its ground, its
 * normal maps and its foam; 25 times the largest scene would refuse one such. */
#define TARN_SCENE_TEXELS_MAX (16u * 1024u * 1024u)
/* The memory the loaded scene keeps, as tarn_scene_cost_bytes estimates it. */
#define TARN_SCENE_MEMORY_MAX (128u * 1024u * 1024u)

/* What a scene, or a part of one, holds. */
typedef struct {
    uint64_t objects, vertices, triangles, texels;
} tarn_scene_cost;

/* The bytes a loaded scene holding `cost` keeps, estimated from what each object,
 * vertex, triangle and texel keeps. */
uint64_t tarn_scene_cost_bytes(const tarn_scene_cost *cost);

/* 1 when `held` and `more` together cross a limit, with the first crossed in `why`
 * ("the scene would hold 4,000,001 triangles; the limit is 4,000,000"); else 0. */
int tarn_scene_cost_over(const tarn_scene_cost *held, const tarn_scene_cost *more, char *why,
                         size_t why_size);

/* Adds `more` to `held`; or, when that would cross a limit, leaves `held` alone and
 * returns -1 with `err` set to "WHAT: WHY". */
int tarn_scene_cost_charge(tarn_scene_cost *held, const tarn_scene_cost *more, const char *what,
                           tarn_error *err);

#endif
