/* accuracy_math.c: error sweeps against libm and timing of core/'s math functions. */
#include "accuracy_math.h"

#include <math.h>

#include "clock.h"

/* ---- error sweeps ------------------------------------------------------------------*/

typedef struct {
    tarn_math_error error;
    double abs_sum;
} error_sweep;

static error_sweep sweep_start(int report_relative)
{
    error_sweep sweep = {{0.0, 0.0, report_relative ? 0.0 : -1.0, 0, 0}, 0.0};
    return sweep;
}

static void sweep_add(error_sweep *sweep, int64_t input, double result, double exact)
{
    tarn_math_error *e = &sweep->error;
    double abs_error = fabs(result - exact);
    if (e->samples == 0 || abs_error > e->max_abs_lsb) {
        e->max_abs_lsb = abs_error;
        e->worst_input = input;
    }
    if (e->max_rel_excess >= 0.0 && exact > 0.0) {
        e->max_rel_excess = fmax(e->max_rel_excess, (abs_error - 0.5) / exact);
    }
    sweep->abs_sum += abs_error;
    e->samples++;
}

static tarn_math_error sweep_finish(const error_sweep *sweep)
{
    tarn_math_error e = sweep->error;
    e.mean_abs_lsb = e.samples ? sweep->abs_sum / (double)e.samples : 0.0;
    return e;
}

#define DENSE_LIMIT (1u << 22)
#define STEP_SHIFT 18 /* above DENSE_LIMIT, about 2^18 samples per octave */
#define RECIP_Q30_STEP 1021u /* a prime: about 2^21 mantissas, every low bit pattern */

/* Advances through [first, UINT32_MAX]: every input below DENSE_LIMIT, then odd steps
 * (so the low bits vary) of about x / 2^STEP_SHIFT that still land on the last value
 * of each octave and on each power of two. Returns 0 after UINT32_MAX. */
static int next_stepped_input(uint64_t *x)
{
    if (*x >= UINT32_MAX) return 0;
    if (*x < DENSE_LIMIT) {
        *x += 1;
        return 1;
    }
    uint64_t octave_last = *x;
    for (unsigned shift = 1; shift < 64; shift <<= 1) octave_last |= octave_last >> shift;
    uint64_t next = *x + ((*x >> STEP_SHIFT) | 1u);
    *x = (*x < octave_last && next > octave_last) ? octave_last : next;
    return 1;
}

tarn_math_error tarn_math_measure_exp2(tarn_exp2_config config)
{
    error_sweep sweep = sweep_start(0);
    for (int32_t x = 0; x >= -18 * 65536; x--) {
        sweep_add(&sweep, x, tarn_exp2_neg_q16(x, config), 65536.0 * exp2(x / 65536.0));
    }
    return sweep_finish(&sweep);
}

tarn_math_error tarn_math_measure_recip(unsigned newton_steps)
{
    error_sweep sweep = sweep_start(1);
    uint64_t x = 2;
    do {
        sweep_add(&sweep, (int64_t)x, tarn_recip_u32((uint32_t)x, newton_steps), 4294967296.0 / (double)x);
    } while (next_stepped_input(&x));
    return sweep_finish(&sweep);
}

tarn_math_error tarn_math_measure_recip_q30(unsigned newton_steps)
{
    error_sweep sweep = sweep_start(1);
    for (uint64_t m = 1u << 31; m <= UINT32_MAX; m += RECIP_Q30_STEP) {
        sweep_add(&sweep, (int64_t)m, tarn_recip_q30((uint32_t)m, newton_steps), 0x1p62 / (double)m);
    }
    sweep_add(&sweep, UINT32_MAX, tarn_recip_q30(UINT32_MAX, newton_steps), 0x1p62 / UINT32_MAX);
    return sweep_finish(&sweep);
}

/* 32768 * sin(angle), clamped to the Q1.15 range [-32767, 32767]. */
static double exact_sin_q15(double angle_turns)
{
    const double turn_radians = 8.0 * atan(1.0);
    return fmax(-32767.0, fmin(32767.0, 32768.0 * sin(turn_radians * angle_turns)));
}

tarn_math_error tarn_math_measure_sin(void)
{
    error_sweep sweep = sweep_start(0);
    for (uint32_t a = 0; a <= UINT16_MAX; a++) {
        sweep_add(&sweep, a, tarn_sin_q15((uint16_t)a), exact_sin_q15(a / 65536.0));
    }
    return sweep_finish(&sweep);
}

