/* underwater_internal.h: the underwater view of tarn_water.h (private to core/). After the
 * opaque and water passes, every pixel of the tile takes its colour from a point
 * displaced by a panning normal map, tinted by the water between it and the
 * camera. It reads the water pass's output around the tile (its apron). */
#ifndef TARN_UNDERWATER_INTERNAL_H
#define TARN_UNDERWATER_INTERNAL_H

#include "water/water_internal.h"

typedef struct {
    const tarn_underwater *under;
    tarn_linear_depth linear;
    tarn_exp2_config exp2;
    unsigned fog_argument_bits;
    uint32_t pan[2];             /* Q0.32 offsets of the normal map */
    uint32_t screen_u_per_half;  /* 2^32 / (2 * width): screen u of half a pixel, Q0.32 */
    uint32_t distortion_px;      /* distortion * width: pixels per unit normal, Q16.16 */
    const uint32_t *colour;      /* the water pass's colour and depth */
    const void *depth;
    uint8_t depth_bits;
    int32_t origin_x, origin_y, stride;
    int32_t offset_limit;        /* pixels a sample may move, each axis: the underwater apron */
    tarn_pixel_rect sample_rect; /* where displaced samples may land: the frame */
} tarn_underwater_context;

void tarn__underwater_setup(tarn_underwater_context *u, const tarn_view *view,
                           const tarn_frame_config *config, const tarn_underwater *under);

/* Writes the tile's pixels (rect) into `out` (index 0 = the rect's first pixel). */
void tarn__underwater_tile(const tarn_underwater_context *u, const tarn_pixel_rect *rect,
                          uint32_t *out, int32_t out_stride);

#endif
