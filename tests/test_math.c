/* test_math.c: core/'s fixed-point math against libm, over each whole input range.
 *
 * The sweeps are host/compare/accuracy_math.c's (the same numbers `tarn accuracy --math`
 * prints); this file asserts the error bounds documented in core/include/tarn/tarn_math.h, the
 * exact values at the limits, and that invalid knob values stay in bounds. Running
 * it under ASan + UBSan also checks every swept input for undefined behaviour and
 * out-of-bounds table reads. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <math.h>
#include <stdio.h>

#include <cmocka.h>

#include "accuracy_math.h"
#include "tarn_internal.h"
#include "tarn/tarn_math.h"
#include "tarn/tarn_render.h"

#define EXP2_CONFIGS 6 /* table sizes 8, 16, ..., 256 */

/* tarn_math.h's documented maxima, in Q0.16 LSBs, per table size 8..256. */
static const double exp2_nearest_max_lsb[EXP2_CONFIGS] = {5439, 2778, 1404, 706, 354, 177};
static const double exp2_linear_max_lsb[EXP2_CONFIGS] = {60, 15.4, 4.5, 1.7, 1.2, 1.0};

/* tarn_math.h's documented relative errors beyond rounding, per Newton step count,
 * for tarn_recip_u32 and tarn_recip_q30 alike. */
static const double recip_max_rel_excess[TARN_RECIP_STEPS_MAX + 1] = {1.96e-3, 3.82e-6, 9.4e-10};

static void assert_max_error(const char *what, tarn_math_error e, double max_lsb)
{
    if (e.max_abs_lsb <= max_lsb) return;
    print_error("%s: error %.4f LSB at input %lld, documented maximum %.4f\n", what,
                e.max_abs_lsb, (long long)e.worst_input, max_lsb);
    fail();
}

static void assert_max_rel_excess(const char *what, tarn_math_error e, double max_rel)
{
    if (e.max_rel_excess >= 0.0 && e.max_rel_excess <= max_rel) return;
    print_error("%s: relative error beyond rounding %.3g, documented maximum %.3g\n", what,
                e.max_rel_excess, max_rel);
    fail();
}

static tarn_exp2_config exp2_config(unsigned size_index, int interpolate)
{
    tarn_exp2_config config = {(uint16_t)(TARN_EXP2_ENTRIES_MIN << size_index), (uint8_t)interpolate};
    return config;
}

/* ---- exp2 --------------------------------------------------------------------------*/

static void exp2_sweeps_stay_within_documented_bounds(void **state)
{
    (void)state;
    for (int interpolate = 0; interpolate <= 1; interpolate++) {
        const double *bounds = interpolate ? exp2_linear_max_lsb : exp2_nearest_max_lsb;
        double coarser_max = 1e30;
        for (unsigned size = 0; size < EXP2_CONFIGS; size++) {
            tarn_exp2_config config = exp2_config(size, interpolate);
            tarn_math_error e = tarn_math_measure_exp2(config);
            char what[48];
            snprintf(what, sizeof what, "exp2 %u entries %s", config.entries,
                     interpolate ? "linear" : "nearest");
            assert_int_equal(e.samples, 18ul * 65536ul + 1ul); /* 0 down to -18.0 */
            assert_max_error(what, e, bounds[size]);
            /* more entries never make it worse */
            assert_true(e.max_abs_lsb <= coarser_max);
            coarser_max = e.max_abs_lsb;
        }
    }
}

static void exp2_limits(void **state)
{
    (void)state;
    for (unsigned size = 0; size < EXP2_CONFIGS; size++) {
        for (int interpolate = 0; interpolate <= 1; interpolate++) {
            tarn_exp2_config config = exp2_config(size, interpolate);
            assert_int_equal(tarn_exp2_neg_q16(0, config), 65536);
            assert_int_equal(tarn_exp2_neg_q16(1, config), 65536); /* positive x clamps */
            assert_int_equal(tarn_exp2_neg_q16(INT32_MAX, config), 65536);
            assert_int_equal(tarn_exp2_neg_q16(-65536, config), 32768);
            assert_int_equal(tarn_exp2_neg_q16(-16 * 65536, config), 1);
            assert_int_equal(tarn_exp2_neg_q16(-17 * 65536, config), 1); /* 0.5 rounds up */
            assert_int_equal(tarn_exp2_neg_q16(-18 * 65536, config), 0);
            assert_int_equal(tarn_exp2_neg_q16(-18 * 65536 - 1, config), 0);
            assert_int_equal(tarn_exp2_neg_q16(INT32_MIN + 1, config), 0);
            assert_int_equal(tarn_exp2_neg_q16(INT32_MIN, config), 0);
        }
        /* just below 0: linear follows 2^(-1/65536) = 65535.3, nearest-below stays at 1.0 */
        assert_int_equal(tarn_exp2_neg_q16(-1, exp2_config(size, 1)), 65535);
        assert_int_equal(tarn_exp2_neg_q16(-1, exp2_config(size, 0)), 65536);
    }
}

