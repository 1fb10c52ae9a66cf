/* texel_span.h: how many texels of a texture one triangle may span.
 *
 * The core interpolates a texture coordinate across a triangle in 30 bits, and the
 * perspective divide's error is a share of that (core/raster/triangle_setup.c): a
 * share of the texels the triangle spans. A plane under a camera looking across it
 * drew within the shading bars (exact 48 dB and 0.1% of pixels more than 2 levels
 * off, balanced 44 dB and 0.5%) with triangles across 4096 texels of its texture
 * or of a water map at its scale, and at 65,536 the balanced preset missed them
 * (one Newton step: a texel's edges move by 2^-18 of the span). A mesh whose
 * triangles span more is refused, naming the field that sets it: the object's
 * uv_scale (or mesh file), or a water map's scale when the mesh alone is within
 * the limit; scenes/extremes/uv-scale.json sits at it. */
#ifndef TARN_HOST_TEXEL_SPAN_H
#define TARN_HOST_TEXEL_SPAN_H

#include "scene_fields.h"
#include "tarn/tarn_scene.h"

#define TARN_TEXEL_SPAN_MAX 4096.0

/* 0, or -1 with "file: field: ..." set when a triangle of object `index` reaches
 * more than TARN_TEXEL_SPAN_MAX texels of a texture its material samples: `uv_field`
 * names what sets the mesh's coordinates ("objects[2].uv_scale"), and a water map's
 * own scale field is named for a map that its scale takes past the limit. */
int tarn_check_texel_spans(tarn_loader *l, const tarn_object *object, size_t index, const char *uv_field);

#endif
