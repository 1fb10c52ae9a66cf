/* test_reference.c: the float reference renderer and the image metrics, on tiny
 * hand-made scenes whose right answer can be worked out on paper.
 *
 * Every scene is seen by the same camera: at the origin, looking down -z, 90 degree
 * vertical field of view, on a 16x16 frame, so focal = 8 pixels and a point at depth
 * d with screen position (sx, sy) sits at world ((sx-8)*d/8, (8-sy)*d/8, -d). The
 * AT_SCREEN macro places vertices that way, so coverage can be stated in pixels. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compare.h"
#include "reference.h"
#include "tarn/tarn_render.h"

#define W 16
#define H 16
#define HALF 8.0
#define SUBPIXEL_BITS 4

#define Q(v) ((tarn_q16)((v) * 65536.0))
#define VEC(x, y, z) { Q(x), Q(y), Q(z) }
#define AT_SCREEN(sx, sy, d) VEC(((sx) - HALF) * (d) / HALF, (HALF - (sy)) * (d) / HALF, -(d))
#define IDENTITY { { Q(1), 0, 0 }, { 0, Q(1), 0 }, { 0, 0, Q(1) } }

#define RED 0xFF0000u
#define GREEN 0x00FF00u
#define BACKGROUND 0x102030u

/* Enough normals facing the camera for any mesh here. */
static const tarn_vec3 facing[8] = {
    VEC(0, 0, 1), VEC(0, 0, 1), VEC(0, 0, 1), VEC(0, 0, 1),
    VEC(0, 0, 1), VEC(0, 0, 1), VEC(0, 0, 1), VEC(0, 0, 1),
};

static const tarn_material white_two_sided = { 0xFFFFFF, NULL, TARN_CULL_NONE, 1, NULL };

static uint8_t rgb[W * H * 3];
static uint8_t covered[W * H];

/* ---- scene and rendering helpers ---------------------------------------------- */

static tarn_object object_of(const tarn_mesh *mesh, const tarn_material *material)
{
    tarn_object obj = { mesh, material, VEC(0, 0, 0), IDENTITY, Q(1), NULL, NULL };
    return obj;
}

static tarn_scene scene_of(const tarn_object *objects, uint16_t count)
{
    tarn_scene scene = {
        objects, count,
        { VEC(0, 0, 0), VEC(0, 0, -1), Q(90), Q(1), Q(100) },
        { VEC(0, 0, 1), 0xFFFFFF, 0x000000 },
        BACKGROUND,
        NULL,
        NULL,
        NULL,
        NULL,
    };
    return scene;
}

static int render_mode(const tarn_scene *scene, int snapped)
{
    tarn_reference_options opt = { .geometry = snapped ? TARN_REF_CORE_TRIANGLES : TARN_REF_CONTINUOUS, .subpixel_bits = SUBPIXEL_BITS };
    return tarn_reference_render(scene, W, H, &opt, rgb, covered);
}

static void render(const tarn_scene *scene)
{
    assert_int_equal(render_mode(scene, 0), TARN_OK);
}

static void render_mesh(const tarn_mesh *mesh, const tarn_material *material)
{
    tarn_object obj = object_of(mesh, material);
    tarn_scene scene = scene_of(&obj, 1);
    render(&scene);
}

/* The rasterization rules decide pixel centres that lie exactly on an edge: only on
 * a grid do such ties happen, so those tests draw the core's triangles, whose
 * corners here land exactly on the grid. */
static void render_mesh_on_grid(const tarn_mesh *mesh, const tarn_material *material)
{
    tarn_object obj = object_of(mesh, material);
    tarn_scene scene = scene_of(&obj, 1);
    assert_int_equal(render_mode(&scene, 1), TARN_OK);
}

/* The mesh made of triangle `t` of `mesh` alone. */
static tarn_mesh single_triangle(const tarn_mesh *mesh, unsigned t)
{
    tarn_mesh one = *mesh;
    one.indices = mesh->indices + 3 * t;
    one.triangle_count = 1;
    return one;
}

static const uint8_t *pixel(int i, int j)
{
    return rgb + 3 * (j * W + i);
}

static void assert_pixel(int i, int j, uint32_t expected)
{
    const uint8_t *p = pixel(i, j);
    uint32_t got = (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
    if (got != expected) fail_msg("pixel (%d,%d) is %06X, expected %06X", i, j, got, expected);
}

typedef int (*coverage_rule)(int i, int j);

static void assert_coverage(const uint8_t *mask, coverage_rule expected)
{
    int wrong = 0;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++)
            if (!mask[j * W + i] != !expected(i, j)) {
                print_error("pixel (%d,%d): covered %d, expected %d\n", i, j, mask[j * W + i],
                            expected(i, j));
                wrong++;
            }
    assert_int_equal(wrong, 0);
}

/* ---- coverage and the top-left rule -------------------------------------------- */

/* Three right triangles whose edges run through pixel centres: each edge kind
 * (top, left, right, bottom, diagonal left, diagonal right) has centres exactly on
 * it. Each is listed in both windings; with culling off both must cover the same. */
