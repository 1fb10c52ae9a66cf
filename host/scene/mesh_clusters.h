/* mesh_clusters.h: orders a mesh's triangles so that neighbours in space are
 * neighbours in the index list, then cuts the list into runs with a bounding sphere
 * each (tarn_cluster). For every tile the core skips the runs whose sphere cannot
 * touch it, so a large mesh costs each tile only the part of it that is nearby. */
#ifndef TARN_HOST_MESH_CLUSTERS_H
#define TARN_HOST_MESH_CLUSTERS_H

#include "error.h"
#include "mesh_gen.h"

/* Triangles per run: smaller runs skip more precisely, but every run costs a
 * sphere test per tile (docs/figures.md has the measurement behind this value). */
#define TARN_CLUSTER_TRIANGLES 8u

/* Reorders m's triangles along a Z-order curve of their centroids and fills
 * m->clusters. 0, or -1 with `err` set (out of memory; m is left as it was). */
int tarn_mesh_build_clusters(tarn_mesh_buffer *m, tarn_error *err);

#endif
