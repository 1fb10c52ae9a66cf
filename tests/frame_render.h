/* frame_render.h: one frame of a scene for the tests, as RGB bytes or as the
 * status the core returns. */
#ifndef TARN_TESTS_FRAME_RENDER_H
#define TARN_TESTS_FRAME_RENDER_H

#include <stdint.h>
#include "tarn/tarn_render.h"

/* Every demo and water scene, one-effect scenes that each stress a part of the
 * water, and the extremes: the scenes a test that two ways of drawing give the
 * same frame walks. */
extern const char *const test_frame_scenes[];
#define TEST_FRAME_SCENE_COUNT 21u

/* The frame as width * height * 3 bytes, R G B, which the caller frees; a render
 * that fails fails the test, naming `what`. */
uint8_t *test_render_rgb(const tarn_scene *scene, const tarn_frame_config *config, const char *what);

/* What tarn_render_frame returns for the frame, in exactly the memory it asks for,
 * the tiles dropped. */
tarn_status test_render_status(const tarn_scene *scene, const tarn_frame_config *config);

#endif