static const tarn_vec3 corner_positions[] = {
    AT_SCREEN(2.5, 2.5, 2), AT_SCREEN(10.5, 2.5, 2), AT_SCREEN(2.5, 10.5, 2),
    AT_SCREEN(10.5, 10.5, 2),
};

/* top edge (inclusive), left edge (inclusive), hypotenuse a right edge (exclusive) */
static int upper_left_rule(int i, int j)
{
    return i >= 2 && j >= 2 && i + j <= 11;
}

/* top edge (inclusive), right edge (exclusive), diagonal a left edge (inclusive) */
static int upper_right_rule(int i, int j)
{
    return i <= 9 && j >= 2 && j <= i;
}

/* bottom edge (exclusive), left edge (inclusive), diagonal a right edge (exclusive) */
static int lower_left_rule(int i, int j)
{
    return i >= 2 && j <= 9 && j > i;
}

static void check_corner_triangle(const uint16_t indices[6], coverage_rule rule)
{
    for (unsigned t = 0; t < 2; t++) {
        tarn_mesh mesh = { corner_positions, facing, NULL, NULL, indices + 3 * t, 4, 1, NULL, 0, NULL };
        render_mesh_on_grid(&mesh, &white_two_sided);
        assert_coverage(covered, rule);
    }
}

static void test_top_left_rule_on_pixel_centres(void **state)
{
    (void)state;
    static const uint16_t upper_left[6] = { 0, 1, 2, 0, 2, 1 };
    static const uint16_t upper_right[6] = { 0, 1, 3, 0, 3, 1 };
    static const uint16_t lower_left[6] = { 2, 3, 0, 2, 0, 3 };
    check_corner_triangle(upper_left, upper_left_rule);
    check_corner_triangle(upper_right, upper_right_rule);
    check_corner_triangle(lower_left, lower_left_rule);
}

static void test_covered_pixels_take_colour_and_others_background(void **state)
{
    (void)state;
    static const uint16_t indices[3] = { 0, 2, 1 };
    static const tarn_material red = { RED, NULL, TARN_CULL_NONE, 1, NULL };
    tarn_mesh mesh = { corner_positions, facing, NULL, NULL, indices, 4, 1, NULL, 0, NULL };
    render_mesh_on_grid(&mesh, &red);
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) assert_pixel(i, j, upper_left_rule(i, j) ? RED : BACKGROUND);
}

/* Renders every triangle of `mesh` alone, adds up how often each pixel is drawn. */
static void count_draws(const tarn_mesh *mesh, uint8_t counts[W * H])
{
    memset(counts, 0, W * H);
    for (unsigned t = 0; t < mesh->triangle_count; t++) {
        tarn_mesh one = single_triangle(mesh, t);
        render_mesh_on_grid(&one, &white_two_sided);
        for (int p = 0; p < W * H; p++) counts[p] += covered[p];
    }
}

static void assert_each_drawn_at_most_once(const uint8_t counts[W * H])
{
    for (int p = 0; p < W * H; p++)
        if (counts[p] > 1) fail_msg("pixel (%d,%d) drawn %d times", p % W, p / W, counts[p]);
}

/* A diamond of four triangles around a centre vertex, all edges through pixel
 * centres: the inner edges are shared horizontal and vertical ones. */
static const tarn_vec3 diamond_positions[] = {
    AT_SCREEN(8.5, 8.5, 2), AT_SCREEN(8.5, 1.5, 2), AT_SCREEN(15.5, 8.5, 2),
    AT_SCREEN(8.5, 15.5, 2), AT_SCREEN(1.5, 8.5, 2),
};

/* Outer edges: the two on the left own their centres, the two on the right do not. */
static int diamond_rule(int i, int j)
{
    int dx = i - 8, dy = j - 8;
    int taxicab = abs(dx) + abs(dy);
    return taxicab < 7 || (taxicab == 7 && dx < 0);
}

static void test_shared_edges_draw_each_pixel_once(void **state)
{
    (void)state;
    static const uint16_t fan[12] = { 0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1 };
    tarn_mesh mesh = { diamond_positions, facing, NULL, NULL, fan, 5, 4, NULL, 0, NULL };
    uint8_t counts[W * H];
    count_draws(&mesh, counts);
    assert_each_drawn_at_most_once(counts);
    assert_coverage(counts, diamond_rule);
}

/* A quad off the grid, split along either diagonal: the two halves never overlap
 * and together cover the same pixels whichever diagonal splits it. */
static void test_quad_split_either_way_covers_the_same(void **state)
{
    (void)state;
    static const tarn_vec3 quad[] = {
        AT_SCREEN(1.5, 1.5, 2), AT_SCREEN(14.25, 2.75, 3), AT_SCREEN(13.5, 13.5, 2),
        AT_SCREEN(2.125, 12.0, 1.5),
    };
    static const uint16_t split_02[6] = { 0, 1, 2, 0, 2, 3 };
    static const uint16_t split_13[6] = { 0, 1, 3, 1, 2, 3 };
    tarn_mesh mesh_02 = { quad, facing, NULL, NULL, split_02, 4, 2, NULL, 0, NULL };
    tarn_mesh mesh_13 = { quad, facing, NULL, NULL, split_13, 4, 2, NULL, 0, NULL };
    uint8_t counts_02[W * H], counts_13[W * H];
    count_draws(&mesh_02, counts_02);
    count_draws(&mesh_13, counts_13);
    assert_each_drawn_at_most_once(counts_02);
    assert_each_drawn_at_most_once(counts_13);
    assert_memory_equal(counts_02, counts_13, W * H);
}

