/* test_water.c: the integer water pass at its limits, against what the rules in
 * tarn_water.h say must happen: density 0 leaves the background bit for bit, a huge
 * density leaves only fog, zero refraction changes nothing, a constant normal map
 * shifts the background by an exact number of pixels, tiles do not show with the
 * apron on, and a scene without water pays nothing for water. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include <math.h>

#include "frame_render.h"
#include "scene_builder.h"
#include "tarn_internal.h"

#define W 96
#define H 64

/* A floor at z = -8 with a 1-pixel-ish checker of vertex colours, under a water
 * quad at z = -5 facing the camera, which looks down -z from the origin. */
typedef struct {
    scene_builder b;
    tarn_water water;
    uint32_t colours[BUILDER_VERTICES_MAX];
    uint8_t normal_texels[4 * 4 * 3];
    tarn_texture normal_map;
} water_scene;

static void floor_and_water(water_scene *s, int with_water)
{
    builder_init(&s->b, 0, 0, 0, 0, 0, -1);
    builder_begin_object(&s->b, 0xFFFFFF, TARN_CULL_NONE);
    builder_grid(&s->b, 0, 0, -8, 24, 16, 48, 32); /* many small quads: a varied background */
    for (uint32_t v = 0; v < s->b.vertex_count; v++)
        s->colours[v] = (v * 2654435761u) & 0xFFFFFFu;
    s->b.meshes[0].colours = s->colours;
    if (!with_water) return;
    builder_begin_object(&s->b, 0xFFFFFF, TARN_CULL_NONE);
    builder_grid(&s->b, 0, 0, -5, 20, 14, 1, 1);
    s->b.materials[1].water = &s->water;
}

static void constant_normal_map(water_scene *s, uint8_t x, uint8_t y)
{
    for (int t = 0; t < 16; t++) {
        s->normal_texels[3 * t] = x;
        s->normal_texels[3 * t + 1] = y;
        s->normal_texels[3 * t + 2] = 255;
    }
    s->normal_map.width = s->normal_map.height = 4;
    s->normal_map.rgb = s->normal_texels;
    s->water.normal_a = &s->normal_map;
    s->water.pan_a.scale = TARN_Q16_ONE;
    s->water.normal_strength = TARN_Q16_ONE;
    s->water.normal_xy_max = TARN_Q16_ONE;
    s->water.features |= TARN_WATER_NORMALS;
}

static water_scene *new_scene(int with_water)
{
    water_scene *s = calloc(1, sizeof *s);
    assert_non_null(s);
    s->water.specular_power = 1;
    s->water.fog_rgb = 0x4E83A9;
    floor_and_water(s, with_water);
    return s;
}

static uint8_t *render(const water_scene *s, tarn_frame_config config)
{
    return test_render_rgb(&s->b.scene, &config, "water scene");
}

static tarn_frame_config config_of(void)
{
    tarn_frame_config config = {W, H, tarn_quality_default(), 0};
    return config;
}

static void test_zero_density_leaves_background_bit_for_bit(void **state)
{
    (void)state;
    water_scene *dry = new_scene(0), *wet = new_scene(1);
    wet->water.features = TARN_WATER_FOG; /* density 0, alpha 0 */
    uint8_t *a = render(dry, config_of()), *b = render(wet, config_of());
    assert_memory_equal(a, b, 3u * W * H);
    free(a);
    free(b);
    free(dry);
    free(wet);
}

static void test_huge_density_leaves_only_fog(void **state)
{
    (void)state;
    water_scene *wet = new_scene(1);
    wet->water.features = TARN_WATER_FOG;
    wet->water.fog_density = 64 * TARN_Q16_ONE; /* 3 units of water: 2^-192 of the floor */
    uint8_t *rgb = render(wet, config_of());
    for (int p = 0; p < W * H; p++) {
        assert_int_equal(rgb[3 * p], 0x4E);
        assert_int_equal(rgb[3 * p + 1], 0x83);
        assert_int_equal(rgb[3 * p + 2], 0xA9);
    }
    free(rgb);
    free(wet);
}

static void test_opaque_surface_colour(void **state)
{
    (void)state;
    water_scene *wet = new_scene(1);
    wet->water.albedo_rgb = 0x20C040;
    wet->water.alpha = TARN_Q16_ONE;
    wet->b.materials[1].unlit = 1;
    uint8_t *rgb = render(wet, config_of());
    for (int p = 0; p < W * H; p++) {
        assert_int_equal(rgb[3 * p], 0x20);
        assert_int_equal(rgb[3 * p + 1], 0xC0);
        assert_int_equal(rgb[3 * p + 2], 0x40);
    }
    free(rgb);
    free(wet);
}

