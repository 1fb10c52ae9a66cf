/* status.c: what the library says of itself and of a frame's outcome. */
#include "tarn/tarn_render.h"
#include "tarn/tarn_version.h"

const char *tarn_version(void)
{
    return TARN_VERSION_STRING;
}

const char *tarn_status_text(tarn_status status)
{
    switch (status) {
    case TARN_OK: return "ok";
    case TARN_ERR_CONFIG: return "frame or quality setting out of range";
    case TARN_ERR_MEMORY: return "working memory smaller than tarn_frame_memory_bytes()";
    case TARN_ERR_SCENE: return "malformed scene data";
    case TARN_ERR_SINK: return "the tile sink stopped the frame";
    }
    return "unknown status";
}
