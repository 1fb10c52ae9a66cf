/* test_raster.c: coverage rules, watertightness, tile-size invariance and the
 * extremes of the integer rasterizer, checked against the float reference. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "compare.h"
#include "core_render.h"
#include "tarn_internal.h"
#include "reference.h"
#include "scene_builder.h"
#include "scene_load.h"

#define FRAME 64 /* the direct-raster tests draw into one 64x64 tile */

/* ---- drawing screen triangles straight into a tile, counting coverage -------- */

typedef struct {
    uint32_t colour[FRAME * FRAME];
    uint32_t depth[FRAME * FRAME];
    uint8_t count[FRAME * FRAME];
    tarn_quality quality;
    tarn_material material;
    tarn_mesh mesh;
    tarn_object object;
} coverage_counter;

static void counter_init(coverage_counter *c, unsigned subpixel_bits)
{
    memset(c, 0, sizeof *c);
    c->quality = tarn_quality_default();
    c->quality.subpixel_bits = (uint8_t)subpixel_bits;
    c->material.colour_rgb = 0xFFFFFF;
    c->material.cull = TARN_CULL_NONE;
    c->material.unlit = 1;
    c->object.mesh = &c->mesh;
    c->object.material = &c->material;
}

/* Draws one triangle alone into a cleared tile and adds its pixels to the count. */
static void counter_draw(coverage_counter *c, const tarn_screen_vertex v[3])
{
    tarn_tile_target tile = {.rect = {0, 0, FRAME, FRAME}, .colour = c->colour, .depth = c->depth,
                             .stride = FRAME, .quality = &c->quality};
    memset(c->colour, 0, sizeof c->colour);
    memset(c->depth, 0, sizeof c->depth);
    tarn__raster_triangle(&tile, v, &c->object);
    for (int i = 0; i < FRAME * FRAME; i++) c->count[i] += c->colour[i] != 0;
}

static tarn_screen_vertex screen_vertex(int32_t x, int32_t y)
{
    tarn_screen_vertex v;
    memset(&v, 0, sizeof v);
    v.x = x;
    v.y = y;
    v.inv_depth = 1u << 29;
    for (int c = 0; c < 3; c++) v.lit[c] = 65280;
    return v;
}

static uint32_t lcg(uint32_t *state)
{
    *state = *state * 1664525u + 1013904223u;
    return *state >> 8;
}

/* A grid of jittered vertices reaching past the tile: every pixel once. */
static void test_jittered_grid_covers_every_pixel_once(void **state)
{
    (void)state;
    coverage_counter *c = malloc(sizeof *c);
    counter_init(c, 4);
    enum { N = 12 };
    tarn_screen_vertex grid[N + 1][N + 1];
    uint32_t seed = 1;
    const int32_t cell = (FRAME + 16) * 16 / N; /* subpixels */
    for (int j = 0; j <= N; j++) {
        for (int i = 0; i <= N; i++) {
            int border = i == 0 || j == 0 || i == N || j == N;
            int32_t jx = border ? 0 : (int32_t)(lcg(&seed) % 61u) - 30;
            int32_t jy = border ? 0 : (int32_t)(lcg(&seed) % 61u) - 30;
            grid[j][i] = screen_vertex(-8 * 16 + i * cell + jx, -8 * 16 + j * cell + jy);
        }
    }
    for (int j = 0; j < N; j++) {
        for (int i = 0; i < N; i++) {
            const tarn_screen_vertex a[3] = {grid[j][i], grid[j][i + 1], grid[j + 1][i + 1]};
            const tarn_screen_vertex b[3] = {grid[j][i], grid[j + 1][i + 1], grid[j + 1][i]};
            counter_draw(c, a);
            counter_draw(c, b);
        }
    }
    for (int p = 0; p < FRAME * FRAME; p++) assert_int_equal(c->count[p], 1);
    free(c);
}

/* A fan of 20 triangles around a pixel centre, to grid-aligned points. */
static void test_fan_covers_disc_once(void **state)
{
    (void)state;
    coverage_counter *c = malloc(sizeof *c);
    counter_init(c, 4);
    static const int32_t ring[][2] = {
        {56, 32}, {55, 40}, {52, 46}, {48, 52}, {40, 55}, {32, 56}, {24, 55}, {16, 52},
        {12, 46}, {9, 40}, {8, 32}, {9, 24}, {12, 18}, {16, 12}, {24, 9}, {32, 8},
        {40, 9}, {48, 12}, {52, 18}, {55, 24}};
    const int n = (int)(sizeof ring / sizeof ring[0]);
    const tarn_screen_vertex centre = screen_vertex(32 * 16 + 8, 32 * 16 + 8); /* a pixel centre */
    for (int k = 0; k < n; k++) {
        const int *a = ring[k], *b = ring[(k + 1) % n];
        const tarn_screen_vertex tri[3] = {centre, screen_vertex(a[0] * 16, a[1] * 16),
                                           screen_vertex(b[0] * 16, b[1] * 16)};
        counter_draw(c, tri);
    }
    for (int p = 0; p < FRAME * FRAME; p++) assert_true(c->count[p] <= 1);
    for (int y = 14; y < 50; y++)
        for (int x = 14; x < 50; x++) assert_int_equal(c->count[y * FRAME + x], 1);
    free(c);
}