static void test_zero_area_triangle_draws_nothing(void **state)
{
    (void)state;
    static const tarn_vec3 line[] = {
        AT_SCREEN(1.5, 1.5, 2), AT_SCREEN(8.5, 8.5, 2), AT_SCREEN(14.5, 14.5, 2),
    };
    static const uint16_t indices[3] = { 0, 1, 2 };
    tarn_mesh mesh = { line, facing, NULL, NULL, indices, 3, 1, NULL, 0, NULL };
    render_mesh_on_grid(&mesh, &white_two_sided);
    for (int p = 0; p < W * H; p++) assert_int_equal(covered[p], 0);
}

/* An edge whose ends lie 2^20 pixels off-screen and which passes 1/16 pixel below
 * the centre P of pixel (8,8): the reference clips it to its guard band before
 * projecting, and what is left must still put P above the edge, so in the triangle
 * above it and not in the one below. */
#define FAR_OFF 1048576.0 /* 2^20 pixels */
#define BELOW_P (1.0 / 16)
static const tarn_vec3 near_miss_positions[] = {
    AT_SCREEN(8.5 - FAR_OFF, 8.5 - FAR_OFF + BELOW_P, 1.0 / 256),
    AT_SCREEN(8.5 + FAR_OFF, 8.5 + FAR_OFF + BELOW_P, 1.0 / 256),
    AT_SCREEN(2.5, 14.5, 2), /* below the edge */
    AT_SCREEN(14.5, 2.5, 2), /* above it */
};

static void test_far_off_screen_edges_keep_their_place(void **state)
{
    (void)state;
    static const uint16_t below_then_above[6] = { 0, 1, 2, 0, 1, 3 };
    tarn_mesh mesh = { near_miss_positions, facing, NULL, NULL, below_then_above, 4, 2, NULL, 0, NULL };
    tarn_object obj = object_of(&mesh, &white_two_sided);
    tarn_scene scene = scene_of(&obj, 1);
    scene.camera.near = 1; /* 1/65536 */
    int centre_drawn_by[2];
    for (unsigned t = 0; t < 2; t++) {
        tarn_mesh one = single_triangle(&mesh, t);
        obj.mesh = &one;
        render(&scene);
        centre_drawn_by[t] = covered[8 * W + 8];
    }
    if (centre_drawn_by[0] != 0 || centre_drawn_by[1] != 1)
        fail_msg("the centre of pixel (8,8) was drawn by the triangle below the edge: %d, above it: %d",
                 centre_drawn_by[0], centre_drawn_by[1]);
}

/* A wall 4000 wide at depth 2 fills the frame: its corners land far off-screen,
 * where whole Q1.30 depths (2^29) once took the exact depth's sum of edge values
 * times depths past 64 bits. Every pixel is covered. */
static void test_huge_triangles_near_the_eye_cover_every_pixel(void **state)
{
    (void)state;
    static const tarn_vec3 wall[] = { VEC(-2000, -2000, -2), VEC(2000, -2000, -2), VEC(-2000, 2000, -2),
                                      VEC(2000, 2000, -2) };
    static const uint16_t quad[6] = { 0, 1, 2, 2, 1, 3 };
    tarn_mesh mesh = { wall, facing, NULL, NULL, quad, 4, 2, NULL, 0, NULL };
    render_mesh(&mesh, &white_two_sided);
    for (int p = 0; p < W * H; p++) assert_int_equal(covered[p], 1);
}

/* ---- depth test and culling ------------------------------------------------------ */

/* Two big overlapping triangles: 0-2 near (depth 2) red, 3-5 far (depth 4) green,
 * 6-8 red again at the far one's depth. */
static const tarn_vec3 layered_positions[] = {
    AT_SCREEN(0, 0, 2), AT_SCREEN(16, 0, 2), AT_SCREEN(0, 16, 2),
    AT_SCREEN(0, 0, 4), AT_SCREEN(16, 0, 4), AT_SCREEN(0, 16, 4),
    AT_SCREEN(0, 0, 4), AT_SCREEN(16, 0, 4), AT_SCREEN(0, 16, 4),
};
static const uint32_t layered_colours[] = {
    RED, RED, RED, GREEN, GREEN, GREEN, RED, RED, RED,
};

static void render_layers(const uint16_t indices[6])
{
    tarn_mesh mesh = { layered_positions, facing, NULL, layered_colours, indices, 9, 2, NULL, 0, NULL };
    render_mesh(&mesh, &white_two_sided);
}

