/* tarn_internal.h: the library's own stages, for the code of this repository that
 * works beside the core rather than through its API: the host tool's baker (which
 * runs the core's own vertex and water steps to store their results), the float
 * reference's snapped mode, and the tests that drive a single stage. It is not
 * installed and not part of the API (tarn.h): its names carry two underscores
 * after tarn and change without notice.
 *
 * Everything internal is reached through this one header, never a stage's own:
 * tests/check_layering.sh enforces it.
 *
 *   scene/     checks, presets, reach          scene/scene_internal.h
 *   geometry/  view, vertices, clipping,       geometry/geometry_internal.h,
 *              projection, vertex cache        geometry/vertex_cache_internal.h
 *   tile/      walk, cluster bins, backdrops   tile/tile_internal.h
 *   raster/    triangle setup, spans           raster/raster_internal.h
 *   water/     the water pixel, underwater     water/water_internal.h, water/underwater_internal.h
 *   frame/     memory layout, tile loop        frame/frame_internal.h
 *   math/      the tables behind tarn_math.h   math/math_tables_internal.h */
#ifndef TARN_INTERNAL_H
#define TARN_INTERNAL_H

#include "frame/frame_internal.h"
#include "geometry/vertex_cache_internal.h"
#include "math/math_tables_internal.h"

#endif
