/* test_reference_water.c: the float reference's water (core/include/tarn/tarn_water.h) and
 * underwater view, on a pond whose every pixel can be worked out on paper.
 *
 * The camera hangs at (0, 10, 0) looking straight down (-y), 90 degree field of view,
 * on a 16x16 frame: focal = 8 pixels, screen right = world +x, screen down = world
 * +z. A square of half-width `depth` at that depth below the camera fills the frame
 * exactly, its uv running 0..1 across it, so pixel (i, j) sees uv ((i + 0.5) / 16,
 * (j + 0.5) / 16). The floor is such a square with a 16x16 texture, unlit: pixel
 * (i, j) shows texel (i, j) = (16i + 8, 16j + 8, 100). The water is one at depth 2;
 * diff is then the floor's depth less 2. Expected colours are the header's formulas
 * worked out by hand for these numbers, chosen away from rounding halves. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reference.h"
#include "tarn/tarn_render.h"

#define W 16
#define H 16
#define CAMERA_Y 10.0
#define WATER_DEPTH 2.0
#define SUBPIXEL_BITS 4

#define Q(v) ((tarn_q16)((v) * 65536.0))
#define VEC(x, y, z) { Q(x), Q(y), Q(z) }

#define OBJECTS_MAX 4

static uint8_t rgb[W * H * 3];
static uint8_t covered[W * H];

static uint8_t floor_texels[W * H * 3];
static const tarn_texture floor_texture = { .width = W, .height = H, .rgb = floor_texels };
static const tarn_material floor_material = {
    .colour_rgb = 0xFFFFFF, .texture = &floor_texture, .cull = TARN_CULL_NONE, .unlit = 1,
};
static const tarn_material pillar_material = {
    .colour_rgb = 0xFF00FF, .cull = TARN_CULL_NONE, .unlit = 1,
};

/* One texel of a constant map: every sample reads it. */
#define FLAT_NORMAL { 128, 128, 255 }
static const uint8_t tilt_right[3] = { 255, 128, 128 }; /* decodes to (1, 1/255, 1/255) */

static tarn_water water;
static const tarn_material water_material = {
    .colour_rgb = 0xFFFFFF, .cull = TARN_CULL_NONE, .unlit = 1, .water = &water,
};

static const tarn_vec3 up_normals[4] = { VEC(0, 1, 0), VEC(0, 1, 0), VEC(0, 1, 0), VEC(0, 1, 0) };
static const tarn_uv square_uvs[4] = { { 0, 0 }, { Q(1), 0 }, { Q(1), Q(1) }, { 0, Q(1) } };
static const uint16_t square_indices[6] = { 0, 1, 2, 0, 2, 3 };

static struct {
    tarn_vec3 corners[OBJECTS_MAX][4];
    tarn_mesh meshes[OBJECTS_MAX];
    tarn_object objects[OBJECTS_MAX];
    tarn_scene scene;
    tarn_underwater underwater;
} pond;

/* ---- building the pond ------------------------------------------------------------ */

static int setup_floor_texture(void **state)
{
    (void)state;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            uint8_t *t = floor_texels + 3 * (j * W + i);
            t[0] = (uint8_t)(16 * i + 8);
            t[1] = (uint8_t)(16 * j + 8);
            t[2] = 100;
        }
    return 0;
}

/* A water block with every feature off and alpha 0 (the floor shows through), every
 * panning texture one repeat per uv unit and still. */
static void reset_water(void)
{
    static const tarn_panning still = { .scale = Q(1) };
    water = (tarn_water){ .pan_a = still, .pan_b = still, .foam_pan = still };
}

/* A horizontal rectangle `depth` below the camera, x in [x0, x1], z in [z0, z1]. */
static tarn_object *add_rect(double depth, double x0, double x1, double z0, double z1,
                             const tarn_material *material)
{
    int n = pond.scene.object_count++;
    double y = CAMERA_Y - depth;
    tarn_vec3 *c = pond.corners[n];
    c[0] = (tarn_vec3)VEC(x0, y, z0);
    c[1] = (tarn_vec3)VEC(x1, y, z0);
    c[2] = (tarn_vec3)VEC(x1, y, z1);
    c[3] = (tarn_vec3)VEC(x0, y, z1);
    pond.meshes[n] = (tarn_mesh){ .positions = c, .normals = up_normals, .uvs = square_uvs,
                                  .indices = square_indices, .vertex_count = 4,
                                  .triangle_count = 2 };
    pond.objects[n] = (tarn_object){ .mesh = &pond.meshes[n], .material = material,
                                     .rotation = { { Q(1), 0, 0 }, { 0, Q(1), 0 }, { 0, 0, Q(1) } },
                                     .scale = Q(1) };
    return &pond.objects[n];
}

