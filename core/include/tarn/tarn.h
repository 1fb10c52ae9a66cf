/* tarn.h: the whole public API of tarn, an integer-only renderer of small 3D
 * scenes with stylised water for microcontrollers, in one include.
 *
 *   tarn_version.h   TARN_VERSION_*, tarn_version()
 *   tarn_config.h    TARN_LINK_*: the parts compiled in
 *   tarn_fixed.h     the fixed-point formats (Q16.16, Q1.15, Q1.30, Q8.8) and helpers
 *   tarn_math.h      integer exp2, reciprocal, division, sine, square roots, with bounds
 *   tarn_scene.h     scene data: meshes, textures, materials, objects, camera, light
 *   tarn_water.h     water materials, step by step, and the underwater view
 *   tarn_render.h    drawing a frame a tile at a time: qualities, presets, memory
 *   tarn_panel.h     sending tiles to an SPI panel: RGB565, dither, bands
 *   tarn_checksum.h  the frame checksum the boards report
 *
 * Names with one underscore after tarn (tarn_render_frame) are the API; names with
 * two (tarn__view_setup) are the library's own, declared in core/'s *_internal.h
 * headers, and may change in any release.
 *
 * Copyright (c) 2026 the tarn authors. MIT licence: see LICENSE. */
#ifndef TARN_H
#define TARN_H

#include "tarn_version.h"
#include "tarn_config.h"
#include "tarn_fixed.h"
#include "tarn_math.h"
#include "tarn_scene.h"
#include "tarn_water.h"
#include "tarn_render.h"
#include "tarn_motion.h"
#include "tarn_panel.h"
#include "tarn_checksum.h"

#endif