/* Triangles spanning the whole height but a fraction of a pixel wide. */
static void test_slivers_cover_strip_once(void **state)
{
    (void)state;
    coverage_counter *c = malloc(sizeof *c);
    counter_init(c, 8);
    /* top and bottom rows of points at irregular x; x in 1/256 pixel */
    int32_t top[80], bottom[80];
    uint32_t seed = 7;
    top[0] = bottom[0] = 4 * 256;
    for (int i = 1; i < 80; i++) {
        top[i] = top[i - 1] + 1 + (int32_t)(lcg(&seed) % 180u); /* stays below 60 px */
        bottom[i] = bottom[i - 1] + 1 + (int32_t)(lcg(&seed) % 180u);
    }
    top[79] = bottom[79] = 60 * 256;
    int i = 0, j = 0;
    while (i < 79 || j < 79) { /* zip the two rows into a strip of slivers */
        int advance_top = j == 79 || (i < 79 && top[i + 1] < bottom[j + 1]);
        tarn_screen_vertex tri[3] = {screen_vertex(top[i], 2 * 256), screen_vertex(bottom[j], 62 * 256),
                                     advance_top ? screen_vertex(top[i + 1], 2 * 256)
                                                 : screen_vertex(bottom[j + 1], 62 * 256)};
        counter_draw(c, tri);
        if (advance_top) i++; else j++;
    }
    for (int p = 0; p < FRAME * FRAME; p++) assert_true(c->count[p] <= 1);
    for (int y = 2; y < 62; y++)
        for (int x = 4; x < 60; x++) assert_int_equal(c->count[y * FRAME + x], 1);
    free(c);
}

/* Pixel centres exactly on edges: a 4x4-pixel square from two triangles, corners
 * on pixel centres, covers exactly the top-left-owned 4x4 block. */
static void test_top_left_rule_on_pixel_centres(void **state)
{
    (void)state;
    coverage_counter *c = malloc(sizeof *c);
    counter_init(c, 4);
    const int32_t x0 = 10 * 16 + 8, y0 = 20 * 16 + 8, x1 = 14 * 16 + 8, y1 = 24 * 16 + 8;
    const tarn_screen_vertex a[3] = {screen_vertex(x0, y0), screen_vertex(x1, y0), screen_vertex(x1, y1)};
    const tarn_screen_vertex b[3] = {screen_vertex(x0, y0), screen_vertex(x1, y1), screen_vertex(x0, y1)};
    counter_draw(c, a);
    counter_draw(c, b);
    for (int y = 0; y < FRAME; y++)
        for (int x = 0; x < FRAME; x++) {
            int inside = x >= 10 && x < 14 && y >= 20 && y < 24; /* top and left edges only */
            assert_int_equal(c->count[y * FRAME + x], inside);
        }
    free(c);
}

/* ---- whole frames through the pipeline ------------------------------------- */

typedef struct {
    uint8_t *rgb, *covered;
} frame_buffers;

static frame_buffers frame_new(int w, int h)
{
    frame_buffers f = {malloc((size_t)w * h * 3), malloc((size_t)w * h)};
    assert_non_null(f.rgb);
    assert_non_null(f.covered);
    return f;
}

static void frame_free(frame_buffers *f)
{
    free(f->rgb);
    free(f->covered);
}

static tarn_frame_config config_of(int w, int h)
{
    tarn_frame_config config = {(uint16_t)w, (uint16_t)h, tarn_quality_default(), 0};
    return config;
}

static void render_core(const tarn_scene *scene, const tarn_frame_config *config, frame_buffers *f)
{
    tarn_error err;
    int rc = tarn_core_render(scene, config, f->rgb, f->covered, &err);
    if (rc != 0) fail_msg("core render: %s", err.message);
}

static long drawn_pixels; /* pixels the core drew in the last compare_snapped */

/* The core's coverage must equal the reference's on the core's own triangles:
 * no pixel outside its triangle, none missing. Returns the comparison. */
static tarn_compare_metrics compare_snapped(const tarn_scene *scene, const tarn_frame_config *config)
{
    frame_buffers core = frame_new(config->width, config->height);
    frame_buffers ref = frame_new(config->width, config->height);
    render_core(scene, config, &core);
    tarn_reference_options options = {.geometry = TARN_REF_CORE_TRIANGLES, .subpixel_bits = config->quality.subpixel_bits};
    assert_int_equal(tarn_reference_render(scene, config->width, config->height, &options, ref.rgb,
                                           ref.covered), 0);
    tarn_compare_metrics m;
    tarn_compare_images(core.rgb, ref.rgb, core.covered, ref.covered, config->width, config->height, &m);
    drawn_pixels = 0;
    for (int p = 0; p < config->width * config->height; p++) drawn_pixels += core.covered[p];
    frame_free(&core);
    frame_free(&ref);
    return m;
}

typedef struct {
    coverage_counter *counter;
    int32_t offset_x, offset_y; /* the 64x64 window of the frame being counted */
} visit_counter;

static void count_visited(void *user, const tarn_screen_vertex v[3], const tarn_object *object)
{
    (void)object;
    visit_counter *vc = user;
    tarn_screen_vertex shifted[3];
    for (int k = 0; k < 3; k++) {
        shifted[k] = v[k];
        shifted[k].x -= vc->offset_x << 4;
        shifted[k].y -= vc->offset_y << 4;
    }
    counter_draw(vc->counter, shifted);
}

/* A wall of 2,000 triangles filling the view, and a floor crossing the near plane
 * (its clipped fans must share the cut edges): no pixel twice, the wall no holes. */