static void test_nearer_triangle_wins_in_either_order(void **state)
{
    (void)state;
    static const uint16_t near_first[6] = { 0, 1, 2, 3, 4, 5 };
    static const uint16_t far_first[6] = { 3, 4, 5, 0, 1, 2 };
    render_layers(near_first);
    assert_pixel(4, 4, RED);
    render_layers(far_first);
    assert_pixel(4, 4, RED);
}

static void test_equal_depth_keeps_the_earlier_triangle(void **state)
{
    (void)state;
    static const uint16_t green_first[6] = { 3, 4, 5, 6, 7, 8 };
    static const uint16_t red_first[6] = { 6, 7, 8, 3, 4, 5 };
    render_layers(green_first);
    assert_pixel(4, 4, GREEN);
    render_layers(red_first);
    assert_pixel(4, 4, RED);
}

/* Counter-clockwise seen from the camera (+z side): a front face. */
static const tarn_vec3 front_positions[] = { VEC(-1, -1, -2), VEC(1, -1, -2), VEC(0, 1, -2) };

static int centre_drawn(const uint16_t indices[3], uint8_t cull)
{
    tarn_material material = { 0xFFFFFF, NULL, cull, 1, NULL };
    tarn_mesh mesh = { front_positions, facing, NULL, NULL, indices, 3, 1, NULL, 0, NULL };
    render_mesh(&mesh, &material);
    return covered[8 * W + 8];
}

static void test_cull_modes_pick_the_drawn_side(void **state)
{
    (void)state;
    static const uint16_t front[3] = { 0, 1, 2 };
    static const uint16_t back[3] = { 0, 2, 1 };
    assert_int_equal(centre_drawn(front, TARN_CULL_BACK), 1);
    assert_int_equal(centre_drawn(back, TARN_CULL_BACK), 0);
    assert_int_equal(centre_drawn(front, TARN_CULL_FRONT), 0);
    assert_int_equal(centre_drawn(back, TARN_CULL_FRONT), 1);
    assert_int_equal(centre_drawn(front, TARN_CULL_NONE), 1);
    assert_int_equal(centre_drawn(back, TARN_CULL_NONE), 1);
}

/* Turning the object half a turn about y shows its back: culled. */
static void test_rotated_object_shows_its_back(void **state)
{
    (void)state;
    static const uint16_t front[3] = { 0, 1, 2 };
    static const tarn_material culled = { 0xFFFFFF, NULL, TARN_CULL_BACK, 1, NULL };
    tarn_mesh mesh = { front_positions, facing, NULL, NULL, front, 3, 1, NULL, 0, NULL };
    tarn_object obj = object_of(&mesh, &culled);
    const tarn_q16 half_turn_y[3][3] = { { Q(-1), 0, 0 }, { 0, Q(1), 0 }, { 0, 0, Q(-1) } };
    memcpy(obj.rotation, half_turn_y, sizeof obj.rotation);
    obj.position.z = Q(-4); /* the triangle lands at z = -4 + 2 */
    tarn_scene scene = scene_of(&obj, 1);
    render(&scene);
    assert_int_equal(covered[8 * W + 8], 0);
}

/* ---- clipping ------------------------------------------------------------------- */

/* A floor at y = -1 reaching behind the camera and far beyond it. On screen, depth d
 * on the floor is row sy = 8 + 8/d: near = 1.25 cuts at sy = 14.4, far = 4 at sy = 10,
 * so exactly the rows 10..13 have their centres between the planes. */
static int floor_rule(int i, int j)
{
    (void)i;
    return j >= 10 && j <= 13;
}

static void test_near_and_far_planes_cut_the_floor(void **state)
{
    (void)state;
    static const tarn_vec3 floor_positions[] = {
        VEC(-50, -1, 5), VEC(50, -1, 5), VEC(50, -1, -50), VEC(-50, -1, -50),
    };
    static const uint16_t indices[6] = { 0, 1, 2, 0, 2, 3 };
    tarn_mesh mesh = { floor_positions, facing, NULL, NULL, indices, 4, 2, NULL, 0, NULL };
    tarn_object obj = object_of(&mesh, &white_two_sided);
    tarn_scene scene = scene_of(&obj, 1);
    scene.camera.near = Q(1.25);
    scene.camera.far = Q(4);
    uint8_t counts[W * H];
    memset(counts, 0, sizeof counts);
    for (unsigned t = 0; t < 2; t++) {
        tarn_mesh one = single_triangle(&mesh, t);
        obj.mesh = &one;
        render(&scene);
        for (int p = 0; p < W * H; p++) counts[p] += covered[p];
    }
    assert_each_drawn_at_most_once(counts);
    assert_coverage(counts, floor_rule);
}

/* ---- perspective-correct interpolation ------------------------------------------ */

/* Barycentrics of where the ray through pixel centre (px, py) meets the triangle
 * (Moller-Trumbore): the ground truth for perspective-correct attributes. */
