/* uv_plane.h: whether a mesh is flat, its texture coordinates an affine map of its
 * plane, found in doubles; and that plane in the integers the core reads
 * (tarn_uv_plane, tarn_scene.h). The loader gives every such mesh its plane, and
 * still water's bake places it in the frame (host/bake/still_planes.c). */
#ifndef TARN_HOST_UV_PLANE_H
#define TARN_HOST_UV_PLANE_H

#include "mesh_gen.h"
#include "ref_geometry.h"
#include "tarn/tarn_water.h"

/* The plane through `origin` with unit normal `normal`, and the coordinates on it:
 * uv = uv0 + gradient . (p - origin), each gradient along the plane. */
typedef struct {
    tarn_dvec3 origin, normal;
    double uv0[2];
    tarn_dvec3 gradient[2];
} tarn_uv_plane_fit;

/* 1 with *out (object space) when every vertex of `mesh` lies on one plane and
 * takes the coordinates an affine map of it gives, each within 1e-4 of the mesh's
 * extent (Q16.16 positions and coordinates round by 2^-17); else 0, and *why says
 * which fails ("spans no plane", "is not flat", "has texture coordinates that are
 * not an affine map of its plane"). */
int tarn_uv_plane_find(const tarn_mesh *mesh, tarn_uv_plane_fit *out, const char **why);

/* The plane in tarn_uv_plane's integers: 0 when its offset, the map at the object's
 * origin or its gradient leaves their ranges. */
int tarn_uv_plane_to_fixed(const tarn_uv_plane_fit *p, tarn_uv_plane *out);

/* The most repeats of its finest map a water mesh's coordinates may reach (the
 * largest |uv| times the largest map scale) for the plane to give them: the core
 * holds u * (n . dir) in 32 bits, so a coordinate keeps about 2^-29 of the largest
 * (docs/figures.md, "Flat water"), where a triangle's interpolation keeps bits below
 * its own corners'; at 256 repeats of a 64-texel map that is 2^-15 of a texel. */
#define TARN_UV_PLANE_REPEATS_MAX 256.0

/* The plane of m, drawn with `water`, into m->plane when m is flat, its plane fits
 * the integers and its coordinates stay within TARN_UV_PLANE_REPEATS_MAX (NULL
 * otherwise): 0, or -1 when memory runs out. */
int tarn_mesh_find_plane(tarn_mesh_buffer *m, const tarn_water *water);

#endif