tarn_math_error tarn_math_measure_cos(void)
{
    error_sweep sweep = sweep_start(0);
    for (uint32_t a = 0; a <= UINT16_MAX; a++) {
        sweep_add(&sweep, a, tarn_cos_q15((uint16_t)a), exact_sin_q15(a / 65536.0 + 0.25));
    }
    return sweep_finish(&sweep);
}

static void sweep_isqrt_at(error_sweep *sweep, uint32_t x)
{
    sweep_add(sweep, x, tarn_isqrt_u32(x), floor(sqrt((double)x)));
}

tarn_math_error tarn_math_measure_isqrt(void)
{
    error_sweep sweep = sweep_start(0);
    for (uint32_t x = 0; x < (1u << 24); x++) sweep_isqrt_at(&sweep, x);
    for (uint32_t k = 1; k <= UINT16_MAX; k++) {
        uint32_t square = k * k;
        sweep_isqrt_at(&sweep, square - 1u);
        sweep_isqrt_at(&sweep, square);
        sweep_isqrt_at(&sweep, square + 1u);
    }
    sweep_isqrt_at(&sweep, UINT32_MAX);
    return sweep_finish(&sweep);
}

/* tarn_rsqrt15_q16 for one Newton step, tarn_rsqrt_q16 for two. */
static uint32_t rsqrt_by_steps(uint32_t x, unsigned newton_steps)
{
    return newton_steps < 2u ? tarn_rsqrt15_q16(x) : tarn_rsqrt_q16(x);
}

tarn_math_error tarn_math_measure_rsqrt(unsigned newton_steps)
{
    error_sweep sweep = sweep_start(1);
    uint64_t x = 1;
    do {
        sweep_add(&sweep, (int64_t)x, rsqrt_by_steps((uint32_t)x, newton_steps), 16777216.0 / sqrt((double)x));
    } while (next_stepped_input(&x));
    return sweep_finish(&sweep);
}

/* ---- the cases -------------------------------------------------------------------*/

static const tarn_math_case math_cases[] = {
    {TARN_MATH_EXP2, "tarn_exp2_neg_q16", "8 nearest", {8, 0}, 0},
    {TARN_MATH_EXP2, "tarn_exp2_neg_q16", "16 nearest", {16, 0}, 0},
    {TARN_MATH_EXP2, "tarn_exp2_neg_q16", "32 nearest", {32, 0}, 0},
    {TARN_MATH_EXP2, "tarn_exp2_neg_q16", "64 nearest", {64, 0}, 0},
    {TARN_MATH_EXP2, "tarn_exp2_neg_q16", "128 nearest", {128, 0}, 0},
    {TARN_MATH_EXP2, "tarn_exp2_neg_q16", "256 nearest", {256, 0}, 0},
    {TARN_MATH_EXP2, "tarn_exp2_neg_q16", "8 linear", {8, 1}, 0},
    {TARN_MATH_EXP2, "tarn_exp2_neg_q16", "16 linear", {16, 1}, 0},
    {TARN_MATH_EXP2, "tarn_exp2_neg_q16", "32 linear", {32, 1}, 0},
    {TARN_MATH_EXP2, "tarn_exp2_neg_q16", "64 linear", {64, 1}, 0},
    {TARN_MATH_EXP2, "tarn_exp2_neg_q16", "128 linear", {128, 1}, 0},
    {TARN_MATH_EXP2, "tarn_exp2_neg_q16", "256 linear", {256, 1}, 0},
    {TARN_MATH_RECIP, "tarn_recip_u32", "0 Newton steps", {0, 0}, 0},
    {TARN_MATH_RECIP, "tarn_recip_u32", "1 Newton step", {0, 0}, 1},
    {TARN_MATH_RECIP, "tarn_recip_u32", "2 Newton steps", {0, 0}, 2},
    {TARN_MATH_RECIP_Q30, "tarn_recip_q30", "0 Newton steps", {0, 0}, 0},
    {TARN_MATH_RECIP_Q30, "tarn_recip_q30", "1 Newton step", {0, 0}, 1},
    {TARN_MATH_RECIP_Q30, "tarn_recip_q30", "2 Newton steps", {0, 0}, 2},
    {TARN_MATH_SIN, "tarn_sin_q15", "", {0, 0}, 0},
    {TARN_MATH_COS, "tarn_cos_q15", "", {0, 0}, 0},
    {TARN_MATH_ISQRT, "tarn_isqrt_u32", "", {0, 0}, 0},
    {TARN_MATH_RSQRT, "tarn_rsqrt15_q16", "", {0, 0}, 1},
    {TARN_MATH_RSQRT, "tarn_rsqrt_q16", "", {0, 0}, 2},
};