static void ray_barycentrics(const double v[3][3], double px, double py, double bary[3])
{
    double dir[3] = { (px - HALF) / HALF, (HALF - py) / HALF, -1 };
    double e1[3], e2[3], p[3], s[3], q[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = v[1][k] - v[0][k];
        e2[k] = v[2][k] - v[0][k];
        s[k] = -v[0][k]; /* ray origin (0,0,0) minus v0 */
    }
#define CROSS(out, a, b)                                                                  \
    (out[0] = a[1] * b[2] - a[2] * b[1], out[1] = a[2] * b[0] - a[0] * b[2],              \
     out[2] = a[0] * b[1] - a[1] * b[0])
#define DOT(a, b) (a[0] * b[0] + a[1] * b[1] + a[2] * b[2])
    CROSS(p, dir, e2);
    double det = DOT(e1, p);
    CROSS(q, s, e1);
    bary[1] = DOT(s, p) / det;
    bary[2] = DOT(dir, q) / det;
    bary[0] = 1 - bary[1] - bary[2];
#undef CROSS
#undef DOT
}

static void test_colours_interpolate_perspective_correctly(void **state)
{
    (void)state;
    /* vertices on the subpixel grid at depths 1.5, 4 and 2: snapping moves nothing */
    static const tarn_vec3 positions[] = {
        AT_SCREEN(2, 3, 1.5), AT_SCREEN(14, 5, 4), AT_SCREEN(6, 14, 2),
    };
    static const uint32_t colours[] = { 0xFF0000, 0x00FF00, 0x0000FF };
    static const uint16_t indices[3] = { 0, 1, 2 };
    tarn_mesh mesh = { positions, facing, NULL, colours, indices, 3, 1, NULL, 0, NULL };
    render_mesh(&mesh, &white_two_sided);

    double world[3][3];
    for (int v = 0; v < 3; v++) {
        world[v][0] = positions[v].x / 65536.0;
        world[v][1] = positions[v].y / 65536.0;
        world[v][2] = positions[v].z / 65536.0;
    }
    int drawn = 0;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            if (!covered[j * W + i]) continue;
            double bary[3];
            ray_barycentrics(world, i + 0.5, j + 0.5, bary);
            for (int c = 0; c < 3; c++) {
                double expected = 255.0 * bary[c];
                if (fabs(pixel(i, j)[c] - expected) > 0.5 + 1e-6)
                    fail_msg("pixel (%d,%d) channel %d is %d, expected %.4f", i, j, c,
                             pixel(i, j)[c], expected);
            }
            drawn++;
        }
    assert_true(drawn > 30);
}

/* ---- texturing ------------------------------------------------------------------ */

/* 4x4 texels, texel (x, y) = (60x, 60y, 7 + x + 4y): every texel distinct. */
static uint8_t texels[4 * 4 * 3];
static const tarn_texture texture4 = { 4, 4, texels, 0 };

static void fill_texels(void)
{
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            uint8_t *t = texels + 3 * (y * 4 + x);
            t[0] = (uint8_t)(60 * x);
            t[1] = (uint8_t)(60 * y);
            t[2] = (uint8_t)(7 + x + 4 * y);
        }
}

/* A quad filling the frame exactly at one depth, uv spanning [u0,u1] x [v0,v1]. */
static const tarn_vec3 screen_quad[] = {
    AT_SCREEN(0, 0, 2), AT_SCREEN(16, 0, 2), AT_SCREEN(16, 16, 2), AT_SCREEN(0, 16, 2),
};
static const uint16_t screen_quad_indices[6] = { 0, 3, 2, 0, 2, 1 }; /* front faces */

static void render_textured_quad(double u0, double v0, double u1, double v1, uint32_t tint)
{
    const tarn_uv uvs[4] = {
        { Q(u0), Q(v0) }, { Q(u1), Q(v0) }, { Q(u1), Q(v1) }, { Q(u0), Q(v1) },
    };
    tarn_material material = { tint, &texture4, TARN_CULL_BACK, 1, NULL };
    tarn_mesh mesh = { screen_quad, facing, uvs, NULL, screen_quad_indices, 4, 2, NULL, 0, NULL };
    fill_texels();
    render_mesh(&mesh, &material);
}

static int wrapped_texel(double coordinate)
{
    int t = (int)floor(coordinate * 4) % 4;
    return t < 0 ? t + 4 : t;
}

/* Each pixel centre's uv lies strictly inside a texel: texel * tint / 255 rounded. */
static void assert_textured_quad(double u0, double v0, double u1, double v1, uint32_t tint)
{
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            int tx = wrapped_texel(u0 + (u1 - u0) * (i + 0.5) / W);
            int ty = wrapped_texel(v0 + (v1 - v0) * (j + 0.5) / H);
            const uint8_t *t = texels + 3 * (ty * 4 + tx);
            for (int c = 0; c < 3; c++) {
                int tint_c = (int)(tint >> (16 - 8 * c) & 0xFF);
                int expected = (2 * t[c] * tint_c + 255) / 510; /* never a tie */
                if (pixel(i, j)[c] != expected)
                    fail_msg("pixel (%d,%d) channel %d is %d, expected %d (texel %d,%d)", i, j,
                             c, pixel(i, j)[c], expected, tx, ty);
            }
        }
}