/* The square filling the frame at `depth`. */
static tarn_object *add_layer(double depth, const tarn_material *material)
{
    return add_rect(depth, -depth, depth, -depth, depth, material);
}

static void new_scene(void)
{
    memset(&pond, 0, sizeof pond);
    pond.scene = (tarn_scene){
        .objects = pond.objects,
        .camera = { .position = VEC(0, CAMERA_Y, 0), .target = VEC(0, 0, 0),
                    .fov_y_degrees = Q(90), .near = Q(1), .far = Q(100) },
        .light = { .direction = VEC(0, 1, 0), .colour_rgb = 0xFFFFFF, .ambient_rgb = 0 },
        .background_rgb = 0x102030,
    };
    reset_water();
}

/* The floor `floor_depth` below the camera, then the water over it. */
static void new_pond(double floor_depth)
{
    new_scene();
    add_layer(floor_depth, &floor_material);
    add_layer(WATER_DEPTH, &water_material);
}

static int render_timed(int snapped, uint32_t time_ms)
{
    tarn_reference_options opt = { .geometry = snapped ? TARN_REF_CORE_TRIANGLES : TARN_REF_CONTINUOUS, .subpixel_bits = SUBPIXEL_BITS,
                                   .time_ms = time_ms };
    return tarn_reference_render(&pond.scene, W, H, &opt, rgb, covered);
}

static void render(void)
{
    assert_int_equal(render_timed(0, 0), TARN_OK);
}

static const uint8_t *pixel(int i, int j)
{
    return rgb + 3 * (j * W + i);
}

static void assert_pixel(int i, int j, int r, int g, int b)
{
    const uint8_t *p = pixel(i, j);
    if (p[0] != r || p[1] != g || p[2] != b)
        fail_msg("pixel (%d,%d) is (%d,%d,%d), expected (%d,%d,%d)", i, j, p[0], p[1], p[2], r,
                 g, b);
}

static void assert_floor_texel(int i, int j, int texel_i, int texel_j)
{
    assert_pixel(i, j, 16 * texel_i + 8, 16 * texel_j + 8, 100);
}

static void assert_every_pixel(int r, int g, int b)
{
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) assert_pixel(i, j, r, g, b);
}

static void assert_channel_near(double got, double expected)
{
    if (!(fabs(got - expected) <= 0.5 + 1e-9))
        fail_msg("channel is %g, expected %g", got, expected);
}

/* ---- steps 4, 5: fog and absorption ------------------------------------------------ */

/* B = fog + (B - fog) * exp2(-0.5 * 2) = fog + (B - fog) / 2: (136,136,100) over
 * fog (32,64,96) gives (84,100,98). */
static void test_fog_follows_exp2_of_the_depth_difference(void **state)
{
    (void)state;
    new_pond(4.0);
    water.features = TARN_WATER_FOG;
    water.fog_rgb = 0x204060;
    water.fog_density = Q(0.5);
    render();
    assert_pixel(8, 8, 84, 100, 98);
    assert_pixel(0, 15, 20, 156, 98); /* (8,248,100) halfway to the fog */
    for (int p = 0; p < W * H; p++) assert_int_equal(covered[p], 1);
}

static void test_zero_fog_density_leaves_the_background_bit_for_bit(void **state)
{
    (void)state;
    uint8_t floor_only[sizeof rgb];
    new_pond(4.0);
    pond.scene.object_count = 1;
    render();
    memcpy(floor_only, rgb, sizeof rgb);

    pond.scene.object_count = 2;
    water.features = TARN_WATER_FOG;
    water.fog_rgb = 0xFFFFFF;
    water.fog_density = 0;
    render();
    assert_memory_equal(rgb, floor_only, sizeof rgb);
}

static void test_dense_fog_gives_the_fog_colour(void **state)
{
    (void)state;
    new_pond(4.0);
    water.features = TARN_WATER_FOG;
    water.fog_rgb = 0x204060;
    water.fog_density = Q(64); /* exp2(-128) */
    render();
    assert_every_pixel(0x20, 0x40, 0x60);
}

/* (255,191,127) absorbs (0,64,128) of full strength; 1 - exp2(-1) = 1/2 of it:
 * (136,136,100) - (0,32,64) = (136,104,36), whether k = 0.5 per unit or 0.25 per
 * unit squared (diff^2 = 4). */
