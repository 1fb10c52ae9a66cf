/* still_backdrop.c: the still-water backdrop (backdrop.h, tarn_scene.h "Still
 * water"): the scene drawn with its water's still terms alone, each water pixel
 * marked with its object and where foam can show, the depth of water or the foam
 * band's places where they are shallow, and each water object's plane
 * (still_planes.h). */
#include "still_backdrop.h"
#include "backdrop_frames.h"
#include "tarn_internal.h"

#include <stdlib.h>
#include <string.h>

/* A copy of a scene's objects whose water objects draw with materials of their
 * own, which an edit changes. */
typedef struct {
    tarn_scene scene;
    tarn_object *objects;
    tarn_material *materials; /* per object; a water object's only */
    tarn_water *waters;
} water_edit;

typedef void (*water_change)(tarn_water *water, const void *arg);

static void water_edit_free(water_edit *e)
{
    free(e->objects);
    free(e->materials);
    free(e->waters);
    memset(e, 0, sizeof *e);
}

/* `scene` with each water object's material copied and its water changed. */
static int water_edit_make(const tarn_scene *scene, water_change change, const void *arg, water_edit *e,
                           tarn_error *err)
{
    const size_t count = scene->object_count > 0 ? scene->object_count : 1u;
    e->objects = malloc(count * sizeof *e->objects);
    e->materials = malloc(count * sizeof *e->materials);
    e->waters = malloc(count * sizeof *e->waters);
    if (e->objects == NULL || e->materials == NULL || e->waters == NULL) {
        water_edit_free(e);
        return tarn_fail(err, "backdrop: out of memory copying the water's materials");
    }
    e->scene = *scene;
    e->scene.objects = e->objects;
    for (uint32_t i = 0; i < scene->object_count; i++) {
        e->objects[i] = scene->objects[i];
        if (!tarn_object_is_water(&scene->objects[i])) continue;
        e->waters[i] = *scene->objects[i].material->water;
        change(&e->waters[i], arg);
        e->materials[i] = *scene->objects[i].material;
        e->materials[i].water = &e->waters[i];
        e->objects[i].material = &e->materials[i];
    }
    return 0;
}

/* Features cut to the uint32_t mask `arg`. */
static void keep_features(tarn_water *water, const void *arg)
{
    water->features &= *(const uint32_t *)arg;
}

/* The water object a still-water mark names: the mark-th of the scene's water
 * objects. */
static const tarn_object *water_object(const tarn_scene *scene, uint32_t mark)
{
    for (uint32_t k = 0; k < scene->object_count; k++)
        if (tarn_object_is_water(&scene->objects[k]) && --mark == 0u) return &scene->objects[k];
    return NULL;
}

/* The lit colour of water object `o` (Q8.8 a channel), as the core lights its
 * vertices: their mean, flat water being lit alike where its normals and colours
 * are. */
static void water_lit(const tarn_scene *scene, const tarn_frame_config *config, const tarn_object *o, uint16_t lit[3])
{
    tarn_view view;
    tarn__view_setup(scene, config, &view);
    view.static_vertices = 0; /* light the vertices, whether or not static ones apply */
    tarn_object_xform xform;
    tarn__object_xform_setup(&view, o, &xform);
    uint64_t sum[3] = {0, 0, 0};
    for (uint32_t v = 0; v < o->mesh->vertex_count; v++) {
        tarn_view_vertex vertex;
        tarn__vertex_shade(&view, &xform, o->mesh, (uint16_t)v, &vertex);
        for (int c = 0; c < 3; c++) sum[c] += vertex.lit[c];
    }
    const uint64_t count = o->mesh->vertex_count > 0u ? o->mesh->vertex_count : 1u;
    for (int c = 0; c < 3; c++) lit[c] = (uint16_t)((sum[c] + count / 2u) / count);
}

/* What keeps still water from applying, refused before anything is drawn; and
 * the water objects' planes. */