static void test_zero_refraction_changes_nothing(void **state)
{
    (void)state;
    water_scene *plain = new_scene(1), *refracting = new_scene(1);
    water_scene *both[2] = {plain, refracting};
    for (int k = 0; k < 2; k++) {
        both[k]->water.features = TARN_WATER_FOG;
        both[k]->water.fog_density = TARN_Q16_ONE / 8;
        constant_normal_map(both[k], 230, 40);
    }
    refracting->water.features |= TARN_WATER_REFRACTION; /* strength 0 */
    uint8_t *a = render(plain, config_of()), *b = render(refracting, config_of());
    assert_memory_equal(a, b, 3u * W * H);
    free(a);
    free(b);
    free(plain);
    free(refracting);
}

/* N from texel (255, 128, 255) is (1, 0.0039, 1) normalised: x = 0.7057. With
 * refraction r, the sample moves round(0.7057 * r * W) pixels right. */
static void test_constant_normals_shift_the_background(void **state)
{
    (void)state;
    water_scene *dry = new_scene(0), *wet = new_scene(1);
    constant_normal_map(wet, 255, 128);
    wet->water.features |= TARN_WATER_REFRACTION;
    wet->water.refraction = TARN_Q16_ONE / 16; /* 6 px per unit normal at 96 wide: 4.23 -> 4 */
    uint8_t *floor = render(dry, config_of()), *water = render(wet, config_of());
    int checked = 0;
    for (int j = 0; j < H; j++)
        for (int i = 0; i + 4 < W; i++) {
            assert_memory_equal(&water[3 * (j * W + i)], &floor[3 * (j * W + i + 4)], 3);
            checked++;
        }
    assert_true(checked > 1000);
    free(floor);
    free(water);
    free(dry);
    free(wet);
}

static void test_tiles_do_not_show_with_the_apron(void **state)
{
    (void)state;
    water_scene *wet = new_scene(1);
    constant_normal_map(wet, 250, 20);
    wet->water.features |= TARN_WATER_REFRACTION | TARN_WATER_FOG;
    wet->water.fog_density = TARN_Q16_ONE / 4;
    wet->water.refraction = TARN_Q16_ONE / 10;
    tarn_frame_config config = config_of();
    config.quality.tile_size = 64;
    uint8_t *whole = render(wet, config);
    static const uint8_t tiles[] = {8, 13, 16, 32};
    for (size_t t = 0; t < sizeof tiles; t++) {
        config.quality.tile_size = tiles[t];
        uint8_t *tiled = render(wet, config);
        assert_memory_equal(whole, tiled, 3u * W * H);
        free(tiled);
    }
    /* an apron as wide as the reach is the full apron; a narrower one caps every
     * refracted sample's move at its width, the same at every tile size (no seams);
     * with none, refraction moves nothing */
    config.quality.tile_size = 8;
    const int32_t reach = tarn_frame_apron_pixels(&wet->b.scene, &config);
    assert_true(reach > 2);
    const size_t full_bytes = tarn_frame_memory_bytes(&config, &wet->b.scene);
    config.quality.refraction_apron = (uint8_t)reach;
    assert_int_equal(tarn_frame_memory_bytes(&config, &wet->b.scene), full_bytes);
    uint8_t *as_wide = render(wet, config);
    assert_memory_equal(whole, as_wide, 3u * W * H);
    config.quality.refraction_apron = 0;
    uint8_t *clamped = render(wet, config);
    assert_memory_not_equal(whole, clamped, 3u * W * H);
    wet->water.features &= ~(uint32_t)TARN_WATER_REFRACTION;
    uint8_t *unrefracted = render(wet, config);
    assert_memory_equal(unrefracted, clamped, 3u * W * H);
    wet->water.features |= TARN_WATER_REFRACTION;
    free(unrefracted);
    config.quality.refraction_apron = (uint8_t)(reach / 2);
    assert_int_equal(tarn_frame_apron_pixels(&wet->b.scene, &config), reach / 2);
    assert_true(tarn_frame_memory_bytes(&config, &wet->b.scene) < full_bytes);
    uint8_t *narrow = render(wet, config);
    assert_memory_not_equal(whole, narrow, 3u * W * H);
    assert_memory_not_equal(clamped, narrow, 3u * W * H);
    for (size_t t = 0; t < sizeof tiles; t++) {
        config.quality.tile_size = tiles[t];
        uint8_t *tiled = render(wet, config);
        assert_memory_equal(narrow, tiled, 3u * W * H);
        free(tiled);
    }
    free(narrow);
    free(clamped);
    free(as_wide);
    free(whole);
    free(wet);
}