static void test_absorption_subtracts_the_inverse_water_colour(void **state)
{
    (void)state;
    new_pond(4.0);
    water.features = TARN_WATER_ABSORPTION;
    water.absorb_rgb = 0xFFBF7F;
    water.absorption = Q(0.5);
    render();
    assert_pixel(8, 8, 136, 104, 36);

    water.absorption = Q(0.25);
    water.absorption_squared = 1;
    render();
    assert_pixel(8, 8, 136, 104, 36);

    water.absorb_rgb = 0x000000; /* absorbs everything, floored at 0 */
    water.absorption = Q(64);
    render();
    assert_every_pixel(0, 0, 0);
}

/* ---- steps 6, 7: the surface colour ------------------------------------------------ */

static void test_alpha_blends_the_lit_surface_over_the_background(void **state)
{
    (void)state;
    new_pond(4.0);
    water.albedo_rgb = 0x346498; /* (52,100,152) */
    water.alpha = 0;
    render();
    assert_floor_texel(8, 8, 8, 8);

    water.alpha = Q(0.25); /* (13,25,38) + (102,102,75) */
    render();
    assert_pixel(8, 8, 115, 127, 113);

    /* Alone, and lit by the material colour 128: S * 128 / 255 = (26.1,50.2,76.3). */
    static const tarn_material grey_water = {
        .colour_rgb = 0x808080, .cull = TARN_CULL_NONE, .unlit = 1, .water = &water,
    };
    pond.objects[1].material = &grey_water;
    water.alpha = Q(1);
    render();
    assert_pixel(8, 8, 26, 50, 76);
}

/* Every vertex of the water square sees the camera at n.v = 2 / sqrt(12), so the
 * interpolated term is that constant: alpha = 0 + 1 * 1 * (1 - 2/sqrt(12))^2. */
static void test_fresnel_raises_alpha_at_grazing_angles(void **state)
{
    (void)state;
    new_pond(4.0);
    water.features = TARN_WATER_FRESNEL;
    water.albedo_rgb = 0xFFFFFF;
    water.fresnel = Q(1);
    render();
    double n_dot_v = 2.0 / sqrt(12.0), alpha = (1 - n_dot_v) * (1 - n_dot_v); /* 0.1786 */
    const uint8_t *p = pixel(8, 8);
    assert_channel_near(p[0], 255 * alpha + 136 * (1 - alpha));
    assert_channel_near(p[2], 255 * alpha + 100 * (1 - alpha));
    assert_pixel(8, 8, 157, 157, 128);
}

/* t = saturate(2 / 8) = 0.25 of the way from shallow to deep. */
static void test_depth_colour_goes_from_shallow_to_deep(void **state)
{
    (void)state;
    new_pond(4.0);
    water.features = TARN_WATER_DEPTH_COLOUR;
    water.alpha = Q(1);
    water.shallow_rgb = 0x00FF40;
    water.deep_rgb = 0x8000C0;
    water.depth_scale = Q(8);
    render();
    assert_pixel(8, 8, 32, 191, 96); /* (0,255,64) + (128,-255,128) / 4 */

    new_pond(40.0); /* diff 38: past depth_scale, the deep colour */
    water.features = TARN_WATER_DEPTH_COLOUR;
    water.alpha = Q(1);
    water.shallow_rgb = 0x00FF40;
    water.deep_rgb = 0x8000C0;
    water.depth_scale = Q(8);
    render();
    assert_every_pixel(0x80, 0x00, 0xC0);
}

/* The ramp's texel x = floor(0.25 * 7 + 0.5) = 2. */
static void test_colour_ramp_is_read_at_the_rounded_fraction(void **state)
{
    (void)state;
    static const uint8_t ramp_texels[8 * 3] = {
        0, 255, 7, 30, 225, 7, 60, 195, 7, 90, 165, 7,
        120, 135, 7, 150, 105, 7, 180, 75, 7, 210, 45, 7,
    };
    static const tarn_texture ramp = { .width = 8, .height = 1, .rgb = ramp_texels };
    new_pond(4.0);
    water.features = TARN_WATER_DEPTH_COLOUR;
    water.alpha = Q(1);
    water.depth_scale = Q(8);
    water.colour_ramp = &ramp;
    render();
    assert_every_pixel(60, 195, 7);
}

/* ---- steps 1, 2: normals and refraction --------------------------------------------- */

static const tarn_texture tilted_map = { .width = 1, .height = 1, .rgb = tilt_right };