/* Outside the swept range every result is 0 (x < -18) or 65536 (x > 0); stepping
 * through it under UBSan also shows no shift reaches 32. */
static void exp2_outside_the_sweep_saturates(void **state)
{
    (void)state;
    tarn_exp2_config config = exp2_config(EXP2_CONFIGS - 1, 1);
    for (int64_t x = INT32_MIN; x < -18 * 65536; x += 4099) {
        assert_int_equal(tarn_exp2_neg_q16((tarn_q16)x, config), 0);
    }
    for (int64_t x = 1; x <= INT32_MAX; x += 4099) {
        assert_int_equal(tarn_exp2_neg_q16((tarn_q16)x, config), 65536);
    }
}

/* Invalid table sizes clamp into [8, 256] and round down to a power of two; any
 * non-zero `interpolate` means linear. Under ASan an out-of-bounds read would fail. */
static void exp2_invalid_config_uses_a_valid_table(void **state)
{
    (void)state;
    static const struct {
        uint16_t entries, behaves_as;
    } sizes[] = {{0, 8}, {1, 8}, {7, 8}, {9, 8}, {15, 8}, {100, 64}, {255, 128},
                 {257, 256}, {512, 256}, {1000, 256}, {UINT16_MAX, 256}};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        for (uint8_t interpolate = 0; interpolate <= 2; interpolate++) {
            tarn_exp2_config asked = {sizes[i].entries, interpolate};
            tarn_exp2_config valid = {sizes[i].behaves_as, interpolate != 0};
            for (int32_t x = 0; x >= -2 * 65536; x -= 7) {
                assert_int_equal(tarn_exp2_neg_q16(x, asked), tarn_exp2_neg_q16(x, valid));
            }
        }
        tarn_exp2_config any_nonzero = {sizes[i].entries, UINT8_MAX};
        tarn_exp2_config linear = {sizes[i].behaves_as, 1};
        assert_int_equal(tarn_exp2_neg_q16(-12345, any_nonzero), tarn_exp2_neg_q16(-12345, linear));
    }
}

/* ---- reciprocal ----------------------------------------------------------------------*/

/* Asserts the documented relative error for each step count and that every step
 * helps; returns the error at TARN_RECIP_STEPS_MAX. */
static tarn_math_error assert_recip_errors(const char *name, tarn_math_error (*measure)(unsigned))
{
    tarn_math_error e = {0}, fewer_steps = {0};
    for (unsigned steps = 0; steps <= TARN_RECIP_STEPS_MAX; steps++) {
        char what[48];
        snprintf(what, sizeof what, "%s %u Newton steps", name, steps);
        e = measure(steps);
        assert_true(e.samples > (1ul << 21));
        assert_max_rel_excess(what, e, recip_max_rel_excess[steps]);
        if (steps > 0) {
            assert_true(e.max_rel_excess < fewer_steps.max_rel_excess);
            assert_true(e.max_abs_lsb < fewer_steps.max_abs_lsb);
        }
        fewer_steps = e;
    }
    return e;
}

static void recip_sweeps_stay_within_documented_bounds(void **state)
{
    (void)state;
    assert_max_error("recip_u32 2 Newton steps", assert_recip_errors("recip_u32", tarn_math_measure_recip), 1.0);
    assert_max_error("recip_q30 2 Newton steps",
                     assert_recip_errors("recip_q30", tarn_math_measure_recip_q30), 2.0);
}

