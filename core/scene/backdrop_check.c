/* backdrop_check.c: whether a scene's backdrop (tarn_scene.h) applies to a frame,
 * and whether it is well formed; once a frame, before any tile, so the firmware
 * compiles it for size. */
#include "scene/scene_internal.h"

/* The quality settings that shape the opaque pass's pixels. The others (tile size,
 * apron, bins, the water's own) change only the water or the cost. */
static int same_opaque_quality(const tarn_backdrop *b, const tarn_quality *q)
{
    return b->recip_newton_steps == q->recip_newton_steps && b->perspective == q->perspective &&
           b->perspective_span == q->perspective_span && b->depth_bits == q->depth_bits &&
           b->depth_interpolation == q->depth_interpolation;
}

/* And those that shape the water's still terms, without the underwater view,
 * which moves every pixel. Refraction's apron shapes no still term: its samples
 * are read from the picture as the clock moves them. Still water takes its texture
 * coordinates from its plane, and the quality must say so (TARN_WATER_UV_PLANE):
 * a yardstick's reference follows the quality. */
static int still_water_applies(const tarn_backdrop *b, const tarn_scene *scene, const tarn_frame_config *config)
{
    const tarn_quality *q = &config->quality;
    return TARN_LINK_STILL_WATER && b->water_block == q->water_block && b->fog_argument_bits == q->fog_argument_bits &&
           b->exp2_entries == q->exp2.entries && b->exp2_interpolate == q->exp2.interpolate &&
           q->water_coordinates == TARN_WATER_UV_PLANE && !tarn__underwater_active(scene);
}

const tarn_backdrop *tarn__backdrop_for(const tarn_scene *scene, const tarn_frame_config *config)
{
    if (!TARN_LINK_BACKDROP || !TARN_LINK_STATIC_VERTICES || scene == NULL || scene->static_view == NULL)
        return NULL;
    const tarn_backdrop *b = scene->static_view->backdrop;
    return b != NULL && tarn__static_screen_applies(scene, config) && same_opaque_quality(b, &config->quality) &&
                   (!b->still_water || still_water_applies(b, scene, config))
        ? b
        : NULL;
}

/* Each row's spans inside the frame, left to right and apart, their depth inside
 * the kept depth. */
static int spans_valid(const tarn_backdrop *b, uint16_t width, uint16_t height)
{
    if (b->row_spans[0] != 0u || b->row_spans[height] != b->span_count) return 0;
    for (uint32_t j = 0; j < height; j++) {
        if (b->row_spans[j] > b->row_spans[j + 1]) return 0;
        uint32_t end = 0;
        for (uint32_t k = b->row_spans[j]; k < b->row_spans[j + 1]; k++) {
            const tarn_backdrop_span *s = &b->spans[k];
            if (s->x0 < end || s->x0 >= s->x1 || s->x1 > width || s->first > b->depth_count ||
                (uint32_t)(s->x1 - s->x0) > b->depth_count - s->first)
                return 0;
            end = s->x1;
        }
    }
    return 1;
}

/* Whether a still-water mark names a water object of the scene, or none (0). */
static int names_water(const tarn_scene *scene, uint32_t mark)
{
    if (mark == 0u) return 1;
    const tarn_material *m = mark <= scene->object_count ? scene->objects[mark - 1u].material : NULL;
    return m != NULL && m->water != NULL;
}

/* Colours with nothing above 0xRRGGBB but a still-water backdrop's marks, each
 * object mark of a water object: the water pass marks the pixels it writes in the
 * bits above, and the frame walks the water objects' marks only. A still-water
 * palette ascends, so each mark is looked up where it changes only: checked every
 * frame, 16,384 colours cost the Cortex-M0 2 instructions a pixel so. */
static int palette_valid(const tarn_backdrop *b, const tarn_scene *scene)
{
    if (!TARN_LINK_STILL_WATER || !b->still_water) {
        for (uint32_t k = 0; k < b->palette_count; k++)
            if (b->palette[k] > 0xFFFFFFu) return 0;
        return 1;
    }
    uint32_t previous = 0u; /* mark 0 always names none */
    for (uint32_t k = 0; k < b->palette_count; k++) {
        const uint32_t colour = b->palette[k];
        if (colour < previous || (colour & TARN_WATER_MARK) != 0u) return 0;
        if ((colour ^ previous) & TARN_BACKDROP_STILL_OBJECT) {
            const uint32_t mark = (colour & TARN_BACKDROP_STILL_OBJECT) >> TARN_BACKDROP_STILL_SHIFT;
            if (!names_water(scene, mark)) return 0;
        }
        previous = colour;
    }
    return 1;
}

/* Each water object's plane, its shift within a word and its lit colour within
 * 255.0 a channel, as the water's products assume. */
static int planes_valid(const tarn_backdrop *b, const tarn_scene *scene)
{
    if (!TARN_LINK_STILL_WATER || !b->still_water) return 1;
    if (b->planes == NULL) return 0;
    for (uint32_t k = 0; k < scene->object_count; k++) {
        const tarn_still_plane *p = &b->planes[k];
        if (p->uv_shift > 31u || p->lit[0] > 65280u || p->lit[1] > 65280u || p->lit[2] > 65280u) return 0;
    }
    return 1;
}

/* A palette of 1 to 2^index_bits colours: a pixel's index past its end reads the
 * last (backdrop_read.c), so no index needs checking here, where checking them
 * would cost each frame as much again as reading them. */
int tarn__backdrop_valid(const tarn_backdrop *b, const tarn_scene *scene)
{
    if (b->palette == NULL || b->colour == NULL || b->row_spans == NULL || (b->span_count > 0u && b->spans == NULL) ||
        b->index_bits < 1u ||
        b->index_bits > 16u || b->palette_count < 1u || b->palette_count > (1u << b->index_bits) ||
        (b->depth_bits != 16 && b->depth_bits != 32) || (b->depth_count > 0u && b->depth == NULL) ||
        b->still_water > (TARN_LINK_STILL_WATER ? 1u : 0u))
        return 0;
    const tarn_static_view *view = scene->static_view;
    return palette_valid(b, scene) && planes_valid(b, scene) && spans_valid(b, view->width, view->height);
}