static int still_water_planes(const tarn_scene *scene, const tarn_frame_config *config, tarn_backdrop_image *b,
                              tarn_error *err)
{
    if (scene->underwater != NULL)
        return tarn_fail(err, "--backdrop still: the scene's underwater view moves every pixel with the clock; "
                              "use --backdrop on");
    uint32_t water_objects = 0;
    for (uint32_t i = 0; i < scene->object_count; i++) water_objects += (uint32_t)tarn_object_is_water(&scene->objects[i]);
    if (water_objects > TARN_BACKDROP_STILL_OBJECTS_MAX)
        return tarn_fail(err, "--backdrop still: the scene has %u water objects, at most %u can be told apart",
                         water_objects, TARN_BACKDROP_STILL_OBJECTS_MAX);
    b->planes = calloc(water_objects > 0 ? water_objects : 1u, sizeof *b->planes);
    if (b->planes == NULL) return tarn_fail(err, "backdrop: out of memory finding the water's planes");
    b->backdrop.planes = b->planes;
    if (tarn_still_planes_make(scene, config, b->planes, err) != 0) return -1;
    for (uint32_t mark = 1; mark <= water_objects; mark++)
        water_lit(scene, config, water_object(scene, mark), b->planes[mark - 1u].lit);
    return 0;
}

/* Marks each water pixel of `still` with its water object's number (1 + its index
 * among the water objects): the first whose frame over the opaque objects alone
 * leaves the still frame's depth there. */
static int mark_objects(const tarn_scene *scene, const tarn_frame_config *config, tarn_drawn_frame *still,
                        const uint8_t *water, tarn_error *err)
{
    const size_t pixels = (size_t)config->width * config->height;
    tarn_object *objects = malloc((scene->object_count > 0 ? scene->object_count : 1u) * sizeof *objects);
    uint8_t *marked = calloc(pixels, 1);
    int failed = objects == NULL || marked == NULL ? tarn_fail(err, "backdrop: out of memory marking the water") : 0;
    uint32_t number = 0;
    for (uint32_t i = 0; !failed && i < scene->object_count; i++) {
        if (!tarn_object_is_water(&scene->objects[i])) continue;
        number++;
        tarn_scene alone = tarn_scene_part(scene, 0, objects);
        objects[alone.object_count++] = scene->objects[i];
        tarn_drawn_frame f = {NULL, NULL, 0, 0};
        failed = tarn_backdrop_draw(&alone, config, &f, "marking the water", err);
        for (size_t k = 0; !failed && k < pixels; k++) {
            if (!water[k] || marked[k] || tarn_drawn_depth_differs(&f, still, k)) continue;
            marked[k] = 1;
            still->rgb[k] |= number << TARN_BACKDROP_STILL_SHIFT;
        }
        tarn_drawn_free(&f);
    }
    free(objects);
    free(marked);
    return failed;
}

/* The water objects of `scene` alone, as drawn with exact (32-bit) depth. */
static int draw_water_alone(const tarn_scene *scene, const tarn_frame_config *config, tarn_drawn_frame *surface,
                            tarn_error *err)
{
    tarn_frame_config exact = *config;
    exact.quality.depth_bits = 32;
    return tarn_backdrop_draw_part(scene, 1, &exact, surface, "finding the foam band", err);
}

/* near/d (Q1.30) at pixel k of a frame's depth. */
static uint32_t depth_q30(const tarn_drawn_frame *f, size_t k)
{
    if (f->depth_bytes == 2u) {
        uint16_t code;
        memcpy(&code, f->depth + 2u * k, sizeof code);
        return tarn_depth16_decode(code);
    }
    uint32_t q30;
    memcpy(&q30, f->depth + 4u * k, sizeof q30);
    return q30;
}

/* What the backdrop keeps at a water pixel over `diff` of water (Q16.16 world
 * units), for its object's context (tarn__still_keeps_depth), as Q16.16: the depth
 * of water, or the place in the foam band. */
static uint32_t kept_q16(const tarn_water_context *context, int refracts, uint32_t diff)
{
    return tarn__still_keeps_depth(context->water, refracts) ? diff : tarn__water_foam_band(context, diff);
}

/* A Q16.16 value kept as Q2.14 (TARN_BACKDROP_KEPT_SHIFT), rounded; 0xFFFF, which
 * marks the pixels between kept ones, where it holds none so large. */
static uint16_t kept_q2_14(uint32_t q16)
{
    const uint32_t half = 1u << (TARN_BACKDROP_KEPT_SHIFT - 1u);
    const uint32_t v = q16 < UINT32_MAX - half ? (q16 + half) >> TARN_BACKDROP_KEPT_SHIFT : 0xFFFFu;
    return (uint16_t)(v < 0xFFFFu ? v : 0xFFFFu);
}

/* Where a water pixel's refracted sample may land: within `radius` pixels (0 where
 * its water does not refract), behind `surface_q30`, its surface's near/d; and what
 * decides whether a sample landing on water lies within its foam band: its
 * surface's linear depth and its foam band's depth (0 without foam), and, as a
 * pixel landed on, its opaque surface's linear depth (Q16.16 each). */