static void test_time_near_the_wrap(void **state)
{
    (void)state;
    water_scene *wet = new_scene(1);
    constant_normal_map(wet, 200, 90);
    wet->water.pan_a.speed_u = 16 * TARN_Q16_ONE;
    wet->water.pan_a.speed_v = -16 * TARN_Q16_ONE;
    wet->water.features |= TARN_WATER_REFRACTION | TARN_WATER_SPARKLES | TARN_WATER_SPECULAR;
    wet->water.refraction = TARN_Q16_ONE / 10;
    wet->water.sparkle_amount = 2 * TARN_Q16_ONE;
    wet->water.specular = 4 * TARN_Q16_ONE;
    wet->water.specular_power = 256;
    static const uint32_t times[] = {0, UINT32_MAX - 1000, UINT32_MAX};
    for (size_t t = 0; t < 3; t++) {
        tarn_frame_config config = config_of();
        config.time_ms = times[t];
        free(render(wet, config));
    }
    free(wet);
}

/* Water on the floor itself: diff is 0 or negative everywhere; and the camera
 * exactly in the water plane. Nothing may break. */
static void test_coplanar_water_and_camera_on_the_surface(void **state)
{
    (void)state;
    water_scene *wet = new_scene(1);
    wet->water.features = TARN_WATER_FOG | TARN_WATER_ABSORPTION | TARN_WATER_DEPTH_COLOUR | TARN_WATER_FOAM;
    wet->water.fog_density = TARN_Q16_ONE;
    wet->water.absorption = TARN_Q16_ONE;
    wet->water.depth_scale = TARN_Q16_ONE;
    wet->water.foam_distance = TARN_Q16_ONE;
    wet->water.foam_texture = &wet->normal_map;
    constant_normal_map(wet, 128, 128);
    for (uint32_t v = 0; v < wet->b.vertex_count; v++) wet->b.positions[v].z = builder_q16(-8);
    free(render(wet, config_of()));
    builder_init(&wet->b, 0, -5, 0, 0, -5, -1); /* eye in the plane y = -5 */
    floor_and_water(wet, 1);
    free(render(wet, config_of()));
    free(wet);
}

/* Flat maps refract nothing; all-extreme maps (every component at its limit) with
 * the strongest refraction the apron allows, and a grazing view along the surface
 * to the horizon, render without breaking. */
static void test_extreme_normal_maps_and_views(void **state)
{
    (void)state;
    water_scene *plain = new_scene(1), *flat = new_scene(1);
    plain->water.features = flat->water.features = TARN_WATER_FOG;
    plain->water.fog_density = flat->water.fog_density = TARN_Q16_ONE / 8;
    constant_normal_map(flat, 128, 128); /* decodes to (0.004, 0.004, 1) */
    flat->water.normal_xy_max = TARN_Q16_ONE / 200;
    flat->water.features |= TARN_WATER_REFRACTION;
    flat->water.refraction = TARN_Q16_ONE;
    uint8_t *a = render(plain, config_of()), *b = render(flat, config_of());
    assert_memory_equal(a, b, 3u * W * H);
    free(a);
    free(b);
    static const uint8_t extremes[][3] = {{0, 0, 0}, {255, 255, 0}, {0, 255, 255}, {255, 0, 128}};
    for (size_t e = 0; e < sizeof extremes / sizeof extremes[0]; e++) {
        water_scene *wet = new_scene(1);
        constant_normal_map(wet, extremes[e][0], extremes[e][1]);
        for (int t = 0; t < 16; t++) wet->normal_texels[3 * t + 2] = extremes[e][2];
        wet->water.features |= TARN_WATER_REFRACTION | TARN_WATER_SPECULAR | TARN_WATER_SPARKLES;
        wet->water.refraction = (tarn_q16)(31 * TARN_Q16_ONE / W); /* reach: 31 + 1 = the apron */
        wet->water.specular = TARN_Q16_ONE;
        wet->water.sparkle_amount = TARN_Q16_ONE;
        tarn_frame_config config = config_of();
        assert_int_equal(tarn_frame_apron_pixels(&wet->b.scene, &config), 32);
        free(render(wet, config));
        free(wet);
    }
    water_scene *grazing = new_scene(1);
    builder_init(&grazing->b, 0, 0.001, 0, 0, 0.001, -1); /* a hair above the surface y = 0 */
    builder_begin_object(&grazing->b, 0x806040, TARN_CULL_NONE);
    builder_grid(&grazing->b, 0, -1, -500, 1000, 1, 4, 4);
    builder_begin_object(&grazing->b, 0xFFFFFF, TARN_CULL_NONE);
    uint16_t v[4];
    const double corners[4][2] = {{-900, -999}, {900, -999}, {900, -0.2}, {-900, -0.2}};
    for (int k = 0; k < 4; k++) v[k] = builder_vertex(&grazing->b, corners[k][0], 0, corners[k][1]);
    builder_triangle(&grazing->b, v[0], v[2], v[1]);
    builder_triangle(&grazing->b, v[0], v[3], v[2]);
    grazing->b.materials[1].water = &grazing->water;
    grazing->water.features = TARN_WATER_FOG | TARN_WATER_FOAM;
    grazing->water.fog_density = TARN_Q16_ONE;
    grazing->water.foam_distance = TARN_Q16_ONE;
    constant_normal_map(grazing, 200, 60);
    grazing->water.foam_texture = &grazing->normal_map;
    free(render(grazing, config_of()));
    free(grazing);
    free(plain);
    free(flat);
}