static void test_clipped_meshes_stay_watertight(void **state)
{
    (void)state;
    scene_builder *b = malloc(sizeof *b);
    builder_init(b, 0, 1, 0, 0, 0.7, -10);
    builder_begin_object(b, 0x808080, TARN_CULL_NONE);
    builder_grid(b, 0, 0, -4, 60, 40, 40, 25); /* wall at z = -4 */
    coverage_counter *c = malloc(sizeof *c);
    counter_init(c, 4);
    tarn_frame_config config = config_of(FRAME, FRAME);
    visit_counter vc = {c, 0, 0};
    assert_int_equal(tarn_visit_screen_triangles(&b->scene, &config, count_visited, &vc), TARN_OK);
    for (int p = 0; p < FRAME * FRAME; p++) assert_int_equal(c->count[p], 1);

    /* floor: y = 0 plane from z = +5 (behind the camera) to z = -30, tilted view */
    builder_init(b, 0, 1, 0, 0, 0.2, -10);
    builder_begin_object(b, 0x808080, TARN_CULL_NONE);
    uint16_t first = (uint16_t)b->vertex_count;
    for (int j = 0; j <= 20; j++)
        for (int i = 0; i <= 20; i++) builder_vertex(b, -20 + 2.0 * i, 0, 5 - 1.75 * j);
    for (int j = 0; j < 20; j++)
        for (int i = 0; i < 20; i++) {
            uint16_t v00 = (uint16_t)(first + j * 21 + i);
            builder_triangle(b, v00, (uint16_t)(v00 + 1), (uint16_t)(v00 + 22));
            builder_triangle(b, v00, (uint16_t)(v00 + 22), (uint16_t)(v00 + 21));
        }
    counter_init(c, 4);
    assert_int_equal(tarn_visit_screen_triangles(&b->scene, &config, count_visited, &vc), TARN_OK);
    int covered = 0;
    for (int p = 0; p < FRAME * FRAME; p++) {
        assert_true(c->count[p] <= 1);
        covered += c->count[p];
    }
    assert_true(covered > FRAME * FRAME / 3); /* the floor fills the lower part */
    for (int x = 0; x < FRAME; x++) assert_int_equal(c->count[(FRAME - 1) * FRAME + x], 1);
    free(c);
    free(b);
}

/* ---- tile size and the pond ----------------------------------------------------*/

static tarn_loaded_scene *load_pond(void)
{
    tarn_loaded_scene *s = malloc(sizeof *s);
    tarn_error err;
    if (tarn_scene_load("scenes/pond.json", s, &err) != 0) fail_msg("%s", err.message);
    return s;
}

static void unload(tarn_loaded_scene *s)
{
    tarn_scene_free(s);
    free(s);
}

static void test_tile_size_does_not_change_the_image(void **state)
{
    (void)state;
    tarn_loaded_scene *pond = load_pond();
    static const uint8_t perspective[][2] = {
        {TARN_PERSPECTIVE_PIXEL, 16}, {TARN_PERSPECTIVE_SPAN, 16}, {TARN_PERSPECTIVE_AFFINE, 16}};
    static const uint8_t tiles[] = {8, 13, 16, 32, 64};
    for (size_t m = 0; m < sizeof perspective / sizeof perspective[0]; m++) {
        tarn_frame_config config = config_of(160, 120);
        config.quality.perspective = perspective[m][0];
        config.quality.perspective_span = perspective[m][1];
        config.quality.depth_bits = m == 2 ? 16 : 32;
        frame_buffers first = frame_new(160, 120), other = frame_new(160, 120);
        config.quality.tile_size = tiles[0];
        render_core(&pond->scene, &config, &first);
        for (size_t t = 1; t < sizeof tiles; t++) {
            config.quality.tile_size = tiles[t];
            render_core(&pond->scene, &config, &other);
            assert_memory_equal(first.rgb, other.rgb, 160 * 120 * 3);
        }
        frame_free(&first);
        frame_free(&other);
    }
    unload(pond);
}

/* Renders the scene with and without cluster bins, at two tile sizes; the four
 * images must be the same, and bins must cost 4 bytes a cluster. */
static void assert_bins_change_nothing(const tarn_loaded_scene *loaded, const tarn_scene *scene)
{
    tarn_frame_config config = config_of(160, 120);
    frame_buffers first = frame_new(160, 120), other = frame_new(160, 120);
    render_core(scene, &config, &first);
    uint32_t clusters = 0;
    for (size_t i = 0; i < loaded->object_count; i++)
        clusters += loaded->meshes[i].mesh.clusters ? loaded->meshes[i].mesh.cluster_count : 1u;
    static const uint8_t tiles[] = {16, 32};
    for (size_t t = 0; t < sizeof tiles; t++)
        for (uint8_t bins = 0; bins <= 1; bins++) {
            config.quality.tile_size = tiles[t];
            config.quality.cluster_bins = bins;
            render_core(scene, &config, &other);
            assert_memory_equal(first.rgb, other.rgb, 160 * 120 * 3);
        }
    const size_t with_bins = tarn_frame_memory_bytes(&config, scene);
    config.quality.cluster_bins = 0;
    assert_int_equal(with_bins - tarn_frame_memory_bytes(&config, scene), 4u * clusters);
    frame_free(&first);
    frame_free(&other);
}

