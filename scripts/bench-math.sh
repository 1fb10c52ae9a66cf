#!/bin/sh
# Instructions per call of each fixed-point math function and configuration, counted
# by callgrind on the host: deterministic, unlike wall time. Each case of
# host/compare/accuracy_math.c runs in its own process over its fixed benchmark inputs; the
# count is the function's inclusive Ir divided by the number of calls.
# Usage: scripts/bench-math.sh            (from the repository root)
# Needs valgrind and cc. Compiler flags: $CC -O2, as the release build, but without
# -g: with debug info callgrind splits a function's cost between its own file and
# the headers its inlined helpers come from.
set -eu
cd "$(dirname "$0")/.."
command -v valgrind >/dev/null || { echo "bench-math: valgrind is not installed" >&2; exit 1; }
CC=${CC:-cc}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM

rounds=8
cat >"$work/bench.c" <<'EOF'
/* Runs one case of host/compare/accuracy_math.c over its benchmark inputs: bench CASE ROUNDS.
 * Prints the function's C name, the configuration and the number of calls. */
#include <stdio.h>
#include <stdlib.h>
#include "accuracy_math.h"

int main(int argc, char **argv)
{
    static uint32_t inputs[TARN_MATH_BENCH_INPUTS];
    const tarn_math_case *c = argc == 3 ? tarn_math_case_at(strtoul(argv[1], NULL, 10)) : NULL;
    unsigned rounds = argc == 3 ? (unsigned)strtoul(argv[2], NULL, 10) : 0u;
    if (c == NULL) return 2;
    tarn_math_bench_inputs(c, inputs);
    uint32_t checksum = tarn_math_bench_run(c, inputs, rounds);
    printf("%s\t%s\t%lu\t%lu\n", c->symbol, c->config,
           (unsigned long)rounds * TARN_MATH_BENCH_INPUTS, (unsigned long)checksum);
    return 0;
}
EOF
$CC -std=c99 -O2 -D_POSIX_C_SOURCE=200809L -Icore -Icore/include -Ihost/compare -Ihost/util -o "$work/bench" \
    "$work/bench.c" host/compare/accuracy_math.c host/util/clock.c core/math/*.c -lm

printf '%-18s %-15s %12s\n' function config Ir_per_call
index=0
while line=$("$work/bench" "$index" "$rounds" 2>/dev/null); do
    symbol=$(printf '%s\n' "$line" | cut -f1)
    config=$(printf '%s\n' "$line" | cut -f2)
    calls=$(printf '%s\n' "$line" | cut -f3)
    valgrind --tool=callgrind --callgrind-out-file="$work/out" "$work/bench" "$index" "$rounds" \
        >/dev/null 2>&1
    # inclusive Ir of the function itself (its callees included, the caller's loop not)
    ir=$(callgrind_annotate --inclusive=yes "$work/out" |
        awk -v fn=":$symbol " 'index($0, fn) { gsub(",", "", $1); print $1; exit }')
    [ -n "$ir" ] || { echo "bench-math: no callgrind count for $symbol" >&2; exit 1; }
    awk -v s="$symbol" -v c="$config" -v ir="$ir" -v n="$calls" \
        'BEGIN { printf "%-18s %-15s %12.2f\n", s, c, ir / n }'
    index=$((index + 1))
done