/* The factors the water blends by are checked once a frame, not clamped per pixel:
 * one past its documented range makes the scene malformed. */
static void test_blend_factors_out_of_range_are_refused(void **state)
{
    (void)state;
    water_scene *wet = new_scene(1);
    tarn_frame_config config = config_of();
    const size_t bytes = tarn_frame_memory_bytes(&config, &wet->b.scene);
    void *memory = malloc(bytes);
    tarn_q16 *const factors[] = {&wet->water.alpha, &wet->water.fresnel, &wet->water.foam_opacity,
                                 &wet->water.specular};
    static const tarn_q16 past[] = {TARN_Q16_ONE + 1, TARN_Q16_ONE + 1, TARN_Q16_ONE + 1, 4 * TARN_Q16_ONE + 1};
    for (size_t k = 0; k < sizeof past / sizeof past[0]; k++) {
        const tarn_q16 kept = *factors[k];
        *factors[k] = past[k];
        assert_int_equal(tarn_render_frame(&wet->b.scene, &config, memory, bytes, NULL, NULL), TARN_ERR_SCENE);
        *factors[k] = -1;
        assert_int_equal(tarn_render_frame(&wet->b.scene, &config, memory, bytes, NULL, NULL), TARN_ERR_SCENE);
        *factors[k] = kept;
        assert_int_equal(tarn_render_frame(&wet->b.scene, &config, memory, bytes, NULL, NULL), TARN_OK);
    }
    free(memory);
    free(wet);
}

/* A foam map kept as its red bytes alone (tarn_texture.red_only) draws what the
 * same map in R G B does, its green and blue unlike its red; a normal map or a
 * flag other than 0 or 1 so is refused. */
static void test_a_red_only_texture_is_a_foam_map(void **state)
{
    (void)state;
    water_scene *wet = new_scene(1);
    wet->water.features = TARN_WATER_FOG | TARN_WATER_FOAM;
    wet->water.fog_density = TARN_Q16_ONE / 8;
    wet->water.foam_distance = 8 * TARN_Q16_ONE; /* 3 units deep: foam where red >= 96 */
    wet->water.foam_opacity = TARN_Q16_ONE;
    wet->water.foam_rgb = 0xFFFFFF;
    /* the water's four vertices, the builder's last, over a repeat: every texel shows */
    static tarn_uv uvs[BUILDER_VERTICES_MAX];
    const uint32_t first = wet->b.vertex_count - 4u;
    for (uint32_t v = 0; v < 4u; v++)
        uvs[first + v] = (tarn_uv){(tarn_q16)(v & 1u) * TARN_Q16_ONE, (tarn_q16)(v >> 1) * TARN_Q16_ONE};
    wet->b.meshes[1].uvs = uvs;
    wet->water.foam_pan.scale = TARN_Q16_ONE;
    uint8_t foam_rgb[16 * 3], foam_red[16];
    for (int t = 0; t < 16; t++) {
        foam_red[t] = foam_rgb[3 * t] = (uint8_t)(255 - t * 17); /* every place from all to no foam */
        foam_rgb[3 * t + 1] = (uint8_t)(t * 17);
        foam_rgb[3 * t + 2] = 0;
    }
    tarn_texture foam = {4, 4, foam_rgb, 0};
    wet->water.foam_texture = &foam;
    uint8_t *from_rgb = render(wet, config_of());
    foam.rgb = foam_red;
    foam.red_only = 1;
    uint8_t *from_red = render(wet, config_of());
    assert_memory_equal(from_rgb, from_red, 3u * W * H);
    wet->water.foam_opacity = 0; /* the foam showed: without it the frame differs */
    uint8_t *without = render(wet, config_of());
    assert_memory_not_equal(from_rgb, without, 3u * W * H);
    free(without);
    wet->water.foam_opacity = TARN_Q16_ONE;
    foam.red_only = 2;
    assert_int_equal(test_render_status(&wet->b.scene, &(tarn_frame_config){W, H, tarn_quality_default(), 0}),
                     TARN_ERR_SCENE);
    foam.red_only = 1;
    constant_normal_map(wet, 128, 128);
    wet->water.features |= TARN_WATER_NORMALS | TARN_WATER_SPECULAR;
    wet->water.normal_a = &foam; /* a normal map reads green and blue too */
    assert_int_equal(test_render_status(&wet->b.scene, &(tarn_frame_config){W, H, tarn_quality_default(), 0}),
                     TARN_ERR_SCENE);
    free(from_rgb);
    free(from_red);
    free(wet);
}

