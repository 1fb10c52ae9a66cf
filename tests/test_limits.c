/* test_fixed_limits.c: every helper of core/include/tarn/tarn_fixed.h, and the public functions
 * of core/ that no other suite drives to their limits, at zero, one, the largest and
 * smallest values of their types and the values just past each boundary they draw.
 * `make test` runs this file under UndefinedBehaviorSanitizer too, so an overflow at
 * a limit fails as surely as a wrong value. (tests/test_math.c does the same for
 * tarn_math.h's functions; test_raster.c for the frame's config limits.) */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <inttypes.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

#include "scene_load.h"
#include "tarn/tarn_math.h"
#include "tarn/tarn_panel.h"
#include "tarn/tarn_render.h"
#include "tarn_internal.h"

static void saturation_and_clamping(void **state)
{
    (void)state;
    assert_int_equal(tarn_sat_i64_to_i32(0), 0);
    assert_int_equal(tarn_sat_i64_to_i32(INT32_MAX), INT32_MAX);
    assert_int_equal(tarn_sat_i64_to_i32((int64_t)INT32_MAX + 1), INT32_MAX);
    assert_int_equal(tarn_sat_i64_to_i32(INT32_MIN), INT32_MIN);
    assert_int_equal(tarn_sat_i64_to_i32((int64_t)INT32_MIN - 1), INT32_MIN);
    assert_int_equal(tarn_sat_i64_to_i32(INT64_MAX), INT32_MAX);
    assert_int_equal(tarn_sat_i64_to_i32(INT64_MIN), INT32_MIN);
    assert_int_equal(tarn_clamp_i32(INT32_MIN, -5, 5), -5);
    assert_int_equal(tarn_clamp_i32(INT32_MAX, -5, 5), 5);
    assert_int_equal(tarn_clamp_i32(-5, -5, 5), -5);
    assert_int_equal(tarn_clamp_i32(5, -5, 5), 5);
    assert_int_equal(tarn_clamp_i32(0, INT32_MIN, INT32_MAX), 0);
}

static void rounding_shifts(void **state)
{
    (void)state;
    assert_true(tarn_round_shift_i64(12345, 0) == 12345);
    assert_true(tarn_round_shift_i64(1, 1) == 1);   /* 0.5 rounds up */
    assert_true(tarn_round_shift_i64(-1, 1) == 0);  /* -0.5 rounds up, to 0 */
    assert_true(tarn_round_shift_i64(-3, 1) == -1); /* -1.5 rounds up */
    assert_true(tarn_round_shift_i64(INT64_MAX, 1) == ((int64_t)1 << 62));
    assert_true(tarn_round_shift_i64(INT64_MIN, 1) == -((int64_t)1 << 62));
    assert_true(tarn_round_shift_i64(INT64_MAX, 62) == 2);
    assert_true(tarn_round_shift_i64(INT64_MIN, 62) == -2);
    assert_true(tarn_round_shift_i64(INT64_MAX, 63) == 1);
    assert_true(tarn_round_shift_i64(INT64_MIN, 63) == -1);
    assert_int_equal(tarn_floor_shift(0, 0), 0);
    assert_int_equal(tarn_floor_shift(-1, 1), -1);
    assert_int_equal(tarn_floor_shift(1, 1), 0);
    assert_int_equal(tarn_floor_shift(INT32_MAX, 31), 0);
    assert_int_equal(tarn_floor_shift(INT32_MIN, 31), -1);
    assert_int_equal(tarn_floor_shift(INT32_MIN, 0), INT32_MIN);
    assert_int_equal(tarn_floor_shift(INT32_MIN + 1, 30), -2);
}

