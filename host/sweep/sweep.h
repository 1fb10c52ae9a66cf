/* sweep.h: tarn sweep, the speed/accuracy map of the quality knobs.
 *
 *   tarn sweep [SCENE...] [--out DIR] [--grid full|quick|presets] [--boards B,B|none]
 *              [--host-cost callgrind|none] [--extremes DIR] [--quiet]
 *
 * For each scene (scenes/pond.json when none is given), every point of the grid
 * (sweep_grid.c) is rendered by the core at the scene's size, 1000 ms, and compared
 * with the float reference. Each point's cost is measured on the host (callgrind,
 * tarn_render_frame inclusive, in two workers) and on each emulated board (one
 * firmware boot renders every point that fits the board's RAM: make
 * firmware-sweep), whose checksum of the frame must equal the host's. Then
 * (sweep_report.c) DIR gets sweep.csv, front.md (each scene's and cost's Pareto
 * front) and one PNG plot per scene; with --extremes, stability.md (each knob
 * value's worst case over the extreme scenes in DIR). They are written all or
 * none: a failure leaves the last run's outputs as they were. Every scene, the
 * extreme scenes and the programs it runs are checked before any work, and a
 * failed run removes the work folder it made (DIR/work), unless the error names a
 * log in it. Run it from the top
 * of the tarn tree: a board's cost comes from make there. */
#ifndef TARN_HOST_SWEEP_H
#define TARN_HOST_SWEEP_H

#include <stddef.h>
#include <stdint.h>
#include "yardstick.h"
#include "error.h"
#include "tarn/tarn_render.h"

/* tarn sweep --help */
extern const char tarn_sweep_usage[];

/* What to install for each program the sweep runs: its messages say it. */
#define TARN_SWEEP_INSTALL_VALGRIND "sudo apt-get install valgrind (or give --host-cost none)"
#define TARN_SWEEP_INSTALL_MAKE "sudo apt-get install make"
#define TARN_SWEEP_INSTALL_GNUPLOT "sudo apt-get install gnuplot-nox"

#define TARN_SWEEP_SOURCES_MAX 4 /* the host and up to three boards */
#define TARN_SWEEP_OPTIONS_MAX 256

typedef struct {
    tarn_quality quality;
    const char *preset;            /* "fast", "balanced", "exact", or NULL */
    tarn_yardstick error;          /* whole, shading and panel errors (yardstick.h) */
    uint32_t checksum;             /* tarn_checksum of the host's frame */
    double exp2_max_lsb;           /* the exp2 knob's own largest error (tarn_math) */
    double recip_max_rel;          /* the reciprocal's largest relative error */
    double cost[TARN_SWEEP_SOURCES_MAX]; /* instructions per pixel; negative: not measured */
    uint8_t tile[TARN_SWEEP_SOURCES_MAX]; /* the tile each source rendered it with */
    double convert[TARN_SWEEP_SOURCES_MAX][2]; /* a board's RGB565 conversion without and
                                      with dither, instructions per pixel; negative: none */
    int host_tile_only;            /* a tile-size variant: the boards pick their own tile */
} tarn_sweep_point;

typedef struct {
    const char *path, *name;       /* the scene file, and its name for tables */
    uint16_t width, height;
    tarn_sweep_point *points;
    size_t count;
} tarn_sweep_scene;

/* Where costs come from: sources[0] is "host", the rest are boards. */
typedef struct {
    const char *names[TARN_SWEEP_SOURCES_MAX];
    size_t count;
} tarn_sweep_sources;

/* The command; argv[1] is "sweep". Returns the exit status. */
int tarn_command_sweep(int argc, char **argv);
/* The host-cost worker, run under callgrind by the sweep itself:
 * tarn sweep-cost-worker SCENE POINTS_FILE. */
int tarn_command_sweep_cost_worker(int argc, char **argv);

#endif