static void test_opaque_scenes_pay_nothing_for_water(void **state)
{
    (void)state;
    water_scene *dry = new_scene(0), *wet = new_scene(1);
    tarn_frame_config config = config_of();
    const size_t tile = (size_t)config.quality.tile_size * config.quality.tile_size;
    config.quality.cluster_bins = 0;
    assert_int_equal(tarn_frame_memory_bytes(&config, &dry->b.scene), tile * 8u);
    assert_true(tarn_frame_memory_bytes(&config, &wet->b.scene) > tile * 8u);
    /* bins: 4 bytes for each of the builder's meshes, which have no clusters */
    config.quality.cluster_bins = 1;
    assert_int_equal(tarn_frame_memory_bytes(&config, &dry->b.scene), tile * 8u + 4u * dry->b.scene.object_count);
    free(dry);
    free(wet);
}

/* The water layers of test_water_in_place_draws_as_the_copy, over floor_and_water's
 * floor, each with cull none. */
enum { TWO_WATER_OBJECTS, MESH_OVER_ITSELF, WAVES_FROM_THE_SIDE, WATER_LAYERS };

static void add_water_object(water_scene *s)
{
    builder_begin_object(&s->b, 0xFFFFFF, TARN_CULL_NONE);
    s->b.materials[s->b.scene.object_count - 1].water = &s->water;
}

/* A height field from z = -20 to -2, farthest row first, seen from just above its
 * crests: y = -1.5 + 0.8 sin(1.7 z) beyond z = -6, where each near crest's faces
 * cover the trough behind it, drawn before them; flat nearer. */
static void add_waves(water_scene *s)
{
    enum { ACROSS = 6, ALONG = 48 };
    const uint16_t first = (uint16_t)s->b.vertex_count;
    for (int j = 0; j <= ALONG; j++) {
        const double z = -20.0 + 18.0 * j / ALONG;
        const double y = -1.5 + (z < -6.0 ? 0.8 * sin(1.7 * z) : 0.0);
        for (int i = 0; i <= ACROSS; i++) builder_vertex(&s->b, -12.0 + 24.0 * i / ACROSS, y, z);
    }
    for (int j = 0; j < ALONG; j++)
        for (int i = 0; i < ACROSS; i++) {
            const uint16_t v00 = (uint16_t)(first + j * (ACROSS + 1) + i), v01 = (uint16_t)(v00 + ACROSS + 1);
            builder_triangle(&s->b, v00, (uint16_t)(v00 + 1), (uint16_t)(v01 + 1));
            builder_triangle(&s->b, v00, (uint16_t)(v01 + 1), v01);
        }
}

static water_scene *layered_scene(int layers, uint32_t features)
{
    water_scene *s = new_scene(0);
    if (layers == WAVES_FROM_THE_SIDE) builder_init(&s->b, 0, -0.5, 0, 0, -1.5, -8);
    floor_and_water(s, 0);
    add_water_object(s);
    if (layers == WAVES_FROM_THE_SIDE) {
        add_waves(s);
    } else {
        builder_grid(&s->b, -2, 0, -6, 14, 10, 3, 2); /* the far layer first */
        if (layers == TWO_WATER_OBJECTS) add_water_object(s);
        builder_grid(&s->b, 3, 0.5, -4, 4, 3, 2, 3);  /* a nearer one over part of it */
        builder_grid(&s->b, 0, -3.5, -7, 16, 2, 2, 1); /* a farther one behind both */
    }
    s->water.features = features;
    s->water.fog_density = TARN_Q16_ONE / 6;
    s->water.albedo_rgb = 0x30A060;
    s->water.alpha = TARN_Q16_ONE / 3;
    s->water.specular = TARN_Q16_ONE;
    s->water.specular_power = 16;
    constant_normal_map(s, 180, 90);
    return s;
}

