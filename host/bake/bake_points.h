/* bake_points.h: `tarn bake ... --points FILE`, many quality settings ("points") baked
 * beside the scene, so that one boot of a board can measure them all
 * (firmware/sweep_main.c, `make firmware-sweep`).
 *
 * FILE is plain text, one point per line, each line the QUALITY options exactly as
 * the command line takes them, applied on top of the bake's own quality:
 *     # pond, baked with --apron off --tile 28 --depth 16
 *     --depth 16                               # the bake's own quality again
 *     --perspective span:16 --recip-steps 1
 *     --perspective affine --depth 32
 * Blank lines and lines whose first non-blank character is '#' are skipped, and a
 * word starting with '#' ends a line's options. As on the command line, a line's
 * --quality NAME replaces the whole base (the bake's quality) with the preset, the
 * knobs change it wherever they stand, and a later knob wins. A bad option or value
 * is a one-line error naming FILE:LINE. FILE must be a regular file (input_file.h). */
#ifndef TARN_HOST_BAKE_POINTS_H
#define TARN_HOST_BAKE_POINTS_H

#include <stddef.h>
#include "error.h"
#include "tarn/tarn_render.h"

#define TARN_BAKE_POINTS_MAX 1000u
/* The largest points file read, checked before its first line: room for every point
 * on a line of a thousand bytes (tests/sweep_points.txt takes 319 bytes in all). */
#define TARN_BAKE_POINTS_FILE_BYTES_MAX (1024u * 1024u)

typedef struct {
    const char *path;       /* the file, for messages */
    tarn_quality *qualities; /* `count` points, in the file's order */
    unsigned *lines;        /* the line each came from, 1-based */
    size_t count;
} tarn_bake_points;

/* Reads `path`, each point starting from `base`. 0, or -1 with `err` set
 * ("points.txt:3: --depth: expected 16 or 32, got '8'") and `points` empty. */
int tarn_bake_points_load(const char *path, const tarn_quality *base, tarn_bake_points *points,
                          tarn_error *err);

/* Every point must give a valid frame config with `config`'s size: 0 with
 * `*memory_bytes` raised to the largest tarn_frame_memory_bytes of them, or -1 with
 * `err` naming the first bad point's FILE:LINE. */
int tarn_bake_points_check(const tarn_bake_points *points, const tarn_frame_config *config,
                           const tarn_scene *scene, size_t *memory_bytes, tarn_error *err);

void tarn_bake_points_free(tarn_bake_points *points);

#endif
