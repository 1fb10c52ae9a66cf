#include "grid_merge.h"

#include <stdlib.h>
#include <string.h>

static uint32_t vertex_at(const tarn_grid_blocks *b, uint32_t i, uint32_t j)
{
    return j * b->columns + i;
}

static uint32_t block_size(uint8_t block_log2)
{
    return 1u << (block_log2 - 1u);
}

/* Whether every vertex of the size x size block at cell (i, j) has the same
 * non-zero level key. */
static int block_is_level(const tarn_grid_blocks *b, const uint32_t *level, uint32_t i, uint32_t j,
                          uint32_t size)
{
    const uint32_t key = level[vertex_at(b, i, j)];
    if (key == 0) return 0;
    for (uint32_t y = j; y <= j + size; y++) {
        for (uint32_t x = i; x <= i + size; x++) {
            if (level[vertex_at(b, x, y)] != key) return 0;
        }
    }
    return 1;
}

/* Marks the size x size block at cell (i, j): its first cell holds its size, the
 * others 0. */
static void take_block(tarn_grid_blocks *b, uint32_t i, uint32_t j, uint8_t block_log2)
{
    const uint32_t cells_x = b->columns - 1, size = block_size(block_log2);
    for (uint32_t y = j; y < j + size; y++) memset(&b->block_log2[y * cells_x + i], 0, size);
    b->block_log2[j * cells_x + i] = block_log2;
}

/* Bigger blocks first; aligned power-of-two squares nest, so a block not yet
 * taken lies wholly outside every bigger one. */
static void take_level_blocks(tarn_grid_blocks *b, const uint32_t *level)
{
    const uint32_t cells_x = b->columns - 1, cells_z = b->rows - 1;
    uint8_t top = 1;
    while (2u * block_size(top) <= cells_x && 2u * block_size(top) <= cells_z) top++;
    for (uint8_t log2 = top; log2 >= 2; log2--) {
        const uint32_t size = block_size(log2);
        for (uint32_t j = 0; j + size <= cells_z; j += size) {
            for (uint32_t i = 0; i + size <= cells_x; i += size) {
                if (b->block_log2[j * cells_x + i] == 1 && block_is_level(b, level, i, j, size))
                    take_block(b, i, j, log2);
            }
        }
    }
}

static void mark_corners(tarn_grid_blocks *b)
{
    const uint32_t cells_x = b->columns - 1, cells_z = b->rows - 1;
    for (uint32_t j = 0; j < cells_z; j++) {
        for (uint32_t i = 0; i < cells_x; i++) {
            const uint8_t log2 = b->block_log2[j * cells_x + i];
            if (log2 == 0) continue;
            const uint32_t size = block_size(log2);
            b->corner[vertex_at(b, i, j)] = b->corner[vertex_at(b, i + size, j)] = 1;
            b->corner[vertex_at(b, i, j + size)] = b->corner[vertex_at(b, i + size, j + size)] = 1;
        }
    }
}

int tarn_grid_blocks_find(tarn_grid_blocks *b, uint32_t columns, uint32_t rows,
                          const uint32_t *level, const char *what, tarn_error *err)
{
    const size_t cells = (size_t)(columns - 1) * (rows - 1);
    b->columns = columns;
    b->rows = rows;
    b->block_log2 = malloc(cells + 1);
    b->corner = calloc((size_t)columns * rows, 1);
    b->ring = malloc(4u * sizeof *b->ring * (columns > rows ? columns : rows));
    if (!b->block_log2 || !b->corner || !b->ring) {
        tarn_grid_blocks_free(b);
        return tarn_fail(err, "%s: out of memory merging %u x %u vertices", what, columns, rows);
    }
    memset(b->block_log2, 1, cells);
    take_level_blocks(b, level);
    mark_corners(b);
    return 0;
}

static void put_triangle(uint16_t **out, uint32_t a, uint32_t b, uint32_t c)
{
    (*out)[0] = (uint16_t)a;
    (*out)[1] = (uint16_t)b;
    (*out)[2] = (uint16_t)c;
    *out += 3;
}

/* The corners on the border of the block at cell (i, j), walked +z, +x, -z, -x
 * from its first vertex: the grid's own turning sense. Returns how many. */
static uint32_t border_corners(const tarn_grid_blocks *b, uint32_t i, uint32_t j, uint32_t size,
                               uint32_t *ring)
{
    static const int step[4][2] = { { 0, 1 }, { 1, 0 }, { 0, -1 }, { -1, 0 } };
    uint32_t n = 0, x = i, y = j;
    for (int side = 0; side < 4; side++) {
        for (uint32_t k = 0; k < size; k++) {
            if (b->corner[vertex_at(b, x, y)]) ring[n++] = vertex_at(b, x, y);
            x = (uint32_t)((int32_t)x + step[side][0]);
            y = (uint32_t)((int32_t)y + step[side][1]);
        }
    }
    return n;
}

/* A block's fan around its centre vertex, or a single cell's two triangles. */
static uint32_t block_triangles(const tarn_grid_blocks *b, uint32_t i, uint32_t j, uint8_t block_log2,
                                uint16_t **out)
{
    const uint32_t size = block_size(block_log2);
    if (size == 1) {
        const uint32_t a = vertex_at(b, i, j), c = a + 1, below = a + b->columns, d = below + 1;
        put_triangle(out, a, below, c);
        put_triangle(out, c, below, d);
        return 2;
    }
    const uint32_t n = border_corners(b, i, j, size, b->ring);
    const uint32_t centre = vertex_at(b, i + size / 2, j + size / 2);
    for (uint32_t k = 0; k < n; k++) put_triangle(out, centre, b->ring[k], b->ring[(k + 1) % n]);
    return n;
}

uint32_t tarn_grid_blocks_triangles(const tarn_grid_blocks *b, uint16_t *indices)
{
    const uint32_t cells_x = b->columns - 1, cells_z = b->rows - 1;
    uint32_t count = 0;
    uint16_t *out = indices;
    for (uint32_t j = 0; j < cells_z; j++) {
        for (uint32_t i = 0; i < cells_x; i++) {
            const uint8_t log2 = b->block_log2[j * cells_x + i];
            if (log2 != 0) count += block_triangles(b, i, j, log2, &out);
        }
    }
    return count;
}

void tarn_grid_blocks_free(tarn_grid_blocks *b)
{
    free(b->block_log2);
    free(b->corner);
    free(b->ring);
    b->block_log2 = NULL;
    b->corner = NULL;
    b->ring = NULL;
}
