/* test_fixed_limits.c: every helper of core/tarn_fixed.h at its limits: zero, one,
 * the largest and smallest values of its types and the values just past each
 * boundary it draws. `make test` runs this file under UndefinedBehaviorSanitizer
 * too, so an overflow at a limit fails as surely as a wrong value. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "tarn_fixed.h"

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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(saturation_and_clamping),
        cmocka_unit_test(rounding_shifts),
        cmocka_unit_test(q16_arithmetic),
        cmocka_unit_test(bits),
        cmocka_unit_test(products),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