/* N = normalize(1, 1/255, 1/255) = (0.99998, ...): 3/16 of 16 pixels shifts
 * 2.99994 pixels in x, rounded to 3; 0.0118 in y, rounded to 0. */
static void refracting_water(tarn_q16 refraction)
{
    water.features = TARN_WATER_NORMALS | TARN_WATER_REFRACTION;
    water.normal_a = &tilted_map;
    water.normal_strength = Q(1);
    water.refraction = refraction;
}

static void test_refraction_shifts_the_background_by_whole_pixels(void **state)
{
    (void)state;
    new_pond(4.0);
    refracting_water(Q(3.0 / 16));
    render();
    assert_floor_texel(4, 8, 7, 8);
    assert_floor_texel(12, 3, 15, 3);
    assert_floor_texel(14, 8, 15, 8); /* clamped to the frame */

    /* (0,255,128) decodes to (-1,1,1/255): N.xy = (-0.7071,0.7071); 4/16 of 16 is
     * (-2.83,2.83) pixels, rounded to (-3,3): screen y grows downward. */
    static const uint8_t up_left[3] = { 0, 255, 128 };
    static const tarn_texture up_left_map = { .width = 1, .height = 1, .rgb = up_left };
    water.normal_a = &up_left_map;
    water.refraction = Q(4.0 / 16);
    render();
    assert_floor_texel(8, 8, 5, 11);
}

/* Shallower than one unit the shift shrinks with diff: 4 * 0.99998 * 0.5 = 2. */
static void test_refraction_shrinks_in_shallow_water(void **state)
{
    (void)state;
    new_pond(2.5);
    refracting_water(Q(4.0 / 16));
    render();
    assert_floor_texel(4, 8, 6, 8);
}

/* Two maps add their xy: opposite tilts cancel, and the surface refracts nothing. */
static void test_two_normal_maps_add(void **state)
{
    (void)state;
    static const uint8_t tilt_left[3] = { 0, 128, 255 };
    static const uint8_t tilt_right_up[3] = { 255, 128, 255 };
    static const tarn_texture left = { .width = 1, .height = 1, .rgb = tilt_left };
    static const tarn_texture right = { .width = 1, .height = 1, .rgb = tilt_right_up };
    new_pond(4.0);
    refracting_water(Q(3.0 / 16));
    water.normal_a = &right;
    render();
    assert_floor_texel(4, 8, 6, 8); /* (1,1/255,1) alone: 3 * 0.7071 = 2.12, 2 pixels */
    water.normal_b = &left;
    render();
    assert_floor_texel(4, 8, 4, 8);
}

/* A magenta pillar at depth 1 covers columns 10..15: water pixels whose shifted
 * sample lands on it read their own pixel instead. */
static void test_refraction_falls_back_when_the_sample_is_in_front(void **state)
{
    (void)state;
    new_scene();
    add_layer(4.0, &floor_material);
    add_rect(1.0, 0.25, 1.5, -1.5, 1.5, &pillar_material);
    add_layer(WATER_DEPTH, &water_material);
    refracting_water(Q(3.0 / 16));
    render();
    assert_floor_texel(6, 8, 9, 8);
    assert_floor_texel(7, 8, 7, 8); /* (10,8) is the pillar: fall back */
    assert_floor_texel(8, 8, 8, 8);
    assert_pixel(11, 8, 255, 0, 255);
}

/* ---- the passes: which water is drawn ----------------------------------------------- */

static void test_nearest_water_wins_and_reads_only_the_opaque(void **state)
{
    (void)state;
    static tarn_water red_water;
    static const tarn_material red_material = {
        .colour_rgb = 0xFFFFFF, .cull = TARN_CULL_NONE, .unlit = 1, .water = &red_water,
    };
    red_water = (tarn_water){ .albedo_rgb = 0xFF0000, .alpha = Q(1) };
    new_pond(4.0); /* the clear water (alpha 0) at depth 2 */

    add_layer(3.0, &red_material); /* later, behind the clear water: hidden */
    render();
    assert_floor_texel(8, 8, 8, 8);

    pond.scene.object_count = 2;
    add_layer(1.5, &red_material); /* later and nearer: drawn */
    render();
    assert_pixel(8, 8, 255, 0, 0);

    pond.scene.object_count = 1;
    add_layer(1.5, &red_material);
    add_layer(1.0, &water_material); /* nearer still, but clear: it sees the floor */
    render();
    assert_floor_texel(8, 8, 8, 8);

    pond.scene.object_count = 1;
    add_layer(2.0, &red_material); /* same depth as the clear water, earlier: it stays */
    add_layer(2.0, &water_material);
    render();
    assert_pixel(8, 8, 255, 0, 0);

    new_pond(4.0);
    pond.scene.object_count = 0;
    add_layer(5.0, &red_material); /* water below the floor is not drawn */
    add_layer(4.0, &floor_material);
    render();
    assert_floor_texel(8, 8, 8, 8);
}