typedef struct {
    uint32_t surface_q30;
    uint32_t surface, foam_distance, opaque;
    uint8_t radius;
} refracting_pixel;

/* How far a water pixel's refracted sample may move, in pixels, over `diff` of water
 * (Q16.16): its unit normal times the pixels a unit normal moves it, times its
 * reach saturate(diff), rounded, within the apron. */
static uint8_t refraction_radius(const tarn_water_context *context, uint32_t diff, int32_t apron)
{
    const uint64_t reach = diff < 65536u ? diff : 65536u;
    const uint64_t pixels = ((uint64_t)context->refraction_px * reach >> 32) + 1u;
    return (uint8_t)(pixels < (uint64_t)apron ? pixels : (uint64_t)apron);
}

/* At each water pixel, what the frame reads of the depth of water beneath it
 * (tarn__still_keeps_depth: the depth itself, or the place in the foam band, Q0.16),
 * found as the scene drawn whole finds it with a pixel's own effects, by the core's
 * own steps: from the opaque depth beneath and the water's own near/d. Where it is
 * kept, `kept` is 1; where foam can show (step 9's f < 1), the pixel's colour takes
 * TARN_BACKDROP_STILL_FOAM. `refracting` takes where each pixel's refracted sample may
 * land. */
static int find_kept_values(const tarn_scene *scene, const tarn_frame_config *config, const tarn_drawn_frame *opaque,
                            tarn_drawn_frame *still, const uint8_t *water, uint16_t *values, uint8_t *kept,
                            refracting_pixel *refracting, tarn_error *err)
{
    tarn_drawn_frame surface = {NULL, NULL, 0, 0};
    if (draw_water_alone(scene, config, &surface, err) != 0) return -1;
    tarn_view view;
    tarn__view_setup(scene, config, &view);
    tarn_water_context context;
    memset(&context, 0, sizeof context);
    const int32_t apron = tarn_frame_apron_pixels(scene, config);
    for (size_t k = 0; k < (size_t)config->width * config->height; k++) {
        values[k] = 0xFFFFu;
        kept[k] = 0;
        refracting[k].radius = 0u;
        if (!water[k]) continue;
        const tarn_object *object = water_object(scene, (still->rgb[k] & TARN_BACKDROP_STILL_OBJECT) >> TARN_BACKDROP_STILL_SHIFT);
        if (context.object != object) tarn__water_context_setup(&context, &view, config, object);
        const int refracts = apron > 0 && tarn__water_uses(&context, TARN_WATER_REFRACTION);
        const uint32_t below = tarn__water_linear_depth(depth_q30(opaque, k), &context.linear);
        const uint32_t at = tarn__water_linear_depth(depth_q30(&surface, k), &context.linear);
        const uint32_t diff = below > at ? below - at : 0u;
        const int foam = tarn__water_uses(&context, TARN_WATER_FOAM);
        const refracting_pixel pixel = {depth_q30(&surface, k), at,
                                        foam ? (uint32_t)object->material->water->foam_distance : 0u, below,
                                        refracts ? refraction_radius(&context, diff, apron) : 0u};
        refracting[k] = pixel;
        if (!foam && !refracts) continue;
        const uint32_t value = kept_q16(&context, refracts, diff);
        values[k] = kept_q2_14(value);
        if (value >= 65536u) continue; /* kept only where a sample lands (keep_landing) */
        kept[k] = 1;
        if (tarn__water_uses(&context, TARN_WATER_FOAM) && tarn__water_foam_band(&context, diff) < 65536u)
            still->rgb[k] |= TARN_BACKDROP_STILL_FOAM;
    }
    tarn_drawn_free(&surface);
    return 0;
}

/* What keeping the values where refracted samples land reads and writes. */
typedef struct {
    const tarn_drawn_frame *opaque;
    const uint8_t *water;
    const refracting_pixel *refracting;
    uint32_t landing_depth_q16;
    uint16_t *values;
    uint8_t *kept;
    int32_t width, height;
} landings;

/* Pixel k, where a sample from `from` may land. On the water it keeps its depth of
 * water (or place in the band), though it is a unit or more, where the backdrop can
 * hold it, under water less than the landing depth, and its opaque surface lies
 * within `from`'s foam band: seen from a farther surface a deep pixel's bed may lie
 * within the band. Beside the water it keeps its opaque near/d, as a tarn_depth16
 * code, where that lies no nearer than `from`'s water. */
