/* static_view.h: a scene with its static view (tarn_scene.h), made on the host for
 * firmware that draws the scene from one fixed camera.
 *
 * Each object's vertices are transformed, lit and, for the given frame, projected by
 * the core's own functions, and each cluster binned by the core's own function, so
 * they hold exactly what a frame would compute: a frame drawn with them is the same,
 * byte for byte, as one drawn without. `tarn bake` writes them (docs/bake.md,
 * "Static view"). */
#ifndef TARN_HOST_STATIC_VIEW_H
#define TARN_HOST_STATIC_VIEW_H

#include "error.h"
#include "tarn/tarn_motion.h"
#include "tarn/tarn_render.h"

typedef struct {
    tarn_static_view view;         /* its bins point to `bins` */
    tarn_static_vertex **vertices; /* per object of the scene: its mesh's vertex_count */
    tarn_vec3 *positions;          /* their view positions, every object's in scene order */
    uint32_t object_count;
    tarn_cluster_bin *bins;        /* every cluster's, in scene order */
    uint32_t bin_count;
} tarn_static_vertices;

/* The scene as it draws with a static view: copies of its objects, each pointing to
 * its static vertices and to a copy of its mesh that, unless `keep_positions`, has
 * no positions, normals or colours (they served only to compute what the static
 * vertices hold), and `scene`, the input with those objects and the static view. */
typedef struct {
    tarn_scene scene;
    tarn_static_vertices vertices;
    tarn_object *objects;
    tarn_mesh *meshes;
} tarn_static_scene;

/* Makes the static view of `scene` for its camera and light, with screen positions
 * and cluster bins for `config`'s frame size and subpixel bits. 0, or -1 with `err`
 * set (out of memory; `out` is then empty). */
int tarn_static_scene_make(const tarn_scene *scene, const tarn_frame_config *config, int keep_positions,
                           tarn_static_scene *out, tarn_error *err);
void tarn_static_scene_free(tarn_static_scene *s);

/* tarn_frame_memory_bytes of `config` for the scene as tarn bake writes it with a
 * static view made for `made_for`: in that frame its bins come from flash. A scene
 * that moves is baked without one. */
size_t tarn_static_memory_bytes(const tarn_frame_config *config, const tarn_scene *scene,
                                const tarn_frame_config *made_for);

#endif
