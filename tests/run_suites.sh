#!/bin/sh
# Runs cmocka suites: one line for a suite that passes, its whole output for one that
# fails. Writes their summed counts to SUMMARY_FILE as "passed failed skipped" and,
# when FAILED_FILE is set, the suites that failed to it, a line each. A suite that
# exits non-zero without counting a failed test (a crash, a sanitizer's report)
# counts as one failed test. Exit status: non-zero if any failed.
# Suites run SUITE_JOBS at a time (as many as the cores unless given; each suite is
# one thread but for test_frame_parts), each into a file of its own, and are
# reported in the order given. A suite writes only its own files.
# Usage: SUMMARY_FILE=path [FAILED_FILE=path] [SUITE_JOBS=N] tests/run_suites.sh SUITE...
set -u
jobs=${SUITE_JOBS:-$(nproc 2>/dev/null || echo 1)}
scratch=$(mktemp -d "${TMPDIR:-/tmp}/tarn-suites-XXXXXX") || exit 2
trap 'rm -rf "$scratch"' EXIT
passed=0
failed=0
skipped=0
status=0
failed_suites=
plural() { if [ "$1" -eq 1 ]; then echo "$1 $2"; else echo "$1 $2s"; fi; }
count_suites=$#
n=0
for suite in "$@"; do
    n=$((n + 1))
    eval "suite_$n=\$suite"
done
# start K: suite K in the background, its output and exit status into the scratch
start() {
    eval "path=\$suite_$1"
    ("$path" > "$scratch/$1.out" 2>&1; echo $? > "$scratch/$1.status") &
    eval "pid_$1=\$!"
}
next=1
while [ "$next" -le "$count_suites" ] && [ "$next" -le "$jobs" ]; do start "$next"; next=$((next + 1)); done
k=0
while [ "$k" -lt "$count_suites" ]; do
    k=$((k + 1))
    eval "wait \$pid_$k; suite=\$suite_$k"
    if [ "$next" -le "$count_suites" ]; then start "$next"; next=$((next + 1)); fi
    out=$(cat "$scratch/$k.out")
    suite_status=$(cat "$scratch/$k.status")
    count() { printf '%s\n' "$out" | sed -n "s/^\[  $1 *\] \([0-9]*\) test(s).*/\1/p" | head -1 | grep . || echo 0; }
    p=$(count PASSED) f=$(count FAILED) s=$(count SKIPPED)
    if [ "$suite_status" -ne 0 ] || [ "$f" -gt 0 ]; then
        echo "== $suite"
        printf '%s\n' "$out"
        if [ "$f" -gt 0 ]; then
            echo "  FAIL  $suite ($f of $((p + f + s)) tests failed)"
        else
            f=1
            echo "  FAIL  $suite (exit status $suite_status, no test counted as failed: counted as one)"
        fi
        failed_suites="$failed_suites$suite
"
        status=1
    else
        echo "  ok    $suite ($(plural "$p" test)$([ "$s" -gt 0 ] && echo ", $s skipped"))"
    fi
    passed=$((passed + p))
    failed=$((failed + f))
    skipped=$((skipped + s))
done
echo "$passed $failed $skipped" > "${SUMMARY_FILE:?}"
[ -n "${FAILED_FILE:-}" ] && printf '%s' "$failed_suites" > "$FAILED_FILE"
exit $status
