/* frame_memory.h: the bytes of the renderer's working memory a firmware image
 * reserves, from the baked scene.h: the frame's, or on a board whose cores share a
 * ring of strips (FW_PIPELINE, board.mk's BOARD_CORE_SPLIT := pipeline) the strip
 * pipeline's, which holds more than the frame's: a frame the pipeline does not
 * draw, tarn_render_frame draws in the same memory. Shared by firmware/main.c and
 * firmware/display_main.c. */
#ifndef TARN_FIRMWARE_FRAME_MEMORY_H
#define TARN_FIRMWARE_FRAME_MEMORY_H

#include "scene.h"

#ifndef FW_PIPELINE
#define FW_PIPELINE 0
#endif

#if FW_PIPELINE
#define FW_MEMORY_BYTES SCENE_PIPELINE_MEMORY_BYTES
#else
#define FW_MEMORY_BYTES SCENE_MEMORY_BYTES
#endif

#endif