static void test_cluster_bins_do_not_change_the_image(void **state)
{
    (void)state;
    static const char *const scenes[] = {"scenes/pond.json", "scenes/beach.json", "scenes/lake.json",
                                         "scenes/underwater.json"};
    tarn_loaded_scene *s = malloc(sizeof *s);
    tarn_error err;
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        if (tarn_scene_load(scenes[i], s, &err) != 0) fail_msg("%s", err.message);
        assert_bins_change_nothing(s, &s->scene);
        /* level with the ground, the near plane cuts the clusters under the camera:
         * their bins fall back on spheres */
        tarn_scene low = s->scene;
        low.camera.position.y = low.camera.target.y = s->objects[0].position.y + TARN_Q16_ONE / 2;
        low.camera.position.z = TARN_Q16_ONE * 8;
        low.camera.target.z = 0;
        assert_bins_change_nothing(s, &low);
        tarn_scene_free(s);
    }
    free(s);
}

/* The opaque pond (its water drawn as an ordinary surface): rasterization and
 * shading alone against the reference. */
static void test_pond_matches_snapped_reference(void **state)
{
    (void)state;
    tarn_loaded_scene *pond = load_pond();
    for (size_t m = 0; m < pond->material_count; m++) pond->materials[m].water = NULL;
    tarn_frame_config config = config_of(240, 240);
    tarn_compare_metrics m = compare_snapped(&pond->scene, &config);
    print_message("opaque pond, snapped: %.2f dB, max error %d, %ld coverage mismatches\n", m.psnr_db,
                  m.max_channel_error, m.coverage_mismatches);
    assert_int_equal(m.coverage_mismatches, 0);
    assert_true(m.psnr_db >= 50.0);
    assert_true(m.max_channel_error <= 2);
    unload(pond);
}

/* Unsnapped, the reference places vertices by its own double arithmetic, so a
 * coverage difference may only appear where a triangle edge passes close by. */
typedef struct {
    double (*edges)[4];
    size_t count, capacity;
    unsigned subpixel_bits;
} edge_list;

static void collect_edges(void *user, const tarn_screen_vertex v[3], const tarn_object *object)
{
    (void)object;
    edge_list *list = user;
    const double unit = (double)(1u << list->subpixel_bits);
    for (int k = 0; k < 3; k++) {
        if (list->count == list->capacity) {
            list->capacity = list->capacity ? 2 * list->capacity : 1024;
            list->edges = realloc(list->edges, list->capacity * sizeof *list->edges);
            assert_non_null(list->edges);
        }
        const tarn_screen_vertex *a = &v[k], *b = &v[(k + 1) % 3];
        double *e = list->edges[list->count++];
        e[0] = a->x / unit; e[1] = a->y / unit; e[2] = b->x / unit; e[3] = b->y / unit;
    }
}

static double distance_to_segment(const double e[4], double px, double py)
{
    double dx = e[2] - e[0], dy = e[3] - e[1], length2 = dx * dx + dy * dy;
    double t = length2 > 0 ? ((px - e[0]) * dx + (py - e[1]) * dy) / length2 : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    double ex = e[0] + t * dx - px, ey = e[1] + t * dy - py;
    return ex * ex + ey * ey;
}

static void test_unsnapped_mismatches_lie_on_edges(void **state)
{
    (void)state;
    tarn_loaded_scene *pond = load_pond();
    tarn_frame_config config = config_of(240, 240);
    frame_buffers core = frame_new(240, 240), ref = frame_new(240, 240);
    render_core(&pond->scene, &config, &core);
    tarn_reference_options options = {.geometry = TARN_REF_CONTINUOUS, .subpixel_bits = config.quality.subpixel_bits};
    assert_int_equal(tarn_reference_render(&pond->scene, 240, 240, &options, ref.rgb, ref.covered), 0);
    edge_list edges = {NULL, 0, 0, config.quality.subpixel_bits};
    assert_int_equal(tarn_visit_screen_triangles(&pond->scene, &config, collect_edges, &edges), TARN_OK);
    for (int p = 0; p < 240 * 240; p++) {
        if (core.covered[p] == ref.covered[p]) continue;
        double px = p % 240 + 0.5, py = p / 240 + 0.5;
        int near_edge = 0;
        for (size_t e = 0; e < edges.count && !near_edge; e++)
            near_edge = distance_to_segment(edges.edges[e], px, py) <= 1.0;
        assert_true(near_edge);
    }
    free(edges.edges);
    frame_free(&core);
    frame_free(&ref);
    unload(pond);
}

/* ---- extremes ---------------------------------------------------------------- */

/* Renders the builder's scene and checks coverage against the snapped reference. */
static void assert_exact_coverage(scene_builder *b, int w, int h)
{
    tarn_frame_config config = config_of(w, h);
    tarn_compare_metrics m = compare_snapped(&b->scene, &config);
    assert_int_equal(m.coverage_mismatches, 0);
}

static void one_triangle(scene_builder *b, const double p[3][3])
{
    builder_begin_object(b, 0xC08040, TARN_CULL_NONE);
    uint16_t a = builder_vertex(b, p[0][0], p[0][1], p[0][2]);
    uint16_t c = builder_vertex(b, p[1][0], p[1][1], p[1][2]);
    uint16_t d = builder_vertex(b, p[2][0], p[2][1], p[2][2]);
    builder_triangle(b, a, c, d);
}