/* Fails on any pixel outside 0x00RRGGBB. */
static int check_pixels_are_rgb(void *user, const tarn_tile *tile)
{
    (void)user;
    for (int j = 0; j < tile->height; j++)
        for (int i = 0; i < tile->width; i++) assert_int_equal(tile->rgb[j * tile->stride + i] >> 24, 0);
    return 0;
}

static void assert_tiles_are_rgb(const water_scene *s, const tarn_frame_config *config)
{
    const size_t bytes = tarn_frame_memory_bytes(config, &s->b.scene);
    void *memory = malloc(bytes);
    assert_int_equal(tarn_render_frame(&s->b.scene, config, memory, bytes, check_pixels_are_rgb, NULL), TARN_OK);
    free(memory);
}

/* Without a refraction apron the water pass draws over the opaque buffers instead
 * of a copy of them (tarn_frame_memory_bytes: a tile's worth less), and must draw
 * the same image, also where water lies over water: each water pixel blends over
 * the opaque pixel beneath it, never over other water. A water material that
 * refracts by 0 reaches 1 pixel, so it takes the copy and gives the image
 * without refraction (test_zero_refraction_changes_nothing). */
/* The specular skips the square root where the highlight cannot show; it must add
 * what the normalised normal adds, at every power and intensity, for directions
 * all around the half vector and close to the edge of the highlight. */