size_t tarn_math_case_count(void)
{
    return sizeof math_cases / sizeof math_cases[0];
}

const tarn_math_case *tarn_math_case_at(size_t index)
{
    return index < tarn_math_case_count() ? &math_cases[index] : NULL;
}

tarn_math_error tarn_math_case_measure(const tarn_math_case *c)
{
    switch (c->function) {
    case TARN_MATH_EXP2: return tarn_math_measure_exp2(c->exp2);
    case TARN_MATH_RECIP: return tarn_math_measure_recip(c->newton_steps);
    case TARN_MATH_RECIP_Q30: return tarn_math_measure_recip_q30(c->newton_steps);
    case TARN_MATH_SIN: return tarn_math_measure_sin();
    case TARN_MATH_COS: return tarn_math_measure_cos();
    case TARN_MATH_ISQRT: return tarn_math_measure_isqrt();
    case TARN_MATH_RSQRT: break;
    }
    return tarn_math_measure_rsqrt(c->newton_steps);
}

/* ---- benchmark ---------------------------------------------------------------------*/

/* xorshift32: a fixed pseudo-random sequence, identical on every run. */
static uint32_t next_random(uint32_t *state)
{
    uint32_t v = *state;
    v ^= v << 13;
    v ^= v >> 17;
    v ^= v << 5;
    return *state = v;
}

/* A value with its top bit at a uniformly chosen position 1..31: magnitudes spread
 * evenly over 2^1..2^32. */
static uint32_t random_magnitude(uint32_t *state)
{
    unsigned top_bit = 1u + next_random(state) % 31u;
    uint32_t below_top = next_random(state) & ((1u << top_bit) - 1u);
    return (1u << top_bit) | below_top;
}

void tarn_math_bench_inputs(const tarn_math_case *c, uint32_t inputs[TARN_MATH_BENCH_INPUTS])
{
    uint32_t state = 0x2545F491u;
    for (unsigned i = 0; i < TARN_MATH_BENCH_INPUTS; i++) {
        switch (c->function) {
        case TARN_MATH_EXP2: /* -x, uniform over [0, 16.0] */
            inputs[i] = next_random(&state) % (16u * 65536u + 1u);
            break;
        case TARN_MATH_RECIP_Q30:
            inputs[i] = next_random(&state) | 0x80000000u;
            break;
        case TARN_MATH_SIN:
        case TARN_MATH_COS:
            inputs[i] = next_random(&state) & 0xFFFFu;
            break;
        case TARN_MATH_RECIP:
        case TARN_MATH_ISQRT:
        case TARN_MATH_RSQRT:
            inputs[i] = random_magnitude(&state);
            break;
        }
    }
}

/* The benchmark calls every function through one of these, so each case's loop is
 * the same code with the same overhead (call_nothing measures it). */
typedef uint32_t (*bench_call)(const tarn_math_case *c, uint32_t input);

static uint32_t call_exp2(const tarn_math_case *c, uint32_t neg_x)
{
    return tarn_exp2_neg_q16(-(tarn_q16)neg_x, c->exp2);
}

static uint32_t call_recip(const tarn_math_case *c, uint32_t x)
{
    return tarn_recip_u32(x, c->newton_steps);
}

static uint32_t call_recip_q30(const tarn_math_case *c, uint32_t mantissa)
{
    return tarn_recip_q30(mantissa, c->newton_steps);
}

static uint32_t call_sin(const tarn_math_case *c, uint32_t angle)
{
    (void)c;
    return (uint32_t)tarn_sin_q15((uint16_t)angle);
}

static uint32_t call_cos(const tarn_math_case *c, uint32_t angle)
{
    (void)c;
    return (uint32_t)tarn_cos_q15((uint16_t)angle);
}

static uint32_t call_isqrt(const tarn_math_case *c, uint32_t x)
{
    (void)c;
    return tarn_isqrt_u32(x);
}

static uint32_t call_rsqrt(const tarn_math_case *c, uint32_t x)
{
    return rsqrt_by_steps(x, c->newton_steps);
}

static uint32_t call_nothing(const tarn_math_case *c, uint32_t x)
{
    (void)c;
    return x;
}