static void q16_arithmetic(void **state)
{
    (void)state;
    assert_int_equal(tarn_q16_mul(TARN_Q16_ONE, TARN_Q16_ONE), TARN_Q16_ONE);
    assert_int_equal(tarn_q16_mul(0, TARN_Q16_MAX), 0);
    assert_int_equal(tarn_q16_mul(TARN_Q16_MAX, TARN_Q16_MAX), TARN_Q16_MAX);
    assert_int_equal(tarn_q16_mul(TARN_Q16_MIN, TARN_Q16_MIN), TARN_Q16_MAX);
    assert_int_equal(tarn_q16_mul(TARN_Q16_MIN, TARN_Q16_MAX), TARN_Q16_MIN);
    assert_int_equal(tarn_q16_mul(TARN_Q16_MIN, TARN_Q16_ONE), TARN_Q16_MIN);
    assert_int_equal(tarn_q16_mul(1, 1), 0); /* 2^-32 rounds to 0 */
    assert_int_equal(tarn_q16_mul(1, TARN_Q16_ONE / 2), 1); /* a half rounds up */
    assert_int_equal(tarn_q16_add(TARN_Q16_MAX, 1), TARN_Q16_MAX);
    assert_int_equal(tarn_q16_add(TARN_Q16_MIN, -1), TARN_Q16_MIN);
    assert_int_equal(tarn_q16_add(TARN_Q16_MAX, TARN_Q16_MIN), -1);
    assert_int_equal(tarn_q16_from_int(32767), 32767 * 65536);
    assert_int_equal(tarn_q16_from_int(32768), TARN_Q16_MAX);
    assert_int_equal(tarn_q16_from_int(-32768), TARN_Q16_MIN);
    assert_int_equal(tarn_q16_from_int(-32769), TARN_Q16_MIN);
    assert_int_equal(tarn_q16_from_int(INT32_MAX), TARN_Q16_MAX);
    assert_int_equal(tarn_q16_from_int(INT32_MIN), TARN_Q16_MIN);
}

static void bits(void **state)
{
    (void)state;
    assert_false(tarn_is_power_of_two(0));
    assert_true(tarn_is_power_of_two(1));
    assert_true(tarn_is_power_of_two(0x80000000u));
    assert_false(tarn_is_power_of_two(0x80000001u));
    assert_false(tarn_is_power_of_two(UINT32_MAX));
    assert_int_equal(tarn_clz32(0), 32);
    assert_int_equal(tarn_clz32(1), 31);
    assert_int_equal(tarn_clz32(UINT32_MAX), 0);
    assert_int_equal(tarn_clz32(0x7FFFFFFFu), 1);
    assert_int_equal(tarn_clz32(0x00010000u), 15);
    assert_int_equal(tarn_clz32(0x0000FFFFu), 16);
}

/* The table's count of leading zeros (the Cortex-M0's) is the instruction's, at each
 * power of two and its neighbours and at random. */
static void leading_zeros_by_table(void **state)
{
    (void)state;
    uint32_t seed = 777u;
    for (uint32_t k = 0; k < 96u + 1000000u; k++) {
        const uint32_t v = k < 96u ? (1u << (k / 3u % 32u)) + k % 3u - 1u : (seed = seed * 1664525u + 1013904223u) >> (k % 32u);
        if (tarn_clz32_by_table(v) != tarn_clz32(v))
            fail_msg("leading zeros of 0x%08x: %u by the table, %u by the instruction", v, tarn_clz32_by_table(v),
                     tarn_clz32(v));
    }
    assert_int_equal(tarn_clz32_by_table(0), 32);
}

/* The floor shift is the floor of v / 2^s at every shift, in the compiler's form
 * and in the portable one, at the edges of int32_t and at random: floor(v / 2^s)
 * is the q with q * 2^s <= v < (q + 1) * 2^s. */
static void floor_shift_forms(void **state)
{
    (void)state;
    static const int32_t edges[] = {0, 1, -1, 2, -2, 65535, -65536, -65537, INT32_MAX, INT32_MIN, INT32_MIN + 1};
    const size_t n = sizeof edges / sizeof edges[0];
    uint32_t seed = 777u;
    for (size_t k = 0; k < n + 100000u; k++) {
        const int32_t v = k < n ? edges[k] : (int32_t)(seed = seed * 1664525u + 1013904223u);
        for (unsigned s = 0; s < 32u; s++) {
            const int64_t q = tarn_floor_shift(v, s), portable = tarn_floor_shift_portable(v, s);
            const int64_t unit = (int64_t)1 << s;
            if (q != portable || q * unit > v || (q + 1) * unit <= v)
                fail_msg("floor(%" PRId32 " / 2^%u): %" PRId64 " by the shift, %" PRId64 " portably", v, s, q,
                         portable);
        }
    }
}

/* A by-halves high word `form` against the native product: every pair of `edges`,
 * then a million random operands below `bound` (0: any). */
