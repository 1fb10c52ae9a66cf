/* firmware_conf.h: what a firmware build records for the tests that check it
 * (tests/test_firmware.c, tests/test_firmware_sweep.c, tests/test_real_boards.c): its files as text, the
 * KEY=VALUE lines of firmware.conf, and the frame config its bake flags make. */
#ifndef TARN_TESTS_FIRMWARE_CONF_H
#define TARN_TESTS_FIRMWARE_CONF_H

#include <stddef.h>
#include <stdint.h>
#include "backdrop.h"
#include "scene_load.h"
#include "tarn/tarn_render.h"

/* The whole file, NUL-terminated (NULL if it cannot be read); `size` (may be NULL)
 * gets its length. The caller frees it. */
char *firmware_read_file(const char *path, size_t *size);

/* KEY=VALUE's value among `text`'s lines into `out`, cut to `size`; "" if absent. */
void firmware_conf_value(char *out, size_t size, const char *text, const char *key);

/* The n board names in alphabetical order. */
void firmware_sort_board_names(char names[][64], size_t n);

/* The frame config `tarn bake SCENE BAKE_FLAGS` bakes: the scene's own size unless
 * the flags give one, the flags parsed as tarn parses them, at `time_ms`; and the
 * backdrop it bakes in `*backdrop`, unless NULL. Fails the test on flags tarn
 * refuses. */
tarn_frame_config firmware_bake_config(const char *scene_path, const char *bake_flags,
                                       const tarn_loaded_scene *scene, uint32_t time_ms,
                                       tarn_backdrop_request *backdrop);

#endif