static void test_textured_quad_samples_expected_texels(void **state)
{
    (void)state;
    render_textured_quad(0, 0, 1, 1, 0xFFFFFF);
    assert_textured_quad(0, 0, 1, 1, 0xFFFFFF);
    render_textured_quad(0, 0, 1, 1, 0x80FF40);
    assert_textured_quad(0, 0, 1, 1, 0x80FF40);
}

static void test_texture_coordinates_wrap_below_zero(void **state)
{
    (void)state;
    render_textured_quad(-1, -0.5, 1, 0.5, 0xFFFFFF);
    assert_textured_quad(-1, -0.5, 1, 0.5, 0xFFFFFF);
}

/* ---- lighting ------------------------------------------------------------------- */

typedef struct {
    tarn_vec3 light_direction;
    uint32_t light, ambient, material, vertex_colour;
    uint8_t unlit;
    uint32_t expected;
} lighting_case;

static void render_lit_quad(const lighting_case *lc, const tarn_object *obj_template)
{
    const uint32_t colours[4] = { lc->vertex_colour, lc->vertex_colour, lc->vertex_colour,
                                  lc->vertex_colour };
    tarn_material material = { lc->material, NULL, TARN_CULL_BACK, lc->unlit, NULL };
    tarn_mesh mesh = *obj_template->mesh;
    mesh.colours = colours;
    tarn_object obj = *obj_template;
    obj.mesh = &mesh;
    obj.material = &material;
    tarn_scene scene = scene_of(&obj, 1);
    scene.light.direction = lc->light_direction;
    scene.light.colour_rgb = lc->light;
    scene.light.ambient_rgb = lc->ambient;
    render(&scene);
}

/* shade = min(1, ambient/255 + light/255 * max(0, N.L)); lit = material * vertex / 255
 * * shade. The expected values are worked out by hand in the comments. */
static const lighting_case lighting_cases[] = {
    /* N.L = 1: R 255*(32+128)/255 = 160, G 128*96/255 = 48.19, B 64*64/255 = 16.06 */
    { VEC(0, 0, 1), 0x804020, 0x202020, 0xFF8040, 0xFFFFFF, 0, 0xA03010 },
    /* N.L = 0.5: R 255*96/255 = 96, G 128*64/255 = 32.13, B 64*48/255 = 12.05 */
    { VEC(0, 0.8660254, 0.5), 0x804020, 0x202020, 0xFF8040, 0xFFFFFF, 0, 0x60200C },
    /* light from behind, N.L < 0: ambient only: 32, 128*32/255 = 16.06, 64*32/255 = 8.03 */
    { VEC(0, 0, -1), 0x804020, 0x202020, 0xFF8040, 0xFFFFFF, 0, 0x201008 },
    /* ambient + light above 1 saturates: the base colour */
    { VEC(0, 0, 1), 0xFFFFFF, 0x808080, 0xFF8040, 0xFFFFFF, 0, 0xFF8040 },
    /* vertex colour: base (128, 128, 16.06); R 128*160/255 = 80.31, G 48.19, B 4.03 */
    { VEC(0, 0, 1), 0x804020, 0x202020, 0xFF8040, 0x80FF40, 0, 0x503004 },
    /* unlit: the light is ignored */
    { VEC(0, 0, -1), 0x804020, 0x202020, 0xFF8040, 0xFFFFFF, 1, 0xFF8040 },
};

static void assert_uniform_frame(uint32_t expected)
{
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) assert_pixel(i, j, expected);
}

static void test_lighting_values(void **state)
{
    (void)state;
    tarn_mesh mesh = { screen_quad, facing, NULL, NULL, screen_quad_indices, 4, 2, NULL, 0, NULL };
    tarn_object obj = object_of(&mesh, &white_two_sided);
    for (size_t k = 0; k < sizeof lighting_cases / sizeof lighting_cases[0]; k++) {
        render_lit_quad(&lighting_cases[k], &obj);
        assert_uniform_frame(lighting_cases[k].expected);
    }
}

/* The same quad as an object turned a quarter about y, scaled by 2 and moved:
 * world = position + 2 * R * p with R p = (p.z, p.y, -p.x), so p = (-w.z, w.y, w.x)
 * for a world offset w; normals (-1,0,0) turn to face the camera. Same pixels. */
static void test_object_transform_moves_positions_and_normals(void **state)
{
    (void)state;
    static const tarn_vec3 object_space[] = {
        VEC(0.5, 1, -1), VEC(0.5, 1, 1), VEC(0.5, -1, 1), VEC(0.5, -1, -1),
    };
    static const tarn_vec3 turned_normals[] = {
        VEC(-1, 0, 0), VEC(-1, 0, 0), VEC(-1, 0, 0), VEC(-1, 0, 0),
    };
    tarn_mesh mesh = { object_space, turned_normals, NULL, NULL, screen_quad_indices, 4, 2, NULL, 0, NULL };
    tarn_object obj = { &mesh, &white_two_sided, VEC(0, 0, -1),
                        { { 0, 0, Q(1) }, { 0, Q(1), 0 }, { Q(-1), 0, 0 } }, Q(2), NULL, NULL };
    render_lit_quad(&lighting_cases[0], &obj);
    assert_uniform_frame(lighting_cases[0].expected);
}