static void assert_high_words(const char *what, uint32_t (*form)(uint32_t, uint32_t), const uint32_t *edges,
                              size_t n, uint32_t bound, uint32_t seed)
{
    for (size_t k = 0; k < n * n + 1000000u; k++) {
        uint32_t a, b;
        if (k < n * n) {
            a = edges[k / n];
            b = edges[k % n];
        } else {
            a = seed = seed * 1664525u + 1013904223u;
            b = seed = seed * 1664525u + 1013904223u;
            if (bound != 0u) {
                a %= bound;
                b %= bound;
            }
        }
        const uint32_t want = (uint32_t)(((uint64_t)a * b) >> 32), got = form(a, b);
        if (got != want) fail_msg("the high word of 0x%08x * 0x%08x %s is 0x%08x, not 0x%08x", a, b, what, got, want);
    }
}

static uint32_t by_halves(uint32_t a, uint32_t b)
{
    return tarn_mul_hi_u32_by_halves(a, b);
}

static uint32_t small_by_halves(uint32_t a, uint32_t b)
{
    return tarn_mul_hi_u32_small_by_halves(a, b);
}

/* The Cortex-M0's high word (four 16x16 products and their carries) is the native
 * product's, at the carries' edges and at random. */
static void high_word_by_halves(void **state)
{
    (void)state;
    static const uint32_t edges[] = {0u, 1u, 0xFFFFu, 0x10000u, 0x1FFFFu, 0x7FFFFFFFu, 0x80000000u, 0xFFFF0000u,
                                     0xFFFF0001u, UINT32_MAX - 1u, UINT32_MAX};
    assert_high_words("by halves", by_halves, edges, sizeof edges / sizeof edges[0], 0u, 12345u);
}

/* The Cortex-M0's high word without a carry (tarn_mul_hi_u32_small) is the native
 * product's for operands below 2^31 + 2^16, at their edges and at random. */
static void high_word_of_small_operands_by_halves(void **state)
{
    (void)state;
    static const uint32_t edges[] = {0u, 1u, 0xFFFFu, 0x10000u, 0x3FFFFFFFu, 0x40000000u, 0x40007FFFu,
                                     0x7FFFFFFFu, 0x80000000u, 0x8000FFFEu, 0x8000FFFFu};
    assert_high_words("by halves without a carry", small_by_halves, edges, sizeof edges / sizeof edges[0],
                      0x8001FFFFu, 4242u);
}

/* The Cortex-M0's sum of two products of factors within +-2^30 is the native one,
 * at the factors' edges and at random. */
static void sum_of_products_by_halves(void **state)
{
    (void)state;
    static const int32_t edges[] = {0, 1, -1, 0xFFFF, 0x10000, -0x10000, -0x10001, (1 << 30) - 1, 1 << 30,
                                    -(1 << 30), -(1 << 30) + 1};
    const size_t n = sizeof edges / sizeof edges[0];
    uint32_t seed = 777u;
    for (size_t k = 0; k < n * n * n * n + 1000000u; k++) {
        int32_t f[4];
        for (int c = 0; c < 4; c++) {
            if (k < n * n * n * n) {
                size_t index = k;
                for (int d = 0; d < c; d++) index /= n;
                f[c] = edges[index % n];
            } else {
                seed = seed * 1664525u + 1013904223u;
                f[c] = (int32_t)(seed % ((1u << 31) + 1u)) - (1 << 30);
            }
        }
        const int64_t want = (int64_t)f[0] * f[1] + (int64_t)f[2] * f[3];
        const int64_t got = tarn_dot2_i30_wide_by_halves(f[0], f[1], f[2], f[3]);
        if (got != want)
            fail_msg("%" PRId32 " * %" PRId32 " + %" PRId32 " * %" PRId32 " by halves is %" PRId64 ", not %" PRId64,
                     f[0], f[1], f[2], f[3], got, want);
    }
}

/* The low word of a rounding shift, at every shift, is the whole shift's: at the
 * edges of int64_t and its words, and at a million random values. */
