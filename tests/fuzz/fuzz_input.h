/* fuzz_input.h: what the fuzz targets share: a scratch directory for the files a
 * loader reads (scene files go to its s/, beside links to scenes/assets that let them
 * name the demo's meshes and textures as the demo's scenes do), and a reader that
 * turns the fuzzer's bytes into numbers. Run the targets from the repository's root. */
#ifndef TARN_FUZZ_INPUT_H
#define TARN_FUZZ_INPUT_H

#include <stddef.h>
#include <stdint.h>

#include "error.h"

/* Writes `size` bytes to NAME in the scratch directory; returns its path. Aborts
 * when the scratch directory cannot be made (a broken machine, not a finding). */
const char *fuzz_write_file(const char *name, const uint8_t *data, size_t size);
/* The path NAME would have in the scratch directory. */
const char *fuzz_path(const char *name);

/* 1 when the error says what is wrong in one line, as every tarn error must. */
int fuzz_error_is_one_line(const tarn_error *err);

typedef struct {
    const uint8_t *data;
    size_t size, at;
} fuzz_reader;

/* The next bytes as an unsigned number, 0 once the input is used up. */
uint32_t fuzz_u32(fuzz_reader *r);
uint16_t fuzz_u16(fuzz_reader *r);
uint8_t fuzz_u8(fuzz_reader *r);

#endif