static void recip_limits(void **state)
{
    (void)state;
    for (unsigned steps = 0; steps <= TARN_RECIP_STEPS_MAX + 1; steps++) {
        assert_int_equal(tarn_recip_u32(0, steps), UINT32_MAX);
        assert_int_equal(tarn_recip_u32(1, steps), UINT32_MAX);
        assert_int_equal(tarn_recip_u32(UINT32_MAX, steps), 1);
        assert_int_equal(tarn_recip_u32(1u << 31, steps), 2);
    }
    assert_in_range(tarn_recip_u32(2, TARN_RECIP_STEPS_MAX), (1u << 31) - 1u, 1u << 31);
    assert_in_range(tarn_recip_u32(3, TARN_RECIP_STEPS_MAX), 1431655764u, 1431655766u);
    assert_int_equal(tarn_recip_u32(65536, TARN_RECIP_STEPS_MAX), 65536);
}

static void recip_q30_limits(void **state)
{
    (void)state;
    for (unsigned steps = 0; steps <= TARN_RECIP_STEPS_MAX; steps++) {
        assert_int_equal(tarn_recip_q30(0, steps), UINT32_MAX);
        /* documented range, at both ends of the mantissa */
        assert_in_range(tarn_recip_q30(1u << 31, steps), (1u << 30) - 1022u, (1u << 31) - 1u);
        assert_in_range(tarn_recip_q30(UINT32_MAX, steps), (1u << 30) - 1022u, (1u << 31) - 1u);
        /* an unnormalised mantissa is shifted up first */
        assert_int_equal(tarn_recip_q30(1, steps), tarn_recip_q30(1u << 31, steps));
        assert_int_equal(tarn_recip_q30(3, steps), tarn_recip_q30(3u << 30, steps));
        assert_int_equal(tarn_recip_q30(0x7FFFFFFFu, steps), tarn_recip_q30(0xFFFFFFFEu, steps));
    }
    /* tarn_recip_u32 is the same mantissa scaled and rounded: 2^32 / 3 and 2^32 / 6 */
    assert_int_equal(tarn_recip_u32(3, 2), tarn_recip_q30(3u << 30, 2));
    assert_int_equal(tarn_recip_u32(6, 2), (tarn_recip_q30(3u << 30, 2) + 1u) >> 1);
}

/* Newton's steps as 64-bit arithmetic writes them, for the mantissa's documented
 * algorithm: the seed from the table, then y' = y + y (1 - m y) in Q2.30. */
static uint32_t recip_q30_by_64_bits(uint32_t m, unsigned steps)
{
    const uint32_t index = (m >> (31u - TARN_RECIP_SEED_BITS)) & ((1u << TARN_RECIP_SEED_BITS) - 1u);
    uint32_t y = (uint32_t)tarn__recip_seed_q15[index] << 15;
    for (unsigned k = 0; k < steps; k++) {
        const uint32_t m_y = (uint32_t)(((uint64_t)m * y) >> 32);
        const uint32_t error = m_y <= (1u << 30) ? (1u << 30) - m_y : m_y - (1u << 30);
        const uint32_t change = (uint32_t)(((uint64_t)y * (error << 2)) >> 32);
        y = m_y <= (1u << 30) ? y + change : y - change;
    }
    return y;
}

/* The first step takes products by the 16-bit seed alone: it must give the same
 * number as the full products, for every seed bucket and across each one. */
static void recip_q30_steps_match_64_bit_arithmetic(void **state)
{
    (void)state;
    uint64_t random = 0x9E3779B97F4A7C15u;
    for (uint32_t n = 0; n < (1u << 21); n++) {
        random ^= random << 13;
        random ^= random >> 7;
        random ^= random << 17;
        /* each seed bucket's first and last mantissa, then random ones */
        const uint32_t bucket_shift = 31u - TARN_RECIP_SEED_BITS, last = (1u << bucket_shift) - 1u;
        const uint32_t m = n < (2u << TARN_RECIP_SEED_BITS)
            ? 0x80000000u | (n >> 1) << bucket_shift | ((n & 1u) ? last : 0u)
            : (uint32_t)random | 0x80000000u;
        for (unsigned steps = 0; steps <= TARN_RECIP_STEPS_MAX; steps++)
            if (tarn_recip_q30(m, steps) != recip_q30_by_64_bits(m, steps))
                fail_msg("m=%08x steps=%u: %08x, by 64 bits %08x", m, steps, tarn_recip_q30(m, steps),
                         recip_q30_by_64_bits(m, steps));
    }
}

