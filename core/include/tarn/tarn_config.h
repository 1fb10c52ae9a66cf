/* tarn_config.h: what of the renderer is compiled in, chosen when core/ is built.
 *
 * Every switch is TARN_LINK_<PART>: 1 (the default) compiles the part in, 0 leaves
 * its code out of the image, and a frame that would need it is refused
 * (tarn_render_frame returns TARN_ERR_CONFIG for a quality knob, TARN_ERR_SCENE
 * for scene data). Nothing else changes: a frame the build can draw is the same,
 * byte for byte, whatever the switches.
 *
 * Set them when compiling every file of core/, in one of these ways:
 *  - `tarn bake` writes NAME_link.h with each switch set to what the baked scene
 *    and qualities use; compile core/ with `-include NAME_link.h` (firmware/);
 *  - `-DTARN_LINK_APRON=0` and the like on the compiler's command line;
 *  - CMake: the options of the same names (core/CMakeLists.txt).
 * A switch left unset here is 1. The switches only remove code, so a mistaken 0
 * shows as a refused frame, never as a wrong one. The one setting after them,
 * TARN_VERTEX_CACHE_SLOTS, trades stack for speed and is set the same ways. */
#ifndef TARN_CONFIG_H
#define TARN_CONFIG_H

/* ---- the rasterizer ---------------------------------------------------------- */

/* The perspective modes (tarn_render.h), each a loop of its own: TARN_PERSPECTIVE_AFFINE,
 * which TARN_PERSPECTIVE_SPAN needs too (it draws triangles narrower than a span
 * affine); TARN_PERSPECTIVE_SPAN, about 1 KB of a Cortex-M0 image; and
 * TARN_PERSPECTIVE_PIXEL, a reciprocal and a product per attribute at every pixel. */
#ifndef TARN_LINK_PERSPECTIVE_AFFINE
#define TARN_LINK_PERSPECTIVE_AFFINE 1
#endif
#ifndef TARN_LINK_PERSPECTIVE_SPAN
#define TARN_LINK_PERSPECTIVE_SPAN 1
#endif

#ifndef TARN_LINK_PERSPECTIVE_PIXEL
#define TARN_LINK_PERSPECTIVE_PIXEL 1
#endif

/* The depth buffer's forms (the quality's depth_bits): 16 bits, a small float of
 * near/d, and 32 bits, near/d in Q1.30. Every pixel's depth test and store is
 * compiled for the forms linked. */
#ifndef TARN_LINK_DEPTH16
#define TARN_LINK_DEPTH16 1
#endif
#ifndef TARN_LINK_DEPTH32
#define TARN_LINK_DEPTH32 1
#endif

/* TARN_DEPTH_EXACT: the exact per-pixel division of the depth. Without it every
 * quality must use TARN_DEPTH_PLANE. */
#ifndef TARN_LINK_EXACT_DEPTH
#define TARN_LINK_EXACT_DEPTH 1
#endif

/* ---- vertices ----------------------------------------------------------------- */

/* Transforming and lighting vertices in the frame. Without it every object needs
 * static vertices that apply (tarn_scene.h): a baked, fixed view. */
#ifndef TARN_LINK_COMPUTED_VERTICES
#define TARN_LINK_COMPUTED_VERTICES 1
#endif

/* Reading static vertices (tarn_scene.h). Without it a scene's static view is
 * ignored and its meshes need their positions (tarn bake --static-view off). */
#ifndef TARN_LINK_STATIC_VERTICES
#define TARN_LINK_STATIC_VERTICES 1
#endif

/* Finding the clusters' screen boxes in the frame (the quality's cluster_bins).
 * Without it a frame whose bins the scene's static view does not hold tests each
 * cluster's bounding sphere instead: the same image, at more cost. */
#ifndef TARN_LINK_FOUND_BINS
#define TARN_LINK_FOUND_BINS 1
#endif

/* ---- backdrops ------------------------------------------------------------------ */

/* Starting each tile from a backdrop (tarn_scene.h, tarn bake --backdrop). */
#ifndef TARN_LINK_BACKDROP
#define TARN_LINK_BACKDROP 1
#endif

/* Drawing objects of opaque materials. Without it every opaque object must be in
 * a backdrop (tarn bake --backdrop): a scene with one is refused. */
#ifndef TARN_LINK_OPAQUE_OBJECTS
#define TARN_LINK_OPAQUE_OBJECTS 1
#endif

/* Water over a still-water backdrop (tarn bake --backdrop still). */
#ifndef TARN_LINK_STILL_WATER
#define TARN_LINK_STILL_WATER 1
#endif