/* ---- step 8: specular -------------------------------------------------------------- */

/* A flat surface, light straight down the camera's backward axis: N.h = 1 and the
 * highlight is light * specular = (32,64,96) / 2 on top of the floor. */
static void test_specular_on_a_flat_surface(void **state)
{
    (void)state;
    new_pond(4.0);
    water.features = TARN_WATER_SPECULAR;
    water.specular = Q(0.5);
    water.specular_power = 8;
    pond.scene.light.colour_rgb = 0x204060;
    render();
    assert_pixel(8, 8, 152, 168, 148);

    /* L = (0.6,0.8,0): h = normalize(0.6,1.8,0), N.h = h.y = 0.949, ^8 = 0.656 */
    pond.scene.light.direction = (tarn_vec3)VEC(0.6, 0.8, 0);
    pond.scene.light.colour_rgb = 0x404040;
    water.specular = Q(1);
    render();
    double lx = Q(0.6) / 65536.0, ly = Q(0.8) / 65536.0 + 1;
    double highlight = 64 * pow(ly / sqrt(lx * lx + ly * ly), 8);
    assert_channel_near(pixel(8, 8)[0], 136 + highlight);
    assert_pixel(8, 8, 178, 178, 142);

    /* L = -V: no half vector; h is taken as the surface's up, N.h = 1 */
    pond.scene.light.direction = (tarn_vec3)VEC(0, -1, 0);
    render();
    assert_pixel(8, 8, 200, 200, 164);
}

/* The normal map's x runs along the object's x axis: turned a quarter about y, the
 * water's tilt no longer leans toward the light's side. N = (0.99998,0.0039,0.0039);
 * h = (0.7071,0.7071,0) in the world. */
static void test_specular_uses_the_object_tangent_frame(void **state)
{
    (void)state;
    new_pond(4.0);
    water.features = TARN_WATER_NORMALS | TARN_WATER_SPECULAR;
    water.normal_a = &tilted_map;
    water.normal_strength = Q(1);
    water.specular = Q(1);
    water.specular_power = 1;
    pond.scene.light.direction = (tarn_vec3)VEC(1, 0, 0);
    pond.scene.light.colour_rgb = 0x404040;
    double nx = 1, nyz = 1 / 255.0, len = sqrt(nx * nx + 2 * nyz * nyz);
    render();
    assert_channel_near(pixel(8, 8)[0], 136 + 64 * (nx + nyz) / len * sqrt(0.5)); /* +45.4 */

    /* object x = world -z, object z = world x: h = (0, 0.7071, 0.7071) (u, v, up) */
    tarn_object *w = &pond.objects[1];
    const tarn_q16 quarter_turn[3][3] = { { 0, 0, Q(1) }, { 0, Q(1), 0 }, { -Q(1), 0, 0 } };
    memcpy(w->rotation, quarter_turn, sizeof quarter_turn);
    render();
    assert_channel_near(pixel(8, 8)[0], 136 + 64 * 2 * nyz / len * sqrt(0.5)); /* +0.35 */
}

/* ---- step 9: foam ------------------------------------------------------------------ */

static uint8_t foam_texel[3];
static const tarn_texture constant_foam = { .width = 1, .height = 1, .rgb = foam_texel };

static void foaming_pond(double foam_distance, uint8_t foam_red)
{
    new_pond(4.0);
    water.features = TARN_WATER_FOAM;
    water.foam_texture = &constant_foam;
    water.foam_distance = Q(foam_distance);
    water.foam_rgb = 0xFFFFFF;
    water.foam_opacity = Q(0.25);
    foam_texel[0] = foam_red;
}

/* f = 2/4 = 0.5, no lines: foam where red/255 >= 0.5, a quarter of the way to white. */
static void test_foam_where_the_texture_reaches_the_band(void **state)
{
    (void)state;
    foaming_pond(4.0, 192);
    render();
    assert_pixel(8, 8, 166, 166, 139); /* (136,136,100) + (119,119,155) / 4, rounded */

    foaming_pond(4.0, 64);
    render();
    assert_floor_texel(8, 8, 8, 8);

    foaming_pond(2.0, 255); /* f = 1: past the band, no foam at all */
    render();
    assert_floor_texel(8, 8, 8, 8);
}