static void test_extreme_triangles(void **state)
{
    (void)state;
    static const double cases[][3][3] = {
        {{-30000, -30000, -5}, {30000, -30000, -5}, {0, 30000, -5}},  /* far larger than the screen */
        {{-1, -1, 3}, {1, -1, -3}, {0, 1, -3}},                       /* crosses the near plane */
        {{-1, -1, 30}, {1, -0.5, -2}, {0, 1, -2}},                    /* one vertex well behind */
        {{-1, 0, -2}, {0, 0, -2}, {1, 0, -2}},                        /* collinear: no area */
        {{0.3, 0.3, -2}, {0.3, 0.3, -2}, {0.3, 0.3, -2}},             /* a single point */
        {{-1, -1, -2}, {1, 1, -2}, {1.0001, 1.0002, -2}},             /* sliver */
        {{-500, -1, -999.9}, {500, -1, -999.9}, {0, 500, -999.9}},    /* at the far plane */
        {{-500, -1, -1200}, {500, -1, -1200}, {0, 500, -1200}},       /* beyond it */
        {{-32767, -32767, -32767}, {32767, -32767, -32767}, {0, 32767, 32767}}, /* Q16.16 limits */
        {{-1e-4, 0, -0.1}, {1e-4, 0, -0.1}, {0, 1e-4, -0.1}},         /* tiny, at the near plane */
    };
    static const int sizes[][2] = {{64, 48}, {1, 1}, {1024, 1024}};
    scene_builder *b = malloc(sizeof *b);
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
            builder_init(b, 0, 0, 0, 0, 0, -1);
            one_triangle(b, cases[c]);
            assert_exact_coverage(b, sizes[s][0], sizes[s][1]);
        }
    }
    free(b);
}

/* A coordinate from a scale chosen at random: a hair, a room, a valley, the limit. */
static double random_coordinate(uint32_t *seed)
{
    static const double scales[] = {1e-3, 1, 40, 2000, 32000};
    double scale = scales[lcg(seed) % 5u];
    return ((double)(lcg(seed) % 20001u) / 10000.0 - 1.0) * scale;
}

/* 300 random triangles around and behind a random camera, in random frame sizes
 * and subpixel precisions: every one covers exactly the pixels the reference says. */
static void test_random_triangles_cover_exactly(void **state)
{
    (void)state;
    scene_builder *b = malloc(sizeof *b);
    uint32_t seed = 12345;
    int visible = 0;
    for (int n = 0; n < 300; n++) {
        double p[3][3];
        for (int k = 0; k < 3; k++)
            for (int a = 0; a < 3; a++) p[k][a] = random_coordinate(&seed);
        builder_init(b, 0, 0, 0, random_coordinate(&seed), random_coordinate(&seed), -1 - (double)(lcg(&seed) % 100u));
        one_triangle(b, p);
        const int w = 1 + (int)(lcg(&seed) % 80u), h = 1 + (int)(lcg(&seed) % 60u);
        tarn_frame_config config = config_of(w, h);
        config.quality.subpixel_bits = (uint8_t)(1 + lcg(&seed) % 8u);
        if (tarn_frame_memory_bytes(&config, NULL) == 0) config.quality.subpixel_bits = 4;
        tarn_compare_metrics m = compare_snapped(&b->scene, &config);
        if (m.coverage_mismatches != 0) fail_msg("triangle %d: %ld pixels differ", n, m.coverage_mismatches);
        visible += drawn_pixels > 0;
    }
    print_message("%d of 300 random triangles drew pixels\n", visible);
    assert_true(visible >= 60); /* the sweep must exercise drawing, not only rejection */
    free(b);
}

/* Cameras at the limits: far away, straight down, straight up, inside geometry. */
static void test_extreme_cameras(void **state)
{
    (void)state;
    static const double cameras[][6] = {
        {0, 30000, 0, 0, 0, 0},          /* straight down from far away */
        {0, -5, 0, 0, 5, 0},             /* straight up */
        {32000, 32000, 32000, -32000, -32000, -32000},
        {0, 0, -4, 0, 0, -4.0001},       /* a hair from the target */
        {0, 0, 0, 1.0 / 65536, 0, -1.0 / 65536}, /* a hair away, off every axis */
    };
    scene_builder *b = malloc(sizeof *b);
    for (size_t c = 0; c < sizeof cameras / sizeof cameras[0]; c++) {
        const double *e = cameras[c];
        builder_init(b, e[0], e[1], e[2], e[3], e[4], e[5]);
        builder_begin_object(b, 0x4080C0, TARN_CULL_NONE);
        builder_grid(b, 0, 0, -4, 40, 40, 8, 8);
        assert_exact_coverage(b, 96, 64);
    }
    free(b);
}

/* One plane tessellated twice, 23x19 and 21x17, red first. Tilted, the two surfaces
 * differ only by vertex rounding and interleave finely; facing the camera, every
 * pixel is an exact tie and the earlier (red) must win. Unlit flat colours, so a
 * wrong winner shows as a full-intensity error against the reference. */
static void plane_grid(scene_builder *b, uint32_t colour, int n, int m, double tilt)
{
    builder_begin_object(b, colour, TARN_CULL_NONE);
    uint16_t first = (uint16_t)b->vertex_count;
    for (int j = 0; j <= m; j++)
        for (int i = 0; i <= n; i++) {
            double y = -4 + 8.0 * j / m;
            builder_vertex(b, -4 + 8.0 * i / n, y, -6 - tilt * y);
        }
    for (int j = 0; j < m; j++)
        for (int i = 0; i < n; i++) {
            uint16_t v00 = (uint16_t)(first + j * (n + 1) + i);
            builder_triangle(b, v00, (uint16_t)(v00 + 1), (uint16_t)(v00 + n + 2));
            builder_triangle(b, v00, (uint16_t)(v00 + n + 2), (uint16_t)(v00 + n + 1));
        }
}

