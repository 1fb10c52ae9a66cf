/* obj_load.h: Wavefront OBJ meshes.
 *
 * Understood: v (x y z, or x y z r g b), vt (u [v [w]]), vn (x y z), f with
 * three or more corners (polygons are fanned from their first corner, so they must
 * be convex), each corner v, v/vt, v//vn or v/vt/vn, indices from 1 or negative
 * (relative to the elements read so far). Ignored: o, g, s, usemtl, mtllib and
 * comments. Anything else is an error naming file:line.
 *
 * OBJ fronts are counter-clockwise, as in tarn. OBJ's v runs up the image while
 * tarn's runs down, so v becomes 1 - v. Corners without a normal get a smooth one,
 * the area-weighted average of the faces around their position. Coordinates must
 * satisfy |v| < 32768 to fit Q16.16.
 *
 * Vertex colours (the MeshLab/Blender extension): r g b in 0..1 on a v line, rounded
 * to 8 bits each. If any v line has them the mesh gets colours, white for v lines
 * without; otherwise its colours are NULL. The homogeneous w of `v x y z w` is not
 * accepted: four numbers more likely mean a colour cut short. */
#ifndef TARN_HOST_OBJ_LOAD_H
#define TARN_HOST_OBJ_LOAD_H

#include "error.h"
#include "mesh_gen.h"
#include "scene_budget.h"

/* The largest OBJ file read, checked before its first line. A full tarn mesh
 * (TARN_MESH_VERTICES_MAX vertices with texture coordinates and normals, as many
 * triangles) is about 10 MB of text, and scenes/ holds a 3 KB one; a sparse file of
 * gigabytes would otherwise be read to its end before anything else is said. */
#define TARN_OBJ_FILE_BYTES_MAX (64u * 1024u * 1024u)

/* Reads `path` into `out`: 0, or -1 with `err` naming the file and line. `scene` is
 * what the rest of the scene holds (NULL: nothing); the file stops at the line whose
 * vertices or faces would take the two past a limit of scene_budget.h. */
int tarn_obj_load(const char *path, const tarn_scene_cost *scene, tarn_mesh_buffer *out, tarn_error *err);

#endif