static void low_word_of_rounding_shifts(void **state)
{
    (void)state;
    static const int64_t edges[] = {INT64_MIN, INT64_MIN + 1, -((int64_t)1 << 32) - 1, -((int64_t)1 << 32),
                                    -((int64_t)1 << 31), -2, -1, 0, 1, ((int64_t)1 << 31) - 1,
                                    ((int64_t)1 << 32) + 1, INT64_MAX - 1, INT64_MAX};
    const size_t n = sizeof edges / sizeof edges[0];
    uint32_t seed = 777u;
    for (size_t k = 0; k < n + 1000000u; k++) {
        int64_t v = k < n ? edges[k] : 0;
        if (k >= n) {
            const uint32_t high = seed = seed * 1664525u + 1013904223u;
            const uint32_t low = seed = seed * 1664525u + 1013904223u;
            v = (int64_t)(((uint64_t)high << 32) | low);
        }
        for (unsigned shift = 0; shift < 64u; shift++) {
            const uint32_t want = (uint32_t)tarn_round_shift_i64(v, shift);
            const uint32_t got = tarn_round_shift_low32((uint64_t)v, shift);
            if (got != want)
                fail_msg("the low word of %lld rounded down %u bits is 0x%08x, not 0x%08x", (long long)v, shift, got,
                         want);
        }
    }
}

/* Every position of `mesh` and the coordinates' edges in each combination: the same
 * view position whole (a core with 64-bit products) and by halves (the Cortex-M0's). */
static void positions_agree(const tarn_object_xform *xform, const tarn_mesh *mesh, const char *what)
{
    static const int32_t edges[] = {INT32_MIN, INT32_MIN + 1, -65537, -65536, -1, 0, 1, 65535, 65536, INT32_MAX};
    const size_t n = sizeof edges / sizeof edges[0];
    for (size_t k = 0; k < mesh->vertex_count + n * n * n; k++) {
        const tarn_vec3 p = k < mesh->vertex_count ? mesh->positions[k]
                                                   : (tarn_vec3){edges[(k - mesh->vertex_count) / (n * n)],
                                                                 edges[(k - mesh->vertex_count) / n % n],
                                                                 edges[(k - mesh->vertex_count) % n]};
        tarn_view_vertex whole, halves;
        tarn__vertex_position(xform, &p, &whole);
        tarn__vertex_position_by_halves(xform, &p, &halves);
        if (whole.x != halves.x || whole.y != halves.y || whole.d != halves.d)
            fail_msg("%s, position (%d, %d, %d): (%d, %d, %d) whole, (%d, %d, %d) by halves", what, p.x, p.y, p.z,
                     whole.x, whole.y, whole.d, halves.x, halves.y, halves.d);
    }
}

/* The vertex transform by halves is the whole one's, for the orbiting pond's objects
 * seen at three times, as they are and scaled and moved to the extremes. */
static void vertex_position_by_halves(void **state)
{
    (void)state;
    tarn_loaded_scene s;
    tarn_error err;
    if (tarn_scene_load("scenes/pond-orbit.json", &s, &err) != 0) fail_msg("%s", err.message);
    static const tarn_q16 scales[] = {65536, 1, 1 << 24, INT32_MAX};
    static const int32_t places[] = {0, -(1 << 30), INT32_MAX};
    for (uint32_t time_ms = 0; time_ms <= 5000; time_ms += 2500) {
        const tarn_frame_config config = {s.width, s.height, tarn_quality_preset(TARN_PRESET_EXACT), time_ms};
        tarn_view view;
        tarn__view_setup(&s.scene, &config, &view);
        for (uint32_t i = 0; i < s.scene.object_count; i++)
            for (size_t k = 0; k < sizeof scales / sizeof scales[0]; k++) {
                tarn_object object = s.scene.objects[i];
                object.scale = scales[k];
                object.position.x = object.position.z = places[k % 3];
                tarn_object_xform xform;
                tarn__object_xform_setup(&view, &object, &xform);
                char what[64];
                snprintf(what, sizeof what, "object %u, scale %d, %u ms", (unsigned)i, scales[k], (unsigned)time_ms);
                positions_agree(&xform, object.mesh, what);
            }
    }
    tarn_scene_free(&s);
}