static bench_call bench_call_for(tarn_math_function function)
{
    switch (function) {
    case TARN_MATH_EXP2: return call_exp2;
    case TARN_MATH_RECIP: return call_recip;
    case TARN_MATH_RECIP_Q30: return call_recip_q30;
    case TARN_MATH_SIN: return call_sin;
    case TARN_MATH_COS: return call_cos;
    case TARN_MATH_ISQRT: return call_isqrt;
    case TARN_MATH_RSQRT: break;
    }
    return call_rsqrt;
}

static uint32_t bench_loop(bench_call call, const tarn_math_case *c,
                           const uint32_t inputs[TARN_MATH_BENCH_INPUTS], unsigned rounds)
{
    uint32_t checksum = 0;
    for (unsigned round = 0; round < rounds; round++) {
        for (unsigned i = 0; i < TARN_MATH_BENCH_INPUTS; i++) checksum += call(c, inputs[i]);
    }
    return checksum;
}

uint32_t tarn_math_bench_run(const tarn_math_case *c, const uint32_t inputs[TARN_MATH_BENCH_INPUTS],
                             unsigned rounds)
{
    return bench_loop(bench_call_for(c->function), c, inputs, rounds);
}

#define TIMED_RUNS 5
#define TIMED_ROUNDS 64u /* 2^18 calls per run: a few milliseconds */

static void sort_doubles(double *v, int n)
{
    for (int i = 1; i < n; i++) {
        for (int j = i; j > 0 && v[j] < v[j - 1]; j--) {
            double swap = v[j];
            v[j] = v[j - 1];
            v[j - 1] = swap;
        }
    }
}

/* Written after each timed run, so the calls cannot be optimised away. */
static volatile uint32_t bench_checksum_sink;

/* Median over TIMED_RUNS runs of nanoseconds per call of `call` over the case's
 * benchmark inputs. */
static double median_ns_per_call(bench_call call, const tarn_math_case *c)
{
    static uint32_t inputs[TARN_MATH_BENCH_INPUTS];
    double ns[TIMED_RUNS];
    tarn_math_bench_inputs(c, inputs);
    for (int run = 0; run < TIMED_RUNS; run++) {
        double start = tarn_clock_seconds();
        bench_checksum_sink = bench_loop(call, c, inputs, TIMED_ROUNDS);
        ns[run] = (tarn_clock_seconds() - start) * 1e9 / ((double)TIMED_ROUNDS * TARN_MATH_BENCH_INPUTS);
    }
    sort_doubles(ns, TIMED_RUNS);
    return ns[TIMED_RUNS / 2];
}

/* ---- the table ---------------------------------------------------------------------*/

static void print_row(FILE *out, const tarn_math_case *c)
{
    tarn_math_error e = tarn_math_case_measure(c);
    fprintf(out, "%-18s %-15s %12.3f %12.4f ", c->symbol, c->config, e.max_abs_lsb, e.mean_abs_lsb);
    if (e.max_rel_excess >= 0.0) {
        fprintf(out, "%10.2e (2^%6.2f)", e.max_rel_excess, log2(fmax(e.max_rel_excess, 1e-300)));
    } else {
        fprintf(out, "%21s", "-");
    }
    fprintf(out, " %9lu %8.2f\n", e.samples, median_ns_per_call(bench_call_for(c->function), c));
}

int tarn_accuracy_math_print(FILE *out)
{
    fprintf(out, "%-18s %-15s %12s %12s %21s %9s %8s\n", "function", "config", "max_abs_lsb",
            "mean_abs_lsb", "max_rel_excess", "samples", "host_ns");
    for (size_t i = 0; i < tarn_math_case_count(); i++) print_row(out, tarn_math_case_at(i));
    fprintf(out,
            "\nErrors are against libm in doubles, in units of the output's last place (LSB).\n"
            "max_rel_excess: largest relative error beyond the final rounding to an integer,\n"
            "  max(0, |result - exact| - 0.5) / exact, for functions whose outputs span many\n"
            "  magnitudes. The inputs swept are listed in host/compare/accuracy_math.h.\n"
            "host_ns: median of %d runs, nanoseconds per call on this machine, including the\n"
            "  benchmark loop's indirect call (%.2f ns per call on its own). For deterministic\n"
            "  instruction counts run scripts/bench-math.sh.\n",
            TIMED_RUNS, median_ns_per_call(call_nothing, tarn_math_case_at(0)));
    return ferror(out) ? -1 : 0;
}