static void test_specular_skip_matches_the_normalised_normal(void **state)
{
    (void)state;
    static const uint16_t powers[] = {1, 2, 8, 64, 256};
    static const tarn_q16 intensities[] = {TARN_Q16_ONE / 50, TARN_Q16_ONE / 2, 4 * TARN_Q16_ONE};
    uint32_t seed = 12345u, skipped = 0u, drawn = 0u;
    for (size_t p = 0; p < sizeof powers / sizeof powers[0]; p++)
        for (size_t k = 0; k < sizeof intensities / sizeof intensities[0]; k++) {
            tarn_water water = {0};
            water.specular = intensities[k];
            water.specular_power = powers[p];
            tarn_water_context w = {0};
            w.water = &water;
            w.dark_cosine = tarn__water_dark_cosine(&water);
            for (int c = 0; c < 3; c++) w.light_q8[c] = 65280u;
            for (int trial = 0; trial < 20000; trial++) {
                seed = seed * 1664525u + 1013904223u;
                const double theta = (seed >> 8) * (6.283185307179586 / 16777216.0);
                w.half_vector[0] = (int32_t)lround(32767.0 * 0.6 * cos(theta));
                w.half_vector[1] = (int32_t)lround(32767.0 * 0.6 * sin(theta));
                w.half_vector[2] = (int32_t)lround(32767.0 * 0.8);
                /* a direction near h: its largest component in [2^13, 2^14) */
                tarn_water_normal n;
                tarn__water_flat_normal(&n);
                int32_t v[3];
                for (int a = 0; a < 3; a++) {
                    seed = seed * 1664525u + 1013904223u;
                    v[a] = w.half_vector[a] / 4 + (int32_t)((seed >> 20) % 4001u) - 2000;
                }
                v[2] = 8192 + (int32_t)((seed >> 4) % 8191u);
                n.x = v[0];
                n.y = v[1];
                n.z = v[2];
                n.length2 = (uint32_t)(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                tarn_water_normal normalised = n;
                tarn__water_normalise(&normalised);
                uint32_t lazy[3] = {0u, 0u, 0u}, eager[3] = {0u, 0u, 0u};
                const int lazy_shows = tarn__water_specular(&w, &n, lazy);
                const int eager_shows = tarn__water_specular(&w, &normalised, eager);
                /* a skipped highlight adds nothing where the normalised one adds nothing */
                assert_memory_equal(lazy, eager, sizeof lazy);
                assert_true(lazy_shows || !eager_shows || (eager[0] | eager[1] | eager[2]) == 0u);
                if (n.length2 != 0u) skipped++; /* not normalised: skipped */
                if (eager[0] != 0u) drawn++;
            }
        }
    /* both outcomes were exercised: the test would not notice a skip that never runs */
    assert_true(skipped > 10000u);
    assert_true(drawn > 10000u);
}

/* A refracted sample over still water is read where the fog saw it from another
 * surface, and moved to this one's (tarn__water_fog_moved): each channel within 1
 * of endless + (colour - endless) * 2^(-density * (to - from)), through more water
 * and less, a little and a lot (the fast path below 1/16 of a halving and the
 * table above it), at every density the loader takes, and held where the colour
 * would move past 15 halvings' worth. */
static void test_moved_fog_is_the_fog_ratio(void **state)
{
    (void)state;
    static const double densities[] = {0.001, 0.15, 1.0, 64.0};
    static const double moves[] = {0.0, 0.01, -0.01, 0.3, -0.3, 1.7, -1.7, -20.0};
    uint32_t seed = 777u;
    size_t checked = 0;
    for (size_t d = 0; d < sizeof densities / sizeof densities[0]; d++)
        for (size_t m = 0; m < sizeof moves / sizeof moves[0]; m++) {
            tarn_water water = {0};
            water.fog_density = (tarn_q16)lround(densities[d] * 65536.0);
            tarn_water_context w = {0};
            w.water = &water;
            const uint32_t from = 10u << 16;
            const uint32_t to = (uint32_t)((int64_t)from + lround(moves[m] * 65536.0));
            const double halvings = water.fog_density / 65536.0 * ((double)to - (double)from) / 65536.0;
            for (int trial = 0; trial < 200; trial++) {
                seed = seed * 1664525u + 1013904223u;
                const uint32_t colour = seed >> 8, endless = (seed * 2654435761u) >> 8;
                const uint32_t moved = tarn__water_fog_moved(&w, colour, endless, from, to);
                const double ratio = exp2(-(halvings < -15.0 ? -15.0 : halvings));
                for (int at = 0; at < 24; at += 8) {
                    const double end = (endless >> at) & 0xFFu, c = (colour >> at) & 0xFFu;
                    double want = end + (c - end) * ratio;
                    want = want < 0.0 ? 0.0 : (want > 255.0 ? 255.0 : want);
                    const double got = (moved >> at) & 0xFFu;
                    if (fabs(got - want) > 1.0)
                        fail_msg("density %g, %g more water: channel %d of %06x toward %06x is %g, expected %.2f",
                                 densities[d], moves[m], at / 8, colour, endless, got, want);
                    checked++;
                }
            }
        }
    assert_int_equal(checked, 4u * 8u * 200u * 3u);
}

/* Where the pixel refracts by the EXACT normal, step 1 finds N itself from the
 * maps' texels: each component within 3 units of Q1.15 of the unit direction, the
 * bound the highlight's skip allows for (water_highlights.c), both N.xy in Q1.30
 * for refraction and N rounded to Q1.15, for texels all around and at every
 * strength the loader takes; the maps' x components for sparkles are the texels'. */
static void test_exact_normal_is_the_unit_direction(void **state)
{
    (void)state;
    static const tarn_q16 strengths[] = {TARN_Q16_ONE / 64, TARN_Q16_ONE / 3, TARN_Q16_ONE, 8 * TARN_Q16_ONE};
    uint8_t texel_a[3], texel_b[3];
    const tarn_texture map_a = {1, 1, texel_a, 0}, map_b = {1, 1, texel_b, 0};
    tarn_water water = {0};
    water.normal_a = &map_a;
    water.normal_b = &map_b;
    water.pan_a.scale = water.pan_b.scale = TARN_Q16_ONE;
    tarn_water_context w = {0};
    w.water = &water;
    w.features = TARN_WATER_NORMALS | TARN_WATER_REFRACTION;
    w.exact_normal = 1;
    const tarn_water_input in = {0};
    uint32_t seed = 2024u;
    double worst_q30 = 0.0, worst_q15 = 0.0;
    for (size_t k = 0; k < sizeof strengths / sizeof strengths[0]; k++) {
        water.normal_strength = strengths[k];
        for (int trial = 0; trial < 5000; trial++) {
            for (int c = 0; c < 3; c++) {
                seed = seed * 1664525u + 1013904223u;
                texel_a[c] = (uint8_t)(seed >> 24);
                texel_b[c] = (uint8_t)(seed >> 16);
            }
            texel_a[2] |= 0x80u; /* z up, as a normal map's */
            texel_b[2] |= 0x80u;
            tarn_water_normal n;
            tarn__water_pixel_normal(&w, &in, &n);
            double v[3], length = 0.0;
            const double s = strengths[k] / 65536.0;
            for (int c = 0; c < 2; c++) v[c] = s * ((2.0 * texel_a[c] - 255.0) + (2.0 * texel_b[c] - 255.0)) / 255.0;
            v[2] = (2.0 * texel_a[2] - 255.0) * (2.0 * texel_b[2] - 255.0) / (255.0 * 255.0);
            for (int c = 0; c < 3; c++) length += v[c] * v[c];
            length = sqrt(length);
            const int32_t q15[3] = {n.x, n.y, n.z};
            for (int c = 0; c < 3; c++) {
                const double unit = v[c] / length;
                if (c < 2 && fabs(n.xy_q30[c] - unit * 1073741824.0) > worst_q30)
                    worst_q30 = fabs(n.xy_q30[c] - unit * 1073741824.0);
                if (fabs(q15[c] - unit * 32768.0) > worst_q15) worst_q15 = fabs(q15[c] - unit * 32768.0);
            }
            assert_int_equal(n.length2, 0u); /* N itself: nothing normalises it again */
            assert_int_equal(n.a_x, tarn__water_normal_component(texel_a[0]));
            assert_int_equal(n.b_x, tarn__water_normal_component(texel_b[0]));
        }
    }
    if (worst_q30 > 3.0 * 32768.0 || worst_q15 > 3.0)
        fail_msg("the exact normal is off the unit direction by %.0f units of Q1.30 (at most 98304) and %.3f of "
                 "Q1.15 (at most 3)", worst_q30, worst_q15);
}

/* With water blocks too (even tiles), whose slots must survive the fall back to
 * strips and give the image of the copy, and of any other tile size. */
static void test_water_in_place_draws_as_the_copy(void **state)
{
    (void)state;
    const uint32_t features = TARN_WATER_FOG | TARN_WATER_NORMALS | TARN_WATER_SPECULAR | TARN_WATER_FRESNEL;
    static const uint8_t tiles[] = {8, 13, 28, 64};
    static const uint8_t depth_bits[] = {16, 32};
    for (int layers = 0; layers < WATER_LAYERS; layers++) {
        water_scene *in_place = layered_scene(layers, features);
        water_scene *copy = layered_scene(layers, features | TARN_WATER_REFRACTION);
        for (uint8_t block = 1; block <= 2; block++) {
            uint8_t *first = NULL;
            for (size_t t = 0; t < sizeof tiles; t++)
                for (size_t d = 0; d < sizeof depth_bits && (block == 1 || tiles[t] % 2 == 0); d++) {
                    tarn_frame_config config = config_of();
                    config.quality.tile_size = tiles[t];
                    config.quality.depth_bits = depth_bits[d];
                    config.quality.water_block = block;
                    /* the tile and two rows of it (the strips), a bin per object, and
                       with blocks a slot per two columns */
                    const size_t pixels = (size_t)tiles[t] * (tiles[t] + 2u);
                    const size_t slots = block == 2 ? tiles[t] / 2u * sizeof(tarn_water_block) : 0u;
                    const size_t in_place_bytes = tarn_frame_memory_bytes(&config, &in_place->b.scene);
                    assert_int_equal(in_place_bytes, pixels * (4u + depth_bits[d] / 8u) + slots +
                                                         4u * in_place->b.scene.object_count);
                    assert_true(tarn_frame_memory_bytes(&config, &copy->b.scene) > in_place_bytes);
                    uint8_t *a = render(in_place, config), *b = render(copy, config);
                    assert_memory_equal(a, b, 3u * W * H);
                    assert_tiles_are_rgb(in_place, &config);
                    if (first != NULL && depth_bits[d] == 16) assert_memory_equal(a, first, 3u * W * H);
                    if (first == NULL && depth_bits[d] == 16) first = a; else free(a);
                    free(b);
                }
            free(first);
        }
        free(in_place);
        free(copy);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_zero_density_leaves_background_bit_for_bit),
        cmocka_unit_test(test_huge_density_leaves_only_fog),
        cmocka_unit_test(test_opaque_surface_colour),
        cmocka_unit_test(test_zero_refraction_changes_nothing),
        cmocka_unit_test(test_constant_normals_shift_the_background),
        cmocka_unit_test(test_tiles_do_not_show_with_the_apron),
        cmocka_unit_test(test_time_near_the_wrap),
        cmocka_unit_test(test_coplanar_water_and_camera_on_the_surface),
        cmocka_unit_test(test_extreme_normal_maps_and_views),
        cmocka_unit_test(test_blend_factors_out_of_range_are_refused),
        cmocka_unit_test(test_a_red_only_texture_is_a_foam_map),
        cmocka_unit_test(test_opaque_scenes_pay_nothing_for_water),
        cmocka_unit_test(test_water_in_place_draws_as_the_copy),
        cmocka_unit_test(test_specular_skip_matches_the_normalised_normal),
        cmocka_unit_test(test_moved_fog_is_the_fog_ratio),
        cmocka_unit_test(test_exact_normal_is_the_unit_direction),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