static void products(void **state)
{
    (void)state;
    assert_int_equal(tarn_mul_hi_u32(0, UINT32_MAX), 0);
    assert_int_equal(tarn_mul_hi_u32(1, UINT32_MAX), 0);
    assert_int_equal(tarn_mul_hi_u32(UINT32_MAX, UINT32_MAX), UINT32_MAX - 1u);
    assert_int_equal(tarn_mul_hi_u32(0x80000000u, 2), 1);
    assert_int_equal(tarn_mul_hi_s32_u32(INT32_MIN, UINT32_MAX), INT32_MIN); /* floor(-2^31 + 1/2) */
    assert_int_equal(tarn_mul_hi_s32_u32(INT32_MAX, UINT32_MAX), INT32_MAX - 1);
    assert_int_equal(tarn_mul_hi_s32_u32(-1, 1), -1); /* floor(-2^-32) */
    assert_int_equal(tarn_mul_hi_s32_u32(-1, 0), 0);
    assert_int_equal(tarn_mul_hi_s32_u32(0, UINT32_MAX), 0);
    assert_true(tarn_mul_u32_wide(UINT32_MAX, UINT32_MAX) == (uint64_t)UINT32_MAX * UINT32_MAX);
    assert_true(tarn_mul_u32_wide(0, UINT32_MAX) == 0);
    assert_true(tarn_mul_u32_wide(1, UINT32_MAX) == UINT32_MAX);
    assert_true(tarn_mul_u32_wide(0x10000u, 0x10000u) == ((uint64_t)1 << 32));
}

static void divisions_used_once(void **state)
{
    (void)state;
    assert_true(tarn_divide_once_i64(0, 7) == 0);
    assert_true(tarn_divide_once_i64(-7, 7) == -1);
    assert_true(tarn_divide_once_i64(-6, 7) == 0); /* toward zero, as C's / */
    assert_true(tarn_divide_once_i64(INT64_MAX, 1) == INT64_MAX);
    assert_true(tarn_divide_once_i64(INT64_MIN + 1, 1) == INT64_MIN + 1);
    assert_true(tarn_divide_once_i64(INT64_MAX, UINT32_MAX) == INT64_MAX / UINT32_MAX);
    assert_true(tarn_divide_once_i64(INT64_MIN + 1, UINT32_MAX) == (INT64_MIN + 1) / (int64_t)UINT32_MAX);
    assert_true(tarn_divide_once_i64(5, 0) == 5); /* a divisor of 0 acts as 1 */
    const tarn_divisor three = tarn_divisor_of(3);
    assert_true(tarn_divide_trunc_i64(-10, &three) == -3);
    assert_true(tarn_divide_trunc_i64(10, &three) == 3);
}

static void frame_helpers(void **state)
{
    (void)state;
    tarn_frame_config config = {1, 1, tarn_quality_default(), 0};
    assert_int_equal(tarn_guard_band_pixels(&config), 16);
    config.width = TARN_FRAME_SIZE_MAX;
    assert_int_equal(tarn_guard_band_pixels(&config), TARN_FRAME_SIZE_MAX / 4 + 16);
    config.height = TARN_FRAME_SIZE_MAX;
    config.width = 1;
    assert_int_equal(tarn_guard_band_pixels(&config), TARN_FRAME_SIZE_MAX / 4 + 16);
    for (int status = TARN_OK; status <= TARN_ERR_SINK; status++) {
        assert_non_null(tarn_status_text((tarn_status)status));
        assert_string_not_equal(tarn_status_text((tarn_status)status), "unknown status");
    }
    assert_string_equal(tarn_status_text((tarn_status)99), "unknown status");
    tarn_panel panel = tarn_panel_preset(TARN_PANEL_ILI9341_320X240, 0);
    assert_int_equal(tarn_panel_band_bytes(&panel, 64), 2u * 320u * 64u);
    assert_int_equal(tarn_panel_band_bytes(NULL, 64), 0);
}

static void refraction_reach(void **state)
{
    (void)state;
    tarn_water water = {0};
    assert_int_equal(tarn_water_reach_pixels(NULL, 240), 0);
    assert_int_equal(tarn_water_reach_pixels(&water, 240), 0); /* no refraction */
    water.features = TARN_WATER_REFRACTION;
    assert_int_equal(tarn_water_reach_pixels(&water, 240), 1); /* only the rounding */
    water.refraction = TARN_Q16_ONE;
    water.normal_xy_max = TARN_Q16_ONE;
    assert_int_equal(tarn_water_reach_pixels(&water, TARN_FRAME_SIZE_MAX), TARN_FRAME_SIZE_MAX + 1);
    water.refraction = INT32_MAX; /* past the range: the same as 1 */
    water.normal_xy_max = INT32_MAX;
    assert_int_equal(tarn_water_reach_pixels(&water, TARN_FRAME_SIZE_MAX), TARN_FRAME_SIZE_MAX + 1);
    water.refraction = INT32_MIN; /* below it: the same as 0 */
    assert_int_equal(tarn_water_reach_pixels(&water, TARN_FRAME_SIZE_MAX), 1);
    assert_int_equal(tarn_water_reach_pixels(&water, 0), 1);
}