static void test_depth_ties_resolve_like_the_reference(void **state)
{
    (void)state;
    static const double tilts[] = {0.3, 0.0};
    scene_builder *b = malloc(sizeof *b);
    tarn_frame_config config = config_of(200, 150);
    for (size_t t = 0; t < 2; t++) {
        builder_init(b, 0, 0, 0, 0, 0, -1);
        plane_grid(b, 0xFF0000, 23, 19, tilts[t]);
        plane_grid(b, 0x00FF00, 21, 17, tilts[t]);
        tarn_compare_metrics m = compare_snapped(&b->scene, &config);
        assert_int_equal(m.coverage_mismatches, 0);
        assert_int_equal(m.max_channel_error, 0);
    }
    frame_buffers f = frame_new(200, 150); /* the exact tie: red everywhere it drew */
    render_core(&b->scene, &config, &f);
    for (int p = 0; p < 200 * 150; p++) assert_true(!f.covered[p] || f.rgb[3 * p + 1] == 0);
    frame_free(&f);
    free(b);
}

/* Plane depth (TARN_DEPTH_PLANE) lands within a few units of 2^-30 of exact depth
 * at every pixel of random triangles: it covers the same pixels, and what it gives
 * up is only the exact tie where two surfaces meet. */
/* A counter on the heap (it holds two tiles) at 4 subpixel bits. */
static coverage_counter *counter_new(void)
{
    coverage_counter *c = malloc(sizeof *c);
    assert_non_null(c);
    counter_init(c, 4);
    return c;
}

/* A vertex anywhere in and around the 64-pixel tile, at any depth. */
static tarn_screen_vertex random_screen_vertex(uint32_t *seed)
{
    tarn_screen_vertex v = screen_vertex((int32_t)(lcg(seed) % (96u * 16u)) - 16 * 16,
                                         (int32_t)(lcg(seed) % (96u * 16u)) - 16 * 16);
    v.inv_depth = 1u + lcg(seed) % (1u << 24) * 64u; /* up to 2^30 */
    return v;
}

static void test_plane_depth_follows_exact_depth(void **state)
{
    (void)state;
    coverage_counter *exact = counter_new(), *plane = counter_new();
    plane->quality.depth_interpolation = TARN_DEPTH_PLANE;
    uint32_t seed = 2024, worst = 0;
    long drawn = 0;
    for (int n = 0; n < 2000; n++) {
        tarn_screen_vertex v[3];
        for (int k = 0; k < 3; k++) {
            v[k] = random_screen_vertex(&seed);
        }
        counter_draw(exact, v);
        counter_draw(plane, v);
        for (int p = 0; p < FRAME * FRAME; p++) {
            assert_int_equal(exact->colour[p] != 0, plane->colour[p] != 0);
            if (exact->colour[p] == 0) continue;
            const uint32_t a = exact->depth[p], b = plane->depth[p], apart = a > b ? a - b : b - a;
            if (apart > worst) worst = apart;
            drawn++;
        }
    }
    print_message("plane depth: %ld pixels, at most %u units of 2^-30 from exact\n", drawn, (unsigned)worst);
    assert_true(drawn > 100000);
    /* each step is rounded (and the division short by up to one unit), and a pixel
     * lies up to 192 steps from the triangle's first: under 2^7 units, where the
     * 16-bit depth buffer's step is 2^-12 of the value */
    assert_true(worst <= 128u);
    free(exact);
    free(plane);
}

/* A vertex lit as one light over an uncoloured mesh lights it: ambient plus light
 * times `diffuse` (0..1 as 0..65536) a channel, rounded to Q8.8 as the vertex
 * stage rounds it. */
static void light_vertex(tarn_screen_vertex *v, uint32_t diffuse)
{
    static const uint32_t ambient[3] = {16448, 18504, 20560}, light[3] = {40000, 38000, 30000}; /* Q8.8 */
    for (int c = 0; c < 3; c++) v->lit[c] = (uint16_t)(ambient[c] + ((light[c] * diffuse + 32768u) >> 16));
}

/* What the setup makes of three lit vertices, at a perspective and a lit knob. */
static tarn_attribute_set setup_lit(const tarn_screen_vertex v[3], uint8_t perspective, int lit_line)
{
    tarn_triangle_setup t;
    assert_true(tarn__orient_triangle(v, TARN_CULL_NONE, 4, &t));
    t.box = tarn__triangle_pixels(&t);
    const tarn_attribute_request request = {NULL, 0, 0, lit_line};
    tarn_attribute_set set;
    tarn__setup_attributes(&t, &request, perspective, TARN_DEPTH_PLANE, &set);
    return set;
}

/* A lit colour on a line takes one plane, of the channel that changes most, and
 * only in per-pixel perspective with the knob at line; colours off the line, or
 * a saturated vertex, keep a plane each. */
static void test_lit_line_where_colours_lie_on_one(void **state)
{
    (void)state;
    tarn_screen_vertex v[3] = {screen_vertex(0, 0), screen_vertex(40 * 16, 0), screen_vertex(0, 40 * 16)};
    light_vertex(&v[0], 0);
    light_vertex(&v[1], 30000);
    light_vertex(&v[2], 65536);
    tarn_attribute_set set = setup_lit(v, TARN_PERSPECTIVE_PIXEL, 1);
    assert_int_equal(set.first_varying, 2);
    assert_int_equal(set.t_min[2] >> set.t_shift[2], v[0].lit[0]); /* red changes most */
    assert_int_equal(set.t_max[2] >> set.t_shift[2], v[2].lit[0]);
    assert_int_equal(setup_lit(v, TARN_PERSPECTIVE_PIXEL, 0).first_varying, 0);
    assert_int_equal(setup_lit(v, TARN_PERSPECTIVE_SPAN, 1).first_varying, 0);
    v[1].lit[2] += TARN_LIT_LINE_TOLERANCE + 2; /* off the line */
    assert_int_equal(setup_lit(v, TARN_PERSPECTIVE_PIXEL, 1).first_varying, 0);
    light_vertex(&v[1], 30000);
    for (int c = 0; c < 3; c++) v[2].lit[c] = 65280; /* saturated: white, not on the line */
    assert_int_equal(setup_lit(v, TARN_PERSPECTIVE_PIXEL, 1).first_varying, 0);
}