/* f = 2/8 = 0.25; one line: saturate(sin(2 pi * 0.25)) * 0.75 = 0.75 lowers the
 * threshold to -0.5, foam even where the texture is black. */
static void test_foam_lines_widen_the_band(void **state)
{
    (void)state;
    foaming_pond(8.0, 0);
    render();
    assert_floor_texel(8, 8, 8, 8);
    water.foam_line_count = 1;
    render();
    assert_pixel(8, 8, 166, 166, 139);
}

/* f = 2/4 = 0.5, texture 32/255 = 0.125, one line moving a quarter band a second:
 * sin(2 pi * (0.5 - time / 4)) is 0 at rest, 1 after a second (lines = 0.5: the
 * threshold drops to 0, foam) and -1 after three (no lines, no foam). */
static void test_foam_lines_move_with_time(void **state)
{
    (void)state;
    foaming_pond(4.0, 32);
    water.foam_line_count = 1;
    water.foam_line_speed = Q(0.25);
    const struct {
        uint32_t time_ms;
        int foam;
    } cases[] = { { 0, 0 }, { 1000, 1 }, { 3000, 0 }, { 5000, 1 } };
    for (unsigned k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        assert_int_equal(render_timed(0, cases[k].time_ms), TARN_OK);
        if (cases[k].foam)
            assert_pixel(8, 8, 166, 166, 139);
        else
            assert_floor_texel(8, 8, 8, 8);
    }
}

/* A 16-texel foam strip white at texel 0 only, one repeat across the frame: at rest
 * only column 0 foams. At 2^32 - 1 ms and 16 repeats per second the pan offset is
 * 68719476.72 repeats, 0.72 after wrapping: 11.52 texels, so column i reads texel
 * floor(i + 0.5 + 11.52) = i + 12 (mod 16) and column 4 foams; panning the other way
 * puts it at column 12. */
static void test_panning_wraps_at_the_end_of_the_clock(void **state)
{
    (void)state;
    static uint8_t strip[16 * 3];
    static const tarn_texture strip_texture = { .width = 16, .height = 1, .rgb = strip };
    strip[0] = 255;
    new_pond(4.0);
    water.features = TARN_WATER_FOAM;
    water.foam_texture = &strip_texture;
    water.foam_distance = Q(8); /* f = 0.25: foam where red >= 64 */
    water.foam_rgb = 0xFFFFFF;
    water.foam_opacity = Q(1);
    const struct {
        uint32_t time_ms;
        tarn_q16 speed;
        int column;
    } cases[] = { { 0, Q(16), 0 }, { UINT32_MAX, Q(16), 4 }, { UINT32_MAX, -Q(16), 12 } };
    for (unsigned k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        water.foam_pan.speed_u = cases[k].speed;
        assert_int_equal(render_timed(0, cases[k].time_ms), TARN_OK);
        for (int i = 0; i < W; i++) {
            int white = pixel(i, 5)[0] == 255 && pixel(i, 5)[2] == 255;
            if (white != (i == cases[k].column))
                fail_msg("case %u: column %d white %d", k, i, white);
        }
    }
}

/* ---- step 10: sparkles ------------------------------------------------------------- */

static void test_sparkles_where_every_map_crosses_the_threshold(void **state)
{
    (void)state;
    static const uint8_t flat[3] = FLAT_NORMAL;
    static const tarn_texture flat_map = { .width = 1, .height = 1, .rgb = flat };
    new_pond(4.0);
    water.features = TARN_WATER_SPARKLES; /* the maps are read only with normals */
    water.normal_a = &tilted_map; /* a.x = 1 */
    water.sparkle_amount = Q(2);  /* 1 * 2 > 1 */
    water.sparkle_rgb = 0x102030;
    render();
    assert_floor_texel(8, 8, 8, 8);

    water.features |= TARN_WATER_NORMALS;
    render();
    assert_pixel(8, 8, 152, 168, 148);

    water.normal_b = &flat_map; /* b.x = 1/255: b.x^2 * 2 < 1 */
    render();
    assert_floor_texel(8, 8, 8, 8);

    water.normal_b = &tilted_map;
    render();
    assert_pixel(8, 8, 152, 168, 148);

    water.normal_a = &flat_map;
    render();
    assert_floor_texel(8, 8, 8, 8);

    /* Exactly at the threshold there is no sparkle: x = -51/255 = -0.2, 0.04 * 25 = 1
     * (which doubles would round to either side); one code further there is. */
    static uint8_t edge[3] = { 102, 128, 255 };
    static const tarn_texture edge_map = { .width = 1, .height = 1, .rgb = edge };
    water.normal_a = &edge_map;
    water.normal_b = NULL;
    water.sparkle_amount = Q(25);
    render();
    assert_floor_texel(8, 8, 8, 8);
    edge[0] = 101;
    render();
    assert_pixel(8, 8, 152, 168, 148);
}

