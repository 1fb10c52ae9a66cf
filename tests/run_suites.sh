#!/bin/sh
# Runs cmocka suites, shows their output, and writes their summed counts to
# SUMMARY_FILE as "passed failed skipped". Exit status: non-zero if any failed.
# Usage: SUMMARY_FILE=path tests/run_suites.sh SUITE...
set -u
passed=0
failed=0
skipped=0
status=0
for suite in "$@"; do
    echo "== $suite"
    out=$("$suite" 2>&1) || status=1
    printf '%s\n' "$out"
    count() { printf '%s\n' "$out" | sed -n "s/^\[  $1 *\] \([0-9]*\) test(s).*/\1/p" | head -1; }
    passed=$((passed + $(count PASSED | grep . || echo 0)))
    failed=$((failed + $(count FAILED | grep . || echo 0)))
    skipped=$((skipped + $(count SKIPPED | grep . || echo 0)))
done
[ "$failed" -gt 0 ] && status=1
echo "$passed $failed $skipped" > "${SUMMARY_FILE:?}"
exit $status
