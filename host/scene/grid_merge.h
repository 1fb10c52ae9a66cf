/* grid_merge.h: fewer triangles for the level parts of a vertex grid.
 *
 * A heightfield's flat stretches (a pond's rim, a plateau) draw the same whichever
 * way they are cut into triangles: position and texture coordinates are affine
 * across them and a level surface is lit the same everywhere. On a small board
 * every triangle costs a set-up per tile it touches, so the grid's level squares
 * are merged into aligned power-of-two blocks, each drawn as a fan around its
 * centre vertex. A block's fan passes through every vertex that another block or
 * cell has on the block's border, so no edge ends in the middle of another's
 * (no T-junction, no crack). Cells that are not merged keep the grid's own two
 * triangles, so everything that is not level draws exactly as before. */
#ifndef TARN_HOST_GRID_MERGE_H
#define TARN_HOST_GRID_MERGE_H

#include <stdint.h>
#include "error.h"

typedef struct {
    uint32_t columns, rows; /* vertices along x and along z */
    uint8_t *block_log2;    /* per cell: 1 + log2(size) of the block whose top-left
                               cell it is, 0 for a cell inside another's block */
    uint8_t *corner;        /* per vertex: 1 when it is a corner of a block or cell */
    uint32_t *ring;         /* scratch: the corners around one block's border */
} tarn_grid_blocks;

/* Covers the grid's cells with blocks: the biggest aligned squares whose vertices
 * all carry the same non-zero `level` key (the caller's: 0 for a vertex that is not
 * level, else one value per height), single cells elsewhere. `what` names the
 * object when memory runs out. */
int tarn_grid_blocks_find(tarn_grid_blocks *b, uint32_t columns, uint32_t rows,
                          const uint32_t *level, const char *what, tarn_error *err);

/* The blocks' triangles as vertex indices (row-major grid numbering), in the order
 * of their first cells, wound as the grid's own (a, b, c) = ((i, j), (i, j+1),
 * (i+1, j)), into `indices`, which has room for the grid's two a cell (a block
 * takes at most as many). Returns how many. */
uint32_t tarn_grid_blocks_triangles(const tarn_grid_blocks *b, uint16_t *indices);

void tarn_grid_blocks_free(tarn_grid_blocks *b);

#endif