/* ---- errors --------------------------------------------------------------------- */

static void test_bad_input_is_rejected(void **state)
{
    (void)state;
    static const uint16_t past_the_end[3] = { 0, 1, 4 };
    tarn_mesh mesh = { corner_positions, facing, NULL, NULL, past_the_end, 4, 1, NULL, 0, NULL };
    tarn_object obj = object_of(&mesh, &white_two_sided);
    tarn_scene scene = scene_of(&obj, 1);
    assert_int_equal(render_mode(&scene, 0), TARN_ERR_SCENE);

    static const tarn_texture no_texels = { 4, 4, NULL, 0 };
    static const tarn_texture not_power_of_two = { 3, 4, texels, 0 };
    const tarn_texture *bad_textures[2] = { &no_texels, &not_power_of_two };
    for (int k = 0; k < 2; k++) {
        tarn_material material = { 0xFFFFFF, bad_textures[k], TARN_CULL_NONE, 1, NULL };
        tarn_mesh fine = single_triangle(&mesh, 0);
        fine.indices = screen_quad_indices;
        obj = object_of(&fine, &material);
        assert_int_equal(render_mode(&scene, 0), TARN_ERR_SCENE);
    }

    tarn_scene empty = scene_of(NULL, 0);
    tarn_reference_options opt = { .geometry = TARN_REF_CONTINUOUS, .subpixel_bits = SUBPIXEL_BITS };
    assert_int_equal(tarn_reference_render(&empty, 0, H, &opt, rgb, covered), TARN_ERR_CONFIG);
    opt.subpixel_bits = 9;
    assert_int_equal(tarn_reference_render(&empty, W, H, &opt, rgb, covered), TARN_ERR_CONFIG);
    empty.camera.far = empty.camera.near;
    opt.subpixel_bits = SUBPIXEL_BITS;
    assert_int_equal(tarn_reference_render(&empty, W, H, &opt, rgb, covered), TARN_ERR_SCENE);
}

/* ---- snapped mode: the core's triangles ----------------------------------------- */

/* The corner triangles' vertices sit on the subpixel grid, so the core's transform
 * snaps them to the same places: snapped mode must draw exactly the same image. */
static void test_snapped_mode_matches_on_grid_triangles(void **state)
{
    (void)state;
    static const uint16_t indices[6] = { 0, 2, 1, 1, 2, 3 };
    static const uint32_t colours[4] = { RED, GREEN, 0x0000FF, 0xFFFFFF };
    static const tarn_material material = { 0xFFFFFF, NULL, TARN_CULL_BACK, 1, NULL };
    tarn_mesh mesh = { corner_positions, facing, NULL, colours, indices, 4, 2, NULL, 0, NULL };
    tarn_object obj = object_of(&mesh, &material);
    tarn_scene scene = scene_of(&obj, 1);
    uint8_t unsnapped_rgb[sizeof rgb], unsnapped_covered[sizeof covered];
    render(&scene);
    memcpy(unsnapped_rgb, rgb, sizeof rgb);
    memcpy(unsnapped_covered, covered, sizeof covered);
    assert_int_equal(render_mode(&scene, 1), TARN_OK);
    assert_memory_equal(covered, unsnapped_covered, sizeof covered);
    tarn_compare_metrics m;
    tarn_compare_images(rgb, unsnapped_rgb, covered, unsnapped_covered, W, H, &m);
    assert_true(m.max_channel_error <= 1); /* the core's Q8.8 colours round once more */
}

/* In snapped mode the material still decides which side draws. */
static void test_snapped_mode_culls_back_faces(void **state)
{
    (void)state;
    static const uint16_t back[3] = { 0, 1, 2 }; /* clockwise seen from the camera */
    static const tarn_material material = { 0xFFFFFF, NULL, TARN_CULL_BACK, 1, NULL };
    tarn_mesh mesh = { corner_positions, facing, NULL, NULL, back, 4, 1, NULL, 0, NULL };
    tarn_object obj = object_of(&mesh, &material);
    tarn_scene scene = scene_of(&obj, 1);
    assert_int_equal(render_mode(&scene, 1), TARN_OK);
    for (int p = 0; p < W * H; p++) assert_int_equal(covered[p], 0);
}

/* ---- metrics -------------------------------------------------------------------- */

#define MW 4
#define MH 4

static void test_identical_images_have_no_error(void **state)
{
    (void)state;
    uint8_t a[MW * MH * 3];
    for (size_t k = 0; k < sizeof a; k++) a[k] = (uint8_t)(k * 37);
    tarn_compare_metrics m;
    tarn_compare_images(a, a, NULL, NULL, MW, MH, &m);
    assert_int_equal(m.max_channel_error, 0);
    assert_true(m.psnr_db == TARN_COMPARE_PSNR_MAX);
    assert_true(m.share_over2 == 0 && m.share_over8 == 0);
    assert_int_equal(m.coverage_mismatches, 0);
    assert_int_equal(m.pixels, MW * MH);
}

