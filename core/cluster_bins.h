/* cluster_bins.h: where on screen each cluster draws, found once a frame (private
 * to core/).
 *
 * Without bins, every tile tests every cluster's bounding sphere against its slice
 * of the view, and walks (transforms, clips, projects) every triangle of each
 * cluster whose sphere touches it: a sphere is loose, so a cluster is walked by
 * several tiles. With bins (the quality's `cluster_bins`), one pass a frame
 * projects every cluster and keeps the screen box its drawable triangles cover, in
 * cells of 4 pixels; a tile then walks only the clusters whose box meets it. That
 * costs 4 bytes of frame memory a cluster, or none where the scene's static view
 * holds the boxes for the frame (tarn bake). A cluster cut by the near plane has no
 * meaningful screen box: its bin is the whole screen and the sphere decides. */
#ifndef TARN_CLUSTER_BINS_H
#define TARN_CLUSTER_BINS_H

#include "pipeline.h"

#define TARN_BIN_CELL_SHIFT 2u /* a cell is 4 x 4 pixels */

/* tarn_cluster_bin (tarn_scene.h): cells [x0, x1] x [y0, y1], inclusive. */

/* Bins a mesh takes: one per cluster, or one for an unclustered mesh. */
uint32_t tarn_cluster_bins_of(const tarn_mesh *mesh);
/* Bins a scene takes, every object in scene order. */
uint32_t tarn_cluster_bin_count(const tarn_scene *scene);
/* Fills bins[tarn_cluster_bin_count(scene)] for this frame's view. */
void tarn_bin_clusters(const tarn_scene *scene, const tarn_view *view, tarn_cluster_bin *bins);

/* 1 when the bin's box meets the pixel rectangle. */
int tarn_cluster_bin_touches(const tarn_cluster_bin *bin, const tarn_pixel_rect *rect);
/* 1 when the bin is the whole screen (the sphere test must decide). */
int tarn_cluster_bin_is_whole(const tarn_cluster_bin *bin);

#endif
