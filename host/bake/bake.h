/* bake.h: a loaded scene written out as const C data for firmware.
 *
 * `tarn bake scenes/pond.json -o out/pond.c` writes three files:
 *   out/pond.c  one self-contained C99 source, needing only core/include/tarn/tarn_render.h:
 *               every mesh, texture, material, water block and object the scene
 *               uses, as `static const` arrays and structs, and two objects
 *                 const tarn_scene pond_scene;
 *                 const tarn_frame_config pond_config;   (frame size and quality)
 *   out/pond.h  declares both and  #define POND_MEMORY_BYTES N, the working memory
 *               tarn_frame_memory_bytes gives for that config, so that firmware can
 *               declare  static uint32_t mem[(POND_MEMORY_BYTES + 3) / 4];
 *   out/pond_link.h  the TARN_LINK_* switches of tarn_render.h for this scene:
 *               compiled into core/ (-include), they leave out the code of every
 *               effect the scene does not use;
 * Every integer is the loaded one, printed exactly; nothing the scene does not
 * reference is written (a texture no used material samples, a mesh that repeats
 * another's data). The header comment of pond.c counts the const bytes of each
 * kind as a 32-bit target lays them out.
 * With `points_path` (--points FILE, bake_points.h), pond.c also defines
 *                 const tarn_quality pond_points[N];   (the file's qualities)
 * pond.h declares it with  #define POND_POINT_COUNT N, POND_MEMORY_BYTES is the
 * largest working memory of the config and of every point, and pond_link.h links
 * whatever any point uses.
 * The files are written all or nothing (atomic_file.h). */
#ifndef TARN_HOST_BAKE_H
#define TARN_HOST_BAKE_H

#include <stddef.h>
#include "error.h"
#include "backdrop.h"
#include "scene_load.h"
#include "tarn/tarn_render.h"

/* Longest NAME: leaves room for the suffixes of every symbol it prefixes. */
#define TARN_BAKE_NAME_MAX 40u

typedef struct {
    const char *scene_path;  /* shown in the header comment */
    const char *output_path; /* must end in ".c"; the headers go beside it */
    const char *name;        /* C identifier prefixing every symbol; NULL: the scene's stem */
    const char *points_path; /* --points FILE (bake_points.h), or NULL */
    int static_view;         /* 1: every object gets static vertices for the scene's camera
                                and the config's frame, and the meshes lose the positions,
                                normals and colours they replace (static_view.h) */
    tarn_backdrop_request backdrop; /* with static_view, what is drawn once for the
                                config into the static view's backdrop (backdrop.h):
                                nothing, the opaque objects, or the still water too;
                                only the water objects are then baked */
    tarn_frame_config config; /* frame size and quality; its time_ms is baked as 0 */
    int argc;                /* the command line, shown in the header comment */
    char *const *argv;
    int quiet;               /* no progress line while the files are written (progress.h) */
} tarn_bake_options;

typedef struct {
    char name[TARN_BAKE_NAME_MAX + 1]; /* the prefix used */
    size_t const_bytes;                /* every baked object, 32-bit layout */
    size_t memory_bytes;               /* tarn_frame_memory_bytes of the baked config (the
                                          largest of it and the points') */
} tarn_bake_result;

/* 0, or -1 with a one-line `err` and neither file written. */
int tarn_bake(const tarn_loaded_scene *scene, const tarn_bake_options *options,
              tarn_bake_result *result, tarn_error *err);

/* 0 if `name` can prefix the baked symbols: a C identifier of at most
 * TARN_BAKE_NAME_MAX characters outside the renderer's own tarn_ namespace. */
int tarn_bake_check_name(const char *name, tarn_error *err);

/* A scene file's stem made a valid name: other characters become '_', and a stem
 * that still would not do gains a "scene_" prefix ("3d-pond" -> "scene_3d_pond"). */
void tarn_bake_default_name(const char *stem, char out[TARN_BAKE_NAME_MAX + 1]);

#endif