static void test_metrics_count_errors_per_pixel(void **state)
{
    (void)state;
    uint8_t a[MW * MH * 3], b[MW * MH * 3];
    memset(a, 100, sizeof a);
    memset(b, 100, sizeof b);
    b[3 * 5 + 1] = 103; /* pixel 5, green off by 3 */
    b[3 * 9 + 0] = 102; /* pixel 9, red off by 2: not over 2 */
    b[3 * 9 + 2] = 98;
    tarn_compare_metrics m;
    tarn_compare_images(a, b, NULL, NULL, MW, MH, &m);
    assert_int_equal(m.max_channel_error, 3);
    assert_true(fabs(m.share_over2 - 1.0 / 16) < 1e-12);
    assert_true(m.share_over8 == 0);
    /* MSE over 48 samples = (9 + 4 + 4) / 48 */
    double psnr = 10 * log10(255.0 * 255.0 / (17.0 / 48));
    assert_true(fabs(m.psnr_db - psnr) < 1e-9);

    b[3 * 2 + 2] = 91; /* off by 9 */
    tarn_compare_images(a, b, NULL, NULL, MW, MH, &m);
    assert_int_equal(m.max_channel_error, 9);
    assert_true(fabs(m.share_over2 - 2.0 / 16) < 1e-12);
    assert_true(fabs(m.share_over8 - 1.0 / 16) < 1e-12);
}

static void test_coverage_mismatches_are_counted(void **state)
{
    (void)state;
    uint8_t a[MW * MH * 3] = { 0 };
    uint8_t cov_a[MW * MH] = { 0 }, cov_b[MW * MH] = { 0 };
    cov_a[0] = 1;
    cov_b[0] = 1;
    cov_a[3] = 1;
    cov_b[7] = 1;
    tarn_compare_metrics m;
    tarn_compare_images(a, a, cov_a, cov_b, MW, MH, &m);
    assert_int_equal(m.coverage_mismatches, 2);
    tarn_compare_images(a, a, cov_a, NULL, MW, MH, &m);
    assert_int_equal(m.coverage_mismatches, 0);
}

static void test_heatmap_colours(void **state)
{
    (void)state;
    uint8_t a[MW * MH * 3], b[MW * MH * 3], heat[MW * MH * 3];
    uint8_t marked[MW * MH] = { 0 };
    memset(a, 100, sizeof a);
    memcpy(b, a, sizeof b);
    b[3 * 1] = 102;     /* error 2: blue */
    b[3 * 2 + 1] = 108; /* error 8: red */
    b[3 * 3 + 2] = 255; /* error 155: white */
    marked[4] = 1;      /* its surface differs: magenta */
    tarn_compare_heatmap(a, b, marked, MW, MH, heat);
    static const uint8_t expected[5][3] = {
        { 0, 0, 0 }, { 0, 0, 255 }, { 255, 0, 0 }, { 255, 255, 255 }, { 255, 0, 255 },
    };
    for (int p = 0; p < 5; p++) assert_memory_equal(heat + 3 * p, expected[p], 3);
    tarn_compare_heatmap(a, b, NULL, MW, MH, heat);
    assert_memory_equal(heat + 3 * 4, expected[0], 3);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_top_left_rule_on_pixel_centres),
        cmocka_unit_test(test_covered_pixels_take_colour_and_others_background),
        cmocka_unit_test(test_shared_edges_draw_each_pixel_once),
        cmocka_unit_test(test_quad_split_either_way_covers_the_same),
        cmocka_unit_test(test_zero_area_triangle_draws_nothing),
        cmocka_unit_test(test_far_off_screen_edges_keep_their_place),
        cmocka_unit_test(test_huge_triangles_near_the_eye_cover_every_pixel),
        cmocka_unit_test(test_nearer_triangle_wins_in_either_order),
        cmocka_unit_test(test_equal_depth_keeps_the_earlier_triangle),
        cmocka_unit_test(test_cull_modes_pick_the_drawn_side),
        cmocka_unit_test(test_rotated_object_shows_its_back),
        cmocka_unit_test(test_near_and_far_planes_cut_the_floor),
        cmocka_unit_test(test_colours_interpolate_perspective_correctly),
        cmocka_unit_test(test_textured_quad_samples_expected_texels),
        cmocka_unit_test(test_texture_coordinates_wrap_below_zero),
        cmocka_unit_test(test_lighting_values),
        cmocka_unit_test(test_object_transform_moves_positions_and_normals),
        cmocka_unit_test(test_bad_input_is_rejected),
        cmocka_unit_test(test_snapped_mode_matches_on_grid_triangles),
        cmocka_unit_test(test_snapped_mode_culls_back_faces),
        cmocka_unit_test(test_identical_images_have_no_error),
        cmocka_unit_test(test_metrics_count_errors_per_pixel),
        cmocka_unit_test(test_coverage_mismatches_are_counted),
        cmocka_unit_test(test_heatmap_colours),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