static uint64_t next_random(uint64_t *state)
{
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    return *state;
}

static void assert_division_exact(uint64_t n, uint32_t divisor)
{
    const tarn_divisor d = tarn_divisor_of(divisor);
    uint32_t remainder = UINT32_MAX;
    assert_true(tarn_divide_u64(n, &d, &remainder) == n / divisor);
    assert_int_equal(remainder, n % divisor);
    const int64_t s = (int64_t)(n >> 2) * ((n & 1u) ? -1 : 1); /* |s| < 2^62 */
    const int64_t floor_q = s / divisor - (s % divisor < 0);
    assert_true(tarn_divide_floor_i64(s, &d, &remainder) == floor_q);
    assert_true((int64_t)remainder == s - floor_q * (int64_t)divisor);
    assert_true(tarn_divide_trunc_i64(s, &d) == s / divisor);
}

/* Division by a prepared divisor equals / and %: every kind of divisor (1, powers of
 * two, their neighbours, the largest, random ones) against numerators of every
 * size, and the reciprocal never overshoots, which keeps each round's estimate at
 * or below the quotient. */
static void divide_is_exact(void **state)
{
    (void)state;
    uint64_t seed = 0x9E3779B97F4A7C15u;
    uint32_t divisors[200];
    size_t count = 0;
    for (unsigned b = 0; b < 32; b++) {
        divisors[count++] = 1u << b;
        divisors[count++] = (1u << b) + 1u;
        divisors[count++] = (1u << b) * 3u / 2u + 1u;
    }
    divisors[count++] = UINT32_MAX;
    while (count < sizeof divisors / sizeof divisors[0])
        divisors[count++] = (uint32_t)(next_random(&seed) >> (32 + next_random(&seed) % 32)) | 1u;
    for (size_t i = 0; i < count; i++) {
        const tarn_divisor d = tarn_divisor_of(divisors[i]);
        if (divisors[i] > 1u) assert_true(d.recip <= ((uint64_t)1 << 62) / (divisors[i] << d.shift));
        assert_division_exact(0, divisors[i]);
        assert_division_exact(divisors[i] - 1u, divisors[i]);
        assert_division_exact(divisors[i], divisors[i]);
        assert_division_exact(UINT64_MAX, divisors[i]);
        for (int k = 0; k < 200; k++) assert_division_exact(next_random(&seed) >> (k % 64), divisors[i]);
    }
    for (uint32_t m = 1u << 31; m >= (1u << 31); m += 1u << 20) /* every seed region of the table */
        assert_true(tarn_divisor_of(m).recip <= ((uint64_t)1 << 62) / m);
    assert_int_equal(tarn_divisor_of(0).divisor, 1);
}

/* More steps than TARN_RECIP_STEPS_MAX act as TARN_RECIP_STEPS_MAX (bounded time). */
static void recip_extra_steps_clamp(void **state)
{
    (void)state;
    for (uint32_t x = 2; x < 100000; x += 37) {
        uint32_t full = tarn_recip_u32(x, TARN_RECIP_STEPS_MAX);
        assert_int_equal(tarn_recip_u32(x, TARN_RECIP_STEPS_MAX + 1), full);
        assert_int_equal(tarn_recip_u32(x, UINT32_MAX), full);
        uint32_t full_q30 = tarn_recip_q30(x, TARN_RECIP_STEPS_MAX);
        assert_int_equal(tarn_recip_q30(x, TARN_RECIP_STEPS_MAX + 1), full_q30);
        assert_int_equal(tarn_recip_q30(x, UINT32_MAX), full_q30);
    }
}

/* ---- sine and cosine ---------------------------------------------------------------*/

static void sin_cos_every_angle_within_documented_bound(void **state)
{
    (void)state;
    tarn_math_error sin_error = tarn_math_measure_sin();
    tarn_math_error cos_error = tarn_math_measure_cos();
    assert_int_equal(sin_error.samples, 65536);
    assert_int_equal(cos_error.samples, 65536);
    assert_max_error("sin", sin_error, 1.001);
    assert_max_error("cos", cos_error, 1.001);
}