static void keep_landing(const landings *l, const refracting_pixel *from, size_t k)
{
    if (l->kept[k]) return;
    if (l->water[k]) {
        const refracting_pixel *at = &l->refracting[k];
        l->kept[k] = (uint8_t)(from->foam_distance > 0u && l->values[k] < 0xFFFFu &&
                               at->opaque < (uint64_t)from->surface + from->foam_distance &&
                               at->opaque - at->surface < l->landing_depth_q16);
        return;
    }
    const uint32_t below = depth_q30(l->opaque, k);
    if (below > from->surface_q30) return;
    l->values[k] = tarn_depth16_encode(below);
    l->kept[k] = 1;
}

/* Where a refracted sample may land, within each refracting pixel's radius, the
 * backdrop keeps what the frame reads there (keep_landing): the frame tells a
 * depth of water from an opaque near/d by the pixel's colour, marked with a water
 * object or not. */
static void keep_where_samples_land(const landings *l)
{
    for (int32_t j = 0; j < l->height; j++)
        for (int32_t i = 0; i < l->width; i++) {
            const refracting_pixel *from = &l->refracting[(size_t)j * (size_t)l->width + (size_t)i];
            const int32_t r = from->radius;
            if (r == 0) continue; /* not a refracting pixel: no sample lands from it */
            for (int32_t y = j - r < 0 ? 0 : j - r; y <= j + r && y < l->height; y++)
                for (int32_t x = i - r < 0 ? 0 : i - r; x <= i + r && x < l->width; x++)
                    keep_landing(l, from, (size_t)y * (size_t)l->width + (size_t)x);
        }
}

/* The opaque frame, the still one with its water marked with its object, and
 * where the water draws (`water`). */
static int draw_still_frames(const tarn_scene *scene, const tarn_frame_config *config, tarn_drawn_frame *opaque,
                             tarn_drawn_frame *still, uint8_t *water, tarn_error *err)
{
    const uint32_t still_features = ~(uint32_t)(TARN_WATER_MOVING | TARN_WATER_REFRACTION);
    water_edit edit = {{0}, NULL, NULL, NULL};
    int failed = tarn_backdrop_draw_part(scene, 0, config, opaque, "drawing the opaque objects", err) ||
                 water_edit_make(scene, keep_features, &still_features, &edit, err) ||
                 tarn_backdrop_draw(&edit.scene, config, still, "drawing the still water", err);
    for (size_t k = 0; !failed && k < (size_t)config->width * config->height; k++)
        water[k] = tarn_drawn_depth_differs(still, opaque, k);
    failed = failed || mark_objects(&edit.scene, config, still, water, err);
    water_edit_free(&edit);
    return failed;
}

/* The still-water backdrop, and where the frame's water draws. */
int tarn_still_image_make(const tarn_scene *scene, const tarn_frame_config *config, uint32_t landing_depth_q16,
                          tarn_backdrop_image *b, uint8_t **water, tarn_error *err)
{
    if (still_water_planes(scene, config, b, err) != 0) return -1;
    tarn_backdrop_set_quality(&b->backdrop, &config->quality, 1);
    const size_t pixels = (size_t)config->width * config->height;
    *water = malloc(pixels);
    uint8_t *kept = malloc(pixels);
    uint16_t *values = malloc(pixels * sizeof *values);
    refracting_pixel *refracting = malloc(pixels * sizeof *refracting);
    tarn_drawn_frame opaque = {NULL, NULL, 0, 0}, still = {NULL, NULL, 0, 0};
    /* the values are kept as a frame's depth is */
    const tarn_drawn_frame kept_frame = {NULL, (uint8_t *)values, sizeof *values, config->width};
    int failed = *water == NULL || kept == NULL || values == NULL || refracting == NULL
        ? tarn_fail(err, "backdrop: out of memory drawing the still water")
        : draw_still_frames(scene, config, &opaque, &still, *water, err) ||
              find_kept_values(scene, config, &opaque, &still, *water, values, kept, refracting, err);
    const landings l = {&opaque, *water, refracting, landing_depth_q16, values, kept, config->width, config->height};
    if (!failed) keep_where_samples_land(&l);
    failed = failed || tarn_backdrop_index_colours(still.rgb, pixels, b, err) ||
             tarn_backdrop_keep_depth(&kept_frame, kept, config->height, b, err);
    tarn_drawn_free(&opaque);
    tarn_drawn_free(&still);
    free(kept);
    free(values);
    free(refracting);
    return failed;
}

