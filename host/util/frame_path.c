/* frame_path.c: a sequence's frame files (frame_path.h). */
#include "frame_path.h"

#include <stdio.h>
#include <string.h>

int tarn_frame_path(const char *output, unsigned index, char *out, size_t size)
{
    size_t length = strlen(output);
    if (length >= 4 && strcmp(output + length - 4, ".png") == 0) length -= 4;
    int written = snprintf(out, size, "%.*s-%04u.png", (int)length, output, index);
    return written >= 0 && (size_t)written < size ? 0 : -1;
}
