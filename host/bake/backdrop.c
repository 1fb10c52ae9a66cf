/* backdrop.c: see backdrop.h. */
#include "backdrop.h"
#include "backdrop_frames.h"
#include "still_backdrop.h"

#include <stdlib.h>
#include <string.h>

static int draw_opaque_frame(const tarn_scene *scene, const tarn_frame_config *config, tarn_drawn_frame *f,
                             tarn_error *err)
{
    return tarn_backdrop_draw_part(scene, 0, config, f, "drawing the opaque objects", err);
}

/* The frame's pixels where water draws: the depth the whole scene leaves there is
 * the water's, which a pixel takes only when it lies closer than the opaque one. */
static int find_water(const tarn_scene *scene, const tarn_frame_config *config, const tarn_drawn_frame *opaque,
                      uint8_t *water, tarn_error *err)
{
    tarn_drawn_frame whole = {NULL, NULL, 0, 0};
    const int failed = tarn_backdrop_draw(scene, config, &whole, "finding the water", err);
    for (size_t k = 0; !failed && k < (size_t)config->width * config->height; k++)
        water[k] = tarn_drawn_depth_differs(&whole, opaque, k);
    tarn_drawn_free(&whole);
    return failed;
}

/* Each row's pixels the water reads (1 in `kept`): from the first water pixel within
 * `reach` rows to the last, `reach` pixels wider on each side. */
static void rows_around_water(const uint8_t *water, int32_t width, int32_t height, int32_t reach, uint8_t *kept)
{
    for (int32_t j = 0; j < height; j++) {
        int32_t x0 = width, x1 = 0;
        for (int32_t y = j - reach < 0 ? 0 : j - reach; y <= j + reach && y < height; y++)
            for (int32_t i = 0; i < width; i++) {
                if (!water[(size_t)y * (size_t)width + (size_t)i]) continue;
                if (i < x0) x0 = i;
                if (i + 1 > x1) x1 = i + 1;
            }
        x0 = x0 - reach < 0 ? 0 : x0 - reach;
        x1 = x1 + reach > width ? width : x1 + reach;
        for (int32_t i = 0; i < width; i++) kept[(size_t)j * (size_t)width + (size_t)i] = i >= x0 && i < x1;
    }
}

/* The pixels whose depth the backdrop keeps (`kept`), and where the frame's water
 * draws (`*water`, width * height flags, or NULL under the underwater view, which
 * keeps every pixel's depth). */
static int find_kept_depth(const tarn_scene *scene, const tarn_frame_config *config, const tarn_drawn_frame *opaque,
                           uint8_t *kept, uint8_t **water, tarn_error *err)
{
    const size_t pixels = (size_t)config->width * config->height;
    *water = NULL;
    if (scene->underwater != NULL) { /* the underwater view displaces every pixel */
        memset(kept, 1, pixels);
        return 0;
    }
    *water = malloc(pixels);
    if (*water == NULL) return tarn_fail(err, "out of memory finding the backdrop's water");
    if (find_water(scene, config, opaque, *water, err) != 0) return -1;
    rows_around_water(*water, config->width, config->height, tarn_frame_apron_pixels(scene, config), kept);
    return 0;
}

static void image_free(tarn_backdrop_image *b)
{
    free(b->palette);
    free(b->colour);
    free(b->planes);
    free(b->row_spans);
    free(b->spans);
    free(b->depth);
    memset(b, 0, sizeof *b);
}

/* The backdrop of the opaque objects, and where the frame's water draws
 * (find_kept_depth). */
static int opaque_image_make(const tarn_scene *scene, const tarn_frame_config *config, tarn_backdrop_image *b,
                             uint8_t **water, tarn_error *err)
{
    tarn_backdrop_set_quality(&b->backdrop, &config->quality, 0);
    tarn_drawn_frame f = {NULL, NULL, 0, 0};
    uint8_t *kept = malloc((size_t)config->width * config->height);
    const int failed = kept == NULL ? tarn_fail(err, "out of memory finding the backdrop's water")
                                    : draw_opaque_frame(scene, config, &f, err) ||
                                          tarn_backdrop_index_colours(f.rgb, (size_t)config->width * config->height, b, err) ||
                                          find_kept_depth(scene, config, &f, kept, water, err) ||
                                          tarn_backdrop_keep_depth(&f, kept, config->height, b, err);
    tarn_drawn_free(&f);
    free(kept);
    return failed;
}

/* The backdrop of `kind`, and where the frame's water draws (NULL under the
 * underwater view). */
static int image_make(const tarn_scene *scene, const tarn_frame_config *config, tarn_backdrop_request request,
                      tarn_backdrop_image *b, uint8_t **water, tarn_error *err)
{
    *water = NULL;
    const int failed = request.kind == TARN_BACKDROP_STILL
                           ? tarn_still_image_make(scene, config, request.landing_depth_q16, b, water, err)
                           : opaque_image_make(scene, config, b, water, err);
    if (failed) {
        image_free(b);
        free(*water);
        *water = NULL;
    }
    return failed ? -1 : 0;
}

tarn_backdrop_request tarn_backdrop_of(tarn_backdrop_kind kind)
{
    const tarn_backdrop_request request = {kind, TARN_LANDING_DEPTH_MAX_Q16};
    return request;
}

int tarn_backdrop_scene_make(const tarn_scene *scene, const tarn_frame_config *config, tarn_backdrop_request request,
                             int keep_positions, tarn_backdrop_scene *out, tarn_error *err)
{
    memset(out, 0, sizeof *out);
    uint8_t *drawn = NULL;
    if (image_make(scene, config, request, &out->image, &drawn, err) != 0) return -1;
    out->water_objects = malloc((scene->object_count > 0 ? scene->object_count : 1u) * sizeof *out->water_objects);
    int failed = out->water_objects == NULL ? tarn_fail(err, "out of memory making the backdrop's scene") : 0;
    tarn_scene water;
    if (!failed) water = tarn_scene_part(scene, 1, out->water_objects);
    if (!failed && drawn != NULL)
        failed = tarn_water_cull_make(&water, out->water_objects, config, drawn, &out->cull, err);
    free(drawn);
    failed = failed || tarn_static_scene_make(&water, config, keep_positions, &out->water, err);
    if (failed) {
        tarn_backdrop_scene_free(out);
        return -1;
    }
    out->water.vertices.view.backdrop = &out->image.backdrop;
    return 0;
}

void tarn_backdrop_scene_free(tarn_backdrop_scene *s)
{
    image_free(&s->image);
    tarn_water_cull_free(&s->cull);
    free(s->water_objects);
    tarn_static_scene_free(&s->water);
    memset(s, 0, sizeof *s);
}