static void sin_cos_exact_points_range_and_symmetry(void **state)
{
    (void)state;
    assert_int_equal(tarn_sin_q15(0), 0);
    assert_int_equal(tarn_sin_q15(16384), 32767);
    assert_int_equal(tarn_sin_q15(32768), 0);
    assert_int_equal(tarn_sin_q15(49152), -32767);
    assert_int_equal(tarn_cos_q15(0), 32767);
    assert_int_equal(tarn_cos_q15(16384), 0);
    assert_int_equal(tarn_cos_q15(32768), -32767);
    assert_int_equal(tarn_cos_q15(UINT16_MAX), 32767);
    for (uint32_t a = 0; a <= UINT16_MAX; a++) {
        int32_t s = tarn_sin_q15((uint16_t)a);
        assert_in_range(s + 32767, 0, 2 * 32767);
        assert_int_equal(tarn_sin_q15((uint16_t)(a + 32768u)), -s);
        assert_int_equal(tarn_sin_q15((uint16_t)(32768u - a)), s);
        assert_int_equal(tarn_cos_q15((uint16_t)a), tarn_sin_q15((uint16_t)(a + 16384u)));
    }
}

/* Every angle from -pi/2 to pi/2 in steps of 2^-14 rad, and past both ends (clamped). */
static void sin_cos_q30_within_four_units(void **state)
{
    (void)state;
    const double unit = 1073741824.0; /* 2^30 */
    double worst = 0;
    for (int64_t x = -1686629713 - (1 << 20); x <= 1686629713 + (1 << 20); x += 1 << 16) {
        int32_t sine, cosine;
        tarn_sin_cos_q30((int32_t)x, &sine, &cosine);
        const double half_pi = 2 * atan(1.0);
        double angle = fmax(-half_pi, fmin(half_pi, (double)x / unit));
        worst = fmax(worst, fabs(sine - sin(angle) * unit));
        worst = fmax(worst, fabs(cosine - cos(angle) * unit));
    }
    assert_true(worst <= 4.0);
    int32_t sine, cosine;
    tarn_sin_cos_q30(INT32_MIN, &sine, &cosine); /* clamps, no overflow */
    assert_true(sine <= -(1 << 30) + 4 && cosine >= 0 && cosine <= 4);
    tarn_sin_cos_q30(0, &sine, &cosine);
    assert_int_equal(sine, 0);
    assert_int_equal(cosine, 1 << 30);
}

/* ---- square roots ------------------------------------------------------------------*/

/* 1 when r is floor(sqrt(x)): r^2 <= x < (r + 1)^2, with (r + 1)^2 beyond 64 bits
 * only for r = 2^32 - 1, where it exceeds every x. */
static int is_floor_root(uint64_t x, uint64_t r)
{
    if (r > 0xFFFFFFFFu || r * r > x) return 0;
    return r == 0xFFFFFFFFu || (r + 1u) * (r + 1u) > x;
}

/* Every power of two's neighbourhood, every square's neighbours, and random values of
 * every bit length: each root is the floor of the square root. */
static void isqrt_u64_is_the_floor_root(void **state)
{
    (void)state;
    for (unsigned b = 0; b < 64; b++)
        for (int64_t d = -70; d <= 70; d++) {
            const uint64_t x = ((uint64_t)1 << b) + (uint64_t)d;
            assert_true(is_floor_root(x, tarn_isqrt_u64(x)));
        }
    uint64_t seed = 0x9E3779B97F4A7C15u;
    for (int i = 0; i < 400000; i++) {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        const uint64_t x = seed >> (i % 64);
        const uint64_t r = tarn_isqrt_u64(x);
        assert_true(is_floor_root(x, r));
        for (uint64_t s = r * r - 2u, k = 0; k < 5u; k++, s++) /* around its square */
            assert_true(is_floor_root(s, tarn_isqrt_u64(s)));
    }
}

static void isqrt_is_exact(void **state)
{
    (void)state;
    tarn_math_error e = tarn_math_measure_isqrt();
    assert_true(e.samples > (1ul << 24));
    assert_max_error("isqrt", e, 0.0);
    assert_int_equal(tarn_isqrt_u32(0), 0);
    assert_int_equal(tarn_isqrt_u32(1), 1);
    assert_int_equal(tarn_isqrt_u32(65535u * 65535u), 65535);
    assert_int_equal(tarn_isqrt_u32(65535u * 65535u - 1u), 65534);
    assert_int_equal(tarn_isqrt_u32(UINT32_MAX), 65535);
    const uint64_t big = 4294967295u; /* (2^32 - 1)^2 is the largest square below 2^64 */
    assert_true(tarn_isqrt_u64(big * big) == big);
    assert_true(tarn_isqrt_u64(big * big - 1u) == big - 1u);
    assert_true(tarn_isqrt_u64(UINT64_MAX) == big);
    assert_true(tarn_isqrt_u64((uint64_t)1 << 62) == (uint64_t)1 << 31);
}