/* ---- underwater -------------------------------------------------------------------- */

static const uint8_t flat_texel[3] = FLAT_NORMAL;
static const tarn_texture flat_normal_map = { .width = 1, .height = 1, .rgb = flat_texel };

static void dive(tarn_q16 level, uint32_t tint_rgb, tarn_q16 density)
{
    pond.underwater = (tarn_underwater){ .level = level, .normal_map = &flat_normal_map,
                                         .pan = { .scale = Q(1) }, .tint_rgb = tint_rgb,
                                         .tint_density = density };
    pond.scene.underwater = &pond.underwater;
}

/* Floor at depth 4, density 0.25: halfway to the tint (0,200,128). */
static void test_underwater_tint_grows_with_depth(void **state)
{
    (void)state;
    new_pond(4.0);
    pond.scene.object_count = 1;
    dive(Q(CAMERA_Y + 10), 0x00C880, Q(0.25));
    render();
    assert_pixel(8, 8, 68, 168, 114);

    pond.scene.object_count = 0; /* nothing drawn: the far distance, 2^-25 of the sky */
    render();
    assert_every_pixel(0x00, 0xC8, 0x80);

    dive(Q(CAMERA_Y - 1), 0x00C880, Q(0.25)); /* the camera above the level: no tint */
    render();
    assert_every_pixel(0x10, 0x20, 0x30);
}

/* The tint reads the nearest depth: the water surface at 2, not the floor at 4;
 * 1 - exp2(-0.5 * 2) = 1/2 of the way from the water's colour (52,100,152). */
static void test_underwater_depth_includes_the_water(void **state)
{
    (void)state;
    new_pond(4.0);
    water.albedo_rgb = 0x346498;
    water.alpha = Q(1);
    dive(Q(CAMERA_Y + 10), 0x00C880, Q(0.5));
    render();
    assert_pixel(8, 8, 26, 150, 140);
}

/* The map's x = 1 and a distortion of 3/16 frame widths move every sample 3 pixels
 * right (clamped at the edge), before the tint. */
static void test_underwater_distortion_shifts_whole_pixels(void **state)
{
    (void)state;
    new_pond(4.0);
    pond.scene.object_count = 1;
    dive(Q(CAMERA_Y + 10), 0x000000, 0);
    pond.underwater.normal_map = &tilted_map;
    pond.underwater.distortion = Q(3.0 / 16);
    render();
    assert_floor_texel(4, 8, 7, 8);
    assert_floor_texel(14, 2, 15, 2);
}

/* On a 24-pixel frame at scale 3, pixel centre i + 0.5 reads the 16-texel map at
 * (i + 0.5) / 24 * 3 * 16 = 2i + 1 exactly: a texel edge, which belongs to the texel
 * above (odd, tilted: a shift of round(2 * 0.99994) = 2 pixels), never to the even,
 * flat one below. */
static void test_underwater_map_edges_take_the_texel_above(void **state)
{
    (void)state;
    enum { SIZE = 24 };
    static uint8_t stripes[16 * 3], base[SIZE * SIZE * 3], shifted[SIZE * SIZE * 3];
    static const tarn_texture stripe_map = { .width = 16, .height = 1, .rgb = stripes };
    for (int k = 0; k < 16; k++) {
        stripes[3 * k] = k % 2 ? 255 : 128;
        stripes[3 * k + 1] = 128;
        stripes[3 * k + 2] = 255;
    }
    new_pond(4.0);
    pond.scene.object_count = 1;
    dive(Q(CAMERA_Y + 10), 0x000000, 0);
    pond.underwater.normal_map = &stripe_map;
    pond.underwater.pan.scale = Q(3);
    tarn_reference_options opt = { .geometry = TARN_REF_CONTINUOUS, .subpixel_bits = SUBPIXEL_BITS };
    assert_int_equal(tarn_reference_render(&pond.scene, SIZE, SIZE, &opt, base, NULL), TARN_OK);
    pond.underwater.distortion = Q(2.0 / SIZE);
    assert_int_equal(tarn_reference_render(&pond.scene, SIZE, SIZE, &opt, shifted, NULL), TARN_OK);
    for (int j = 0; j < SIZE; j++)
        for (int i = 0; i < SIZE; i++) {
            int from = i + 2 < SIZE ? i + 2 : SIZE - 1;
            if (memcmp(shifted + 3 * (j * SIZE + i), base + 3 * (j * SIZE + from), 3) != 0)
                fail_msg("pixel (%d,%d) does not show pixel (%d,%d)", i, j, from, j);
        }
}

