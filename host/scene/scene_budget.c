/* scene_budget.c: a scene weighed against its limits (scene_budget.h). */
#include "scene_budget.h"

#include <inttypes.h>
#include <stdio.h>

#include "mesh_clusters.h"
#include "mesh_gen.h"
#include "tarn/tarn_motion.h"

/* What the loaded scene keeps for each: an object, its mesh buffer and its motion; a
 * vertex's position, normal, texture coordinate and colour; a triangle's three
 * indices and its share of a cluster; a texel's RGB. */
#define OBJECT_BYTES (sizeof(tarn_object) + sizeof(tarn_mesh_buffer) + sizeof(tarn_object_motion))
#define VERTEX_BYTES (2 * sizeof(tarn_vec3) + sizeof(tarn_uv) + sizeof(uint32_t))
#define TRIANGLE_BYTES \
    (3 * sizeof(uint16_t) + (sizeof(tarn_cluster) + TARN_CLUSTER_TRIANGLES - 1) / TARN_CLUSTER_TRIANGLES)
#define TEXEL_BYTES 3u

uint64_t tarn_scene_cost_bytes(const tarn_scene_cost *cost)
{
    return cost->objects * OBJECT_BYTES + cost->vertices * VERTEX_BYTES + cost->triangles * TRIANGLE_BYTES +
           cost->texels * TEXEL_BYTES;
}

/* "4,000,000": a count as people read it. */
static const char *with_commas(uint64_t v, char out[32])
{
    char digits[24];
    int n = snprintf(digits, sizeof digits, "%" PRIu64, v), o = 0;
    for (int k = 0; k < n; k++) {
        if (k > 0 && (n - k) % 3 == 0) out[o++] = ',';
        out[o++] = digits[k];
    }
    out[o] = '\0';
    return out;
}

int tarn_scene_cost_over(const tarn_scene_cost *held, const tarn_scene_cost *more, char *why,
                         size_t why_size)
{
    const tarn_scene_cost total = { held->objects + more->objects, held->vertices + more->vertices,
                                    held->triangles + more->triangles, held->texels + more->texels };
    const struct {
        uint64_t would, limit;
        const char *verb, *noun; /* "the scene would VERB N NOUN" */
    } limits[] = {
        { total.triangles, TARN_SCENE_TRIANGLES_MAX, "hold", "triangles" },
        { total.vertices, TARN_SCENE_VERTICES_MAX, "hold", "vertices" },
        { total.texels, TARN_SCENE_TEXELS_MAX, "hold", "texels of textures and water maps" },
        { tarn_scene_cost_bytes(&total), TARN_SCENE_MEMORY_MAX, "need some", "bytes of memory" },
    };
    for (size_t k = 0; k < sizeof limits / sizeof limits[0]; k++) {
        if (limits[k].would <= limits[k].limit) continue;
        char would[32], limit[32];
        snprintf(why, why_size, "the scene would %s %s %s; the limit is %s", limits[k].verb,
                 with_commas(limits[k].would, would), limits[k].noun, with_commas(limits[k].limit, limit));
        return 1;
    }
    return 0;
}

int tarn_scene_cost_charge(tarn_scene_cost *held, const tarn_scene_cost *more, const char *what,
                           tarn_error *err)
{
    char why[160];
    if (tarn_scene_cost_over(held, more, why, sizeof why)) return tarn_fail(err, "%s: %s", what, why);
    held->objects += more->objects;
    held->vertices += more->vertices;
    held->triangles += more->triangles;
    held->texels += more->texels;
    return 0;
}
