/* accuracy_math.h: measured error and cost of core/'s fixed-point math functions,
 * the table `tarn accuracy --math` prints.
 *
 * Errors come from sweeping each function's input range against libm in doubles
 * (the same sweeps tests/test_math.c asserts bounds on). Costs come from timing a
 * fixed set of benchmark inputs; scripts/bench-math.sh runs the same benchmark
 * under callgrind for deterministic instruction counts. */
#ifndef TARN_HOST_ACCURACY_MATH_H
#define TARN_HOST_ACCURACY_MATH_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "tarn/tarn_math.h"

/* Error of one function over one sweep, in units of the last place (LSB) of the
 * function's output format. */
typedef struct {
    double max_abs_lsb;  /* largest |result - exact| */
    double mean_abs_lsb; /* mean |result - exact| over the sweep's inputs */
    /* Largest relative error beyond the final rounding to an integer:
     * max(0, |result - exact| - 1/2) / exact. Only for functions whose outputs span
     * many magnitudes (recip, recip_q30, rsqrt); negative where it is not reported. */
    double max_rel_excess;
    int64_t worst_input;   /* an input where max_abs_lsb occurs */
    unsigned long samples; /* inputs swept */
} tarn_math_error;

/* Every x from 0 down to -18.0 (Q16.16), where every configuration has reached 0. */
tarn_math_error tarn_math_measure_exp2(tarn_exp2_config config);
/* Every x in [2, 2^22], then steps of about 2^-18 of x up to UINT32_MAX, landing on
 * every power of two and the value just below it. */
tarn_math_error tarn_math_measure_recip(unsigned newton_steps);
/* Mantissas from 2^31 in steps of 1021, and UINT32_MAX; output LSBs of Q2.30. */
tarn_math_error tarn_math_measure_recip_q30(unsigned newton_steps);
/* Every one of the 65536 angles; exact value clamped to [-32767, 32767]. */
tarn_math_error tarn_math_measure_sin(void);
tarn_math_error tarn_math_measure_cos(void);
/* Every x below 2^24, then k^2 - 1, k^2 and k^2 + 1 for every k up to 65535, and
 * UINT32_MAX. Exact is floor(sqrt(x)), so any error is a bug. */
tarn_math_error tarn_math_measure_isqrt(void);
/* Every x in [1, 2^22], then steps as for recip: tarn_rsqrt15_q16 (one Newton step)
 * or tarn_rsqrt_q16 (two). */
tarn_math_error tarn_math_measure_rsqrt(unsigned newton_steps);

typedef enum {
    TARN_MATH_EXP2,
    TARN_MATH_RECIP,
    TARN_MATH_RECIP_Q30,
    TARN_MATH_SIN,
    TARN_MATH_COS,
    TARN_MATH_ISQRT,
    TARN_MATH_RSQRT
} tarn_math_function;

/* One row of the table: a function and a configuration of it. */
typedef struct {
    tarn_math_function function;
    const char *symbol;      /* the core function's C name */
    const char *config;      /* the configuration in words, "" for none */
    tarn_exp2_config exp2;   /* TARN_MATH_EXP2 only */
    unsigned newton_steps;   /* TARN_MATH_RECIP and TARN_MATH_RECIP_Q30 only */
} tarn_math_case;

size_t tarn_math_case_count(void);
const tarn_math_case *tarn_math_case_at(size_t index); /* NULL past the end */
tarn_math_error tarn_math_case_measure(const tarn_math_case *c);

/* Benchmark inputs: exp2 arguments uniform over [-16, 0]; angles and recip_q30
 * mantissas (top bit set) uniform; recip, isqrt and rsqrt inputs with magnitudes
 * spread evenly over 2^1..2^32. Fixed
 * pseudo-random sequences, the same on every run. */
#define TARN_MATH_BENCH_INPUTS 4096u
void tarn_math_bench_inputs(const tarn_math_case *c, uint32_t inputs[TARN_MATH_BENCH_INPUTS]);
/* Calls the case's function on each input, `rounds` times over; returns a checksum
 * of the results so the calls cannot be optimised away. */
uint32_t tarn_math_bench_run(const tarn_math_case *c, const uint32_t inputs[TARN_MATH_BENCH_INPUTS],
                             unsigned rounds);

/* Prints one row per case: errors as above, and host_ns, the median over 5 timed runs
 * of nanoseconds per call. Returns 0, or -1 if writing failed. */
int tarn_accuracy_math_print(FILE *out);

#endif