/* tarn_math.h's bounds: tarn_rsqrt_q16 within 0.501 LSB and 2.5e-9 relative beyond
 * the rounding, tarn_rsqrt15_q16 within 2^-15 relative. */
static void rsqrt_sweep_within_documented_bound(void **state)
{
    (void)state;
    tarn_math_error e = tarn_math_measure_rsqrt(2);
    assert_true(e.samples > (1ul << 20));
    assert_max_error("rsqrt", e, 0.501);
    assert_max_rel_excess("rsqrt", e, 2.5e-9);
    e = tarn_math_measure_rsqrt(1);
    assert_true(e.samples > (1ul << 20));
    assert_max_rel_excess("rsqrt15", e, 1.0 / 32768.0);
}

static void rsqrt_limits(void **state)
{
    (void)state;
    assert_int_equal(tarn_rsqrt_q16(0), 0);               /* no direction */
    assert_int_equal(tarn_rsqrt_q16(1), 1u << 24);        /* 1/sqrt(2^-16) = 256.0 */
    assert_int_equal(tarn_rsqrt_q16(2), 11863283);        /* 2^24 / sqrt(2) */
    assert_int_equal(tarn_rsqrt_q16(65536), 65536);       /* 1.0 */
    assert_int_equal(tarn_rsqrt_q16(4 * 65536), 32768);   /* 1/sqrt(4) = 0.5 */
    assert_int_equal(tarn_rsqrt_q16(UINT32_MAX), 256);    /* 1/sqrt(65536.0) */
    assert_int_equal(tarn_rsqrt_q16(UINT32_MAX - 1u), 256);
}

/* Every code of the 16-bit depth: decoding then encoding gives it back, codes
 * decode to strictly increasing values, and the value just below the next code's
 * still encodes to this one: the encoding is monotone over all of 1..2^30, with a
 * relative step of at most 2^-12 above 2^16. */
static void depth16_codes_are_monotone_and_fine(void **state)
{
    (void)state;
    const uint16_t top = tarn_depth16_encode(1u << 30);
    assert_int_equal(top, 0xF000);
    assert_int_equal(tarn_depth16_encode(0), 1);
    assert_int_equal(tarn_depth16_encode(1), 1);
    assert_int_equal(tarn_depth16_encode(0x3FFFFFFFu), 0xEFFF);
    for (uint32_t code = 1; code < top; code++) {
        const uint32_t low = tarn_depth16_decode((uint16_t)code), next = tarn_depth16_decode((uint16_t)(code + 1));
        assert_true(next > low);
        assert_int_equal(tarn_depth16_encode(low), code);
        assert_int_equal(tarn_depth16_encode(next - 1u), code);
        if (low >= (1u << 16)) assert_true((uint64_t)(next - low) << 12 <= low);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(exp2_sweeps_stay_within_documented_bounds),
        cmocka_unit_test(exp2_limits),
        cmocka_unit_test(exp2_outside_the_sweep_saturates),
        cmocka_unit_test(exp2_invalid_config_uses_a_valid_table),
        cmocka_unit_test(recip_sweeps_stay_within_documented_bounds),
        cmocka_unit_test(recip_limits),
        cmocka_unit_test(recip_q30_limits),
        cmocka_unit_test(recip_q30_steps_match_64_bit_arithmetic),
        cmocka_unit_test(recip_extra_steps_clamp),
        cmocka_unit_test(divide_is_exact),
        cmocka_unit_test(sin_cos_every_angle_within_documented_bound),
        cmocka_unit_test(sin_cos_exact_points_range_and_symmetry),
        cmocka_unit_test(sin_cos_q30_within_four_units),
        cmocka_unit_test(isqrt_is_exact),
        cmocka_unit_test(isqrt_u64_is_the_floor_root),
        cmocka_unit_test(rsqrt_sweep_within_documented_bound),
        cmocka_unit_test(rsqrt_limits),
        cmocka_unit_test(depth16_codes_are_monotone_and_fine),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