/* Lit vertices a rounding step from the line are on it (within
 * TARN_LIT_LINE_TOLERANCE), but the line's far end must not leave 0..255.0, where a
 * pixel would have to clamp it: such a triangle keeps a plane a channel. */
static void test_lit_line_stays_in_range(void **state)
{
    (void)state;
    tarn_screen_vertex v[3] = {screen_vertex(0, 0), screen_vertex(40 * 16, 0), screen_vertex(0, 40 * 16)};
    for (int c = 0; c < 3; c++) {
        v[0].lit[c] = v[1].lit[c] = 0;
        v[2].lit[c] = 65280;
    }
    assert_int_equal(setup_lit(v, TARN_PERSPECTIVE_PIXEL, 1).first_varying, 2); /* ends exactly 0 and 255.0 */
    v[0].lit[1] = v[1].lit[1] = 130; /* green's line ends at 65281: one over */
    assert_int_equal(setup_lit(v, TARN_PERSPECTIVE_PIXEL, 1).first_varying, 0);
    v[0].lit[1] = v[1].lit[1] = 13;  /* ... and from 13 down to 0 ends at -1 */
    v[2].lit[1] = 0;
    assert_int_equal(setup_lit(v, TARN_PERSPECTIVE_PIXEL, 1).first_varying, 0);
}

/* Random lit triangles drawn with the lit colour on its line and with a plane a
 * channel: the same pixels, each channel within a level. */
static void test_lit_line_draws_as_planes(void **state)
{
    (void)state;
    coverage_counter *planes = counter_new(), *line = counter_new();
    planes->quality.lit_colour = TARN_LIT_PLANES;
    line->quality.lit_colour = TARN_LIT_LINE;
    uint32_t seed = 77, worst = 0;
    long drawn = 0, differ = 0;
    for (int n = 0; n < 2000; n++) {
        tarn_screen_vertex v[3];
        for (int k = 0; k < 3; k++) {
            v[k] = random_screen_vertex(&seed);
            light_vertex(&v[k], lcg(&seed) % 65537u);
        }
        counter_draw(planes, v);
        counter_draw(line, v);
        for (int p = 0; p < FRAME * FRAME; p++) {
            assert_int_equal(planes->colour[p] != 0, line->colour[p] != 0);
            if (planes->colour[p] == 0) continue;
            drawn++;
            differ += planes->colour[p] != line->colour[p];
            for (int c = 0; c < 3; c++) {
                const uint32_t a = (planes->colour[p] >> (8 * c)) & 0xFFu, b = (line->colour[p] >> (8 * c)) & 0xFFu;
                const uint32_t apart = a > b ? a - b : b - a;
                if (apart > worst) worst = apart;
            }
        }
    }
    print_message("lit line: %ld pixels, %ld of them another colour than the planes', at most %u level apart\n",
                  drawn, differ, (unsigned)worst);
    assert_true(drawn > 100000);
    assert_true(worst <= 1u);
    free(planes);
    free(line);
}

/* The 16-bit depth code of near/d q, as a pixel's depth test takes it. */
static uint32_t depth16_code(uint32_t q)
{
    if ((int32_t)q < 1) q = 1;
    if (q > (1u << 30)) q = 1u << 30;
    return tarn_depth16_encode(q);
}

/* Within the range found around q, every near/d codes as one shift and one add:
 * checked at both ends of the range and at q, for q at every power of two and its
 * neighbours, the clamps' edges and a million values of every magnitude. */
static void test_depth_ranges_code_as_the_encoder(void **state)
{
    (void)state;
    static uint32_t qs[4 * 32 + 1000000];
    size_t n = 0;
    for (unsigned k = 0; k < 32; k++) {
        qs[n++] = 1u << k;
        qs[n++] = (1u << k) - 1u;
        qs[n++] = (1u << k) + 1u;
    }
    qs[n++] = UINT32_MAX;
    uint32_t x = 2463534242u; /* xorshift32 */
    while (n < sizeof qs / sizeof qs[0]) {
        x ^= x << 13, x ^= x >> 17, x ^= x << 5;
        qs[n++] = x >> (x % 32u);
    }
    for (size_t k = 0; k < n; k++) {
        tarn_depth_range r = {0u, 0u, 0u, 0u};
        tarn__depth_range_find(&r, qs[k]);
        if (qs[k] - r.low >= r.width) fail_msg("near/d %u lies outside its range [%u, +%u)", qs[k], r.low, r.width);
        const uint32_t inside[3] = {r.low, qs[k], r.low + (r.width - 1u)};
        for (int e = 0; e < 3; e++)
            if ((inside[e] >> r.shift) + r.offset != depth16_code(inside[e]))
                fail_msg("near/d %u (range of %u): coded %u, the encoder gives %u", inside[e], qs[k],
                         (inside[e] >> r.shift) + r.offset, depth16_code(inside[e]));
    }
}

