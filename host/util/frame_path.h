/* frame_path.h: the file of one frame of a sequence (render --frames, view's
 * screenshots): "out.png" -> "out-0007.png", a name without ".png" gaining
 * "-0007.png". */
#ifndef TARN_HOST_FRAME_PATH_H
#define TARN_HOST_FRAME_PATH_H

#include <stddef.h>

/* 0, or -1 if the name does not fit `size` bytes. */
int tarn_frame_path(const char *output, unsigned index, char *out, size_t size);

#endif