/* ---- water (tarn_water.h) ----------------------------------------------------- */

/* Water materials at all. */
#ifndef TARN_LINK_WATER
#define TARN_LINK_WATER 1
#endif

/* The water effects compiled in, as TARN_WATER_* bits: the calls of the others are
 * removed at compile time. */
#ifndef TARN_LINK_WATER_FEATURES
#define TARN_LINK_WATER_FEATURES 0xFFFFFFFFu
#endif

/* The water effects every water material of the build has, as TARN_WATER_* bits
 * (within TARN_LINK_WATER_FEATURES): a water pixel does not ask whether its
 * material has them, about ten questions a pixel fewer. The scene check refuses a
 * water material without them. None by default; tarn bake writes its scene's. */
#ifndef TARN_LINK_WATER_FEATURES_ALL
#define TARN_LINK_WATER_FEATURES_ALL 0u
#endif

/* Flat water's texture coordinates from its plane (tarn_uv_plane) at each pixel,
 * the quality's water_coordinates TARN_WATER_UV_PLANE: about 2.5 KB of code on the
 * Cortex-M0. A build that shades water without it refuses that quality; tarn bake
 * leaves it out when no quality it bakes takes it for the scene's water. */
#ifndef TARN_LINK_WATER_PLANE
#define TARN_LINK_WATER_PLANE 1
#endif

/* Shading water pixels in the frame, every step of tarn_water.h. Without it water
 * draws only over a still-water backdrop, which holds the still steps. */
#ifndef TARN_LINK_WATER_SHADING
#define TARN_LINK_WATER_SHADING 1
#endif

/* A refracted sample that moves: the quality's refraction_apron above 0. Without
 * it every refracted sample is the pixel's own. */
#ifndef TARN_LINK_APRON
#define TARN_LINK_APRON 1
#endif

/* The exact normal for refraction: the quality's refraction_normal
 * TARN_REFRACTION_NORMAL_EXACT. */
#ifndef TARN_LINK_REFRACTION_EXACT
#define TARN_LINK_REFRACTION_EXACT 1
#endif

/* A lit colour found along its line (tarn_lit_colour TARN_LIT_LINE) by the opaque
 * triangles drawn in per-pixel perspective. tarn bake leaves it out where none
 * are drawn (another perspective, or a frame over a backdrop); a build without it
 * gives every channel a plane. */
#ifndef TARN_LINK_LIT_LINE
#define TARN_LINK_LIT_LINE 1
#endif

/* Water effects shared by 2x2 or 4x4 blocks: the quality's water_block 2 or 4. */
#ifndef TARN_LINK_WATER_BLOCKS
#define TARN_LINK_WATER_BLOCKS 1
#endif

/* Frames cut into strips (the quality's frame_shape TARN_FRAME_STRIPS). */
#ifndef TARN_LINK_STRIPS
#define TARN_LINK_STRIPS 1
#endif

/* Vertices found once a frame (the quality's vertex_pass TARN_VERTICES_PER_FRAME);
 * it reads them as static vertices, so needs TARN_LINK_STATIC_VERTICES too. */
#ifndef TARN_LINK_VERTEX_PASS
#define TARN_LINK_VERTEX_PASS 1
#endif

/* A frame drawn in parts by several cores (tarn_render_frame_part with parts > 1):
 * the code that shares the tiles and strips out. `tarn bake` leaves it to the
 * build, which knows its cores: firmware/firmware.mk sets 0 on a board of one. */
#ifndef TARN_LINK_PARTS
#define TARN_LINK_PARTS 1
#endif

/* The underwater view (tarn_scene.h's underwater block). */
#ifndef TARN_LINK_UNDERWATER
#define TARN_LINK_UNDERWATER 1
#endif

/* Scenes that move (tarn_motion.h): the frame poses camera, light and objects for
 * its time. Without it a scene with any motion is refused (TARN_ERR_SCENE). */
#ifndef TARN_LINK_MOTION
#define TARN_LINK_MOTION 1
#endif

/* ---- memory ------------------------------------------------------------------ */

/* Not a switch: how many vertices the walk keeps transformed, projected and lit
 * while it draws one object into one tile or strip, a power of two from 4 to 256,
 * 32 bytes of stack each. A vertex the cache has lost is found again. 16, the
 * default, suits a board of 16 KB; a board with RAM drawing a scene that moves
 * without the vertex pass keeps 64 (boards/qemu-m0-264k/board.mk; docs/firmware.md
 * measures it). Every value draws the same frames. */
#ifndef TARN_VERTEX_CACHE_SLOTS
#define TARN_VERTEX_CACHE_SLOTS 16u
#endif

#endif