/* The density times the cut depth, in 64 bits, saturated as the core saturates. */
static uint32_t cut_product(uint32_t rate, uint32_t x, unsigned bits)
{
    const unsigned cut = 16u - bits;
    const uint64_t product = ((uint64_t)rate * (x >> cut << cut)) >> 16;
    return product > INT32_MAX ? (uint32_t)INT32_MAX : (uint32_t)product;
}

/* Fog's exp2 argument at every precision: exactly the density times the cut depth,
 * through the one-multiply path and through the wide one, up to saturation. */
static void fog_argument(void **state)
{
    (void)state;
    const uint32_t values[] = {0, 1, 255, 256, 9830, 65535, 65536, 1u << 20, 16777215, 16777216,
                               (uint32_t)INT32_MAX, 4194304 /* density 64, the scene maximum */};
    const size_t n = sizeof values / sizeof values[0];
    for (unsigned bits = TARN_FOG_ARGUMENT_BITS_MIN; bits <= TARN_FOG_ARGUMENT_BITS_MAX; bits++)
        for (size_t a = 0; a < n; a++)
            for (size_t b = 0; b < n; b++)
                assert_int_equal(tarn__fog_argument_q16(values[a], values[b], bits),
                                 cut_product(values[a], values[b], bits));
    assert_int_equal(tarn__fog_argument_q16(9830, 3u << 16, 16), tarn__water_mul_q16(9830, 3u << 16));
    /* 4 bits: 3.03 units of water are cut to 3; density 0.15 (9830) stays whole */
    assert_int_equal(tarn__fog_argument_q16(9830, (3u << 16) + 2000u, 4), 9830u * 3u);
}

/* rate * x^2 / 2^32, exactly in 128 bits, saturated. */
static uint32_t squared_product(uint32_t rate, uint32_t x)
{
    const unsigned __int128 wide_x = x;
    const unsigned __int128 product = (rate * wide_x * wide_x) >> 32;
    return product > INT32_MAX ? (uint32_t)INT32_MAX : (uint32_t)product;
}

/* Squared absorption's exp2 argument: within 2^-27 of the exact product (and one
 * unit for the truncation) over the whole range of depths and rates, saturated only
 * where the product passes INT32_MAX; a weak rate keeps growing past x = 181, where
 * x^2 alone leaves Q16.16. */
static void squared_argument(void **state)
{
    (void)state;
    const uint32_t values[] = {0, 1, 255, 256, 7, 9830, 65535, 65536, 181u << 16, 182u << 16, 1u << 20,
                               16777215, 16777216, 600u << 16, (uint32_t)INT32_MAX, 4194304};
    const size_t n = sizeof values / sizeof values[0];
    for (size_t a = 0; a < n; a++)
        for (size_t b = 0; b < n; b++) {
            const uint32_t exact = squared_product(values[a], values[b]);
            const uint32_t got = tarn__squared_argument_q16(values[a], values[b]);
            assert_true(got <= exact && exact - got <= (exact >> 27) + 1u);
        }
    /* strength 0.0001 (7) at 400 units: 7 * 400^2 / 65536 = 17.09, where x^2 alone saturates */
    assert_int_equal(tarn__squared_argument_q16(7, 400u << 16) >> 8, (7u * 160000u * 256u) >> 16);
    assert_int_equal(tarn__squared_argument_q16(4194304, (uint32_t)INT32_MAX), INT32_MAX);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(saturation_and_clamping),
        cmocka_unit_test(rounding_shifts),
        cmocka_unit_test(q16_arithmetic),
        cmocka_unit_test(bits),
        cmocka_unit_test(leading_zeros_by_table),
        cmocka_unit_test(floor_shift_forms),
        cmocka_unit_test(high_word_by_halves),
        cmocka_unit_test(high_word_of_small_operands_by_halves),
        cmocka_unit_test(sum_of_products_by_halves),
        cmocka_unit_test(low_word_of_rounding_shifts),
        cmocka_unit_test(vertex_position_by_halves),
        cmocka_unit_test(products),
        cmocka_unit_test(divisions_used_once),
        cmocka_unit_test(frame_helpers),
        cmocka_unit_test(refraction_reach),
        cmocka_unit_test(fog_argument),
        cmocka_unit_test(squared_argument),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
