/* static_view.h: a scene's static vertices (tarn_scene.h), computed on the host for
 * firmware that draws the scene from one fixed camera.
 *
 * Each object's vertices are transformed, lit and, for the given frame, projected by
 * the core's own functions, so they hold exactly what a frame would compute: a frame
 * drawn with them is the same, byte for byte, as one drawn without. `tarn bake`
 * writes them (docs/bake.md, "Static view"). */
#ifndef TARN_HOST_STATIC_VIEW_H
#define TARN_HOST_STATIC_VIEW_H

#include "error.h"
#include "tarn_render.h"

typedef struct {
    tarn_static_view view;         /* its bins point to `bins` */
    tarn_static_vertex **vertices; /* per object of the scene: its mesh's vertex_count */
    uint32_t object_count;
    tarn_cluster_bin *bins;        /* every cluster's, in scene order */
    uint32_t bin_count;
} tarn_static_vertices;

/* Computes every object's static vertices for the scene's camera and light, with
 * screen positions and cluster bins for `config`'s frame size and subpixel bits. 0,
 * or -1 with `err` set (out of memory; `out` is then empty). */
int tarn_static_vertices_build(const tarn_scene *scene, const tarn_frame_config *config,
                               tarn_static_vertices *out, tarn_error *err);
void tarn_static_vertices_free(tarn_static_vertices *s);

/* tarn_frame_memory_bytes of `config` for the scene as tarn bake writes it with a
 * static view made for `made_for`: in that frame its bins come from flash. */
size_t tarn_static_memory_bytes(const tarn_frame_config *config, const tarn_scene *scene,
                                const tarn_frame_config *made_for);

#endif