static void test_cull_modes(void **state)
{
    (void)state;
    static const uint8_t modes[] = {TARN_CULL_BACK, TARN_CULL_FRONT, TARN_CULL_NONE};
    static const int expect_drawn[][2] = {{1, 0}, {0, 1}, {1, 1}}; /* front face, back face */
    scene_builder *b = malloc(sizeof *b);
    for (size_t m = 0; m < 3; m++) {
        for (int back = 0; back < 2; back++) {
            builder_init(b, 0, 0, 0, 0, 0, -1);
            builder_begin_object(b, 0xFFFFFF, modes[m]);
            uint16_t p = builder_vertex(b, -1, -1, -3), q = builder_vertex(b, 1, -1, -3),
                     r = builder_vertex(b, 0, 1, -3);
            if (back) builder_triangle(b, p, r, q); else builder_triangle(b, p, q, r);
            tarn_frame_config config = config_of(32, 32);
            frame_buffers f = frame_new(32, 32);
            render_core(&b->scene, &config, &f);
            assert_int_equal(f.covered[16 * 32 + 16], expect_drawn[m][back]);
            frame_free(&f);
        }
    }
    free(b);
}

static void test_configs_out_of_range_are_rejected(void **state)
{
    (void)state;
    tarn_frame_config config = config_of(240, 240);
    assert_true(tarn_frame_memory_bytes(&config, NULL) > 0);
    tarn_frame_config bad = config;
    bad.width = 0;
    assert_int_equal(tarn_frame_memory_bytes(&bad, NULL), 0);
    bad = config; bad.width = TARN_FRAME_SIZE_MAX + 1;
    assert_int_equal(tarn_frame_memory_bytes(&bad, NULL), 0);
    bad = config; bad.quality.tile_size = 7;
    assert_int_equal(tarn_frame_memory_bytes(&bad, NULL), 0);
    bad = config; bad.quality.subpixel_bits = 7; /* 240 + guard band needs < 2^15 subpixels */
    assert_int_equal(tarn_frame_memory_bytes(&bad, NULL), 0);
    bad = config; bad.quality.depth_bits = 24;
    assert_int_equal(tarn_frame_memory_bytes(&bad, NULL), 0);
    bad = config; bad.quality.perspective_span = 12;
    assert_int_equal(tarn_frame_memory_bytes(&bad, NULL), 0);
    bad = config; bad.quality.cluster_bins = 2;
    assert_int_equal(tarn_frame_memory_bytes(&bad, NULL), 0);

    uint32_t small[16];
    scene_builder *b = malloc(sizeof *b);
    builder_init(b, 0, 0, 0, 0, 0, -1);
    assert_int_equal(tarn_render_frame(&b->scene, &config, small, sizeof small, NULL, NULL), TARN_ERR_MEMORY);
    builder_begin_object(b, 0xFFFFFF, TARN_CULL_NONE);
    builder_grid(b, 0, 0, -4, 1, 1, 1, 1);
    b->indices[0] = 60000; /* an index past the vertices */
    size_t need = tarn_frame_memory_bytes(&config, NULL);
    void *memory = malloc(need);
    assert_int_equal(tarn_render_frame(&b->scene, &config, memory, need, NULL, NULL), TARN_ERR_SCENE);
    /* a mesh without triangles whose cluster still runs over some (found by
     * fuzz_core: the walk followed the run past the indices) */
    b->indices[0] = 0;
    tarn_mesh *mesh = (tarn_mesh *)b->scene.objects[0].mesh;
    const tarn_cluster run = {{0, 0, 0}, TARN_Q16_ONE, 0, 5};
    const uint16_t triangles = mesh->triangle_count;
    mesh->triangle_count = 0;
    mesh->clusters = &run;
    mesh->cluster_count = 1;
    free(memory);
    need = tarn_frame_memory_bytes(&config, &b->scene);
    memory = malloc(need);
    assert_int_equal(tarn_render_frame(&b->scene, &config, memory, need, NULL, NULL), TARN_ERR_SCENE);
    mesh->triangle_count = triangles;
    mesh->clusters = NULL;
    mesh->cluster_count = 0;
    free(memory);
    free(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_jittered_grid_covers_every_pixel_once),
        cmocka_unit_test(test_fan_covers_disc_once),
        cmocka_unit_test(test_slivers_cover_strip_once),
        cmocka_unit_test(test_top_left_rule_on_pixel_centres),
        cmocka_unit_test(test_clipped_meshes_stay_watertight),
        cmocka_unit_test(test_tile_size_does_not_change_the_image),
        cmocka_unit_test(test_cluster_bins_do_not_change_the_image),
        cmocka_unit_test(test_pond_matches_snapped_reference),
        cmocka_unit_test(test_unsnapped_mismatches_lie_on_edges),
        cmocka_unit_test(test_extreme_triangles),
        cmocka_unit_test(test_random_triangles_cover_exactly),
        cmocka_unit_test(test_extreme_cameras),
        cmocka_unit_test(test_depth_ties_resolve_like_the_reference),
        cmocka_unit_test(test_plane_depth_follows_exact_depth),
        cmocka_unit_test(test_lit_line_where_colours_lie_on_one),
        cmocka_unit_test(test_lit_line_stays_in_range),
        cmocka_unit_test(test_lit_line_draws_as_planes),
        cmocka_unit_test(test_depth_ranges_code_as_the_encoder),
        cmocka_unit_test(test_cull_modes),
        cmocka_unit_test(test_configs_out_of_range_are_rejected),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