/* ---- snapped mode and bad water ------------------------------------------------------ */

/* The core's own triangles (its Q1.30 depths and Q1.15 fresnel) land within a
 * level of the reference's. */
static void test_snapped_water_matches_the_unsnapped(void **state)
{
    (void)state;
    uint8_t unsnapped[sizeof rgb];
    new_pond(4.0);
    water.features = TARN_WATER_FOG | TARN_WATER_FRESNEL | TARN_WATER_SPECULAR;
    water.fog_rgb = 0x204060;
    water.fog_density = Q(0.3);
    water.albedo_rgb = 0x80C0FF;
    water.alpha = Q(0.2);
    water.fresnel = Q(1);
    water.specular = Q(0.25);
    water.specular_power = 4;
    render();
    memcpy(unsnapped, rgb, sizeof rgb);
    assert_int_equal(render_timed(1, 0), TARN_OK);
    for (size_t k = 0; k < sizeof rgb; k++)
        if (abs(rgb[k] - unsnapped[k]) > 1)
            fail_msg("byte %zu: snapped %d, unsnapped %d", k, rgb[k], unsnapped[k]);
}

static void test_water_missing_its_textures_is_rejected(void **state)
{
    (void)state;
    const uint32_t needs_a_map[] = { TARN_WATER_NORMALS, TARN_WATER_FOAM };
    for (unsigned k = 0; k < 2; k++) {
        new_pond(4.0);
        water.features = needs_a_map[k];
        water.foam_distance = Q(1);
        assert_int_equal(render_timed(0, 0), TARN_ERR_SCENE);
    }
    new_pond(4.0);
    water.features = TARN_WATER_DEPTH_COLOUR; /* depth_scale 0 */
    assert_int_equal(render_timed(0, 0), TARN_ERR_SCENE);

    new_pond(4.0);
    dive(Q(CAMERA_Y + 10), 0, 0);
    pond.underwater.normal_map = NULL;
    assert_int_equal(render_timed(0, 0), TARN_ERR_SCENE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fog_follows_exp2_of_the_depth_difference),
        cmocka_unit_test(test_zero_fog_density_leaves_the_background_bit_for_bit),
        cmocka_unit_test(test_dense_fog_gives_the_fog_colour),
        cmocka_unit_test(test_absorption_subtracts_the_inverse_water_colour),
        cmocka_unit_test(test_alpha_blends_the_lit_surface_over_the_background),
        cmocka_unit_test(test_fresnel_raises_alpha_at_grazing_angles),
        cmocka_unit_test(test_depth_colour_goes_from_shallow_to_deep),
        cmocka_unit_test(test_colour_ramp_is_read_at_the_rounded_fraction),
        cmocka_unit_test(test_refraction_shifts_the_background_by_whole_pixels),
        cmocka_unit_test(test_refraction_shrinks_in_shallow_water),
        cmocka_unit_test(test_two_normal_maps_add),
        cmocka_unit_test(test_refraction_falls_back_when_the_sample_is_in_front),
        cmocka_unit_test(test_nearest_water_wins_and_reads_only_the_opaque),
        cmocka_unit_test(test_specular_on_a_flat_surface),
        cmocka_unit_test(test_specular_uses_the_object_tangent_frame),
        cmocka_unit_test(test_foam_where_the_texture_reaches_the_band),
        cmocka_unit_test(test_foam_lines_widen_the_band),
        cmocka_unit_test(test_foam_lines_move_with_time),
        cmocka_unit_test(test_panning_wraps_at_the_end_of_the_clock),
        cmocka_unit_test(test_sparkles_where_every_map_crosses_the_threshold),
        cmocka_unit_test(test_underwater_tint_grows_with_depth),
        cmocka_unit_test(test_underwater_depth_includes_the_water),
        cmocka_unit_test(test_underwater_distortion_shifts_whole_pixels),
        cmocka_unit_test(test_underwater_map_edges_take_the_texel_above),
        cmocka_unit_test(test_snapped_water_matches_the_unsnapped),
        cmocka_unit_test(test_water_missing_its_textures_is_rejected),
    };
    return cmocka_run_group_tests(tests, setup_floor_texture, NULL);
}
