#!/bin/sh
# check_firmware_sweep.sh: one boot of qemu-m0 measures several qualities
# (make firmware-sweep, firmware/sweep_main.c), and what it reports is what the host
# renders.
#
# Sweeps the fog scene at 64x64 over tests/sweep_points.txt (three points: pixel,
# span and affine perspective, 16- and 32-bit depth) in build/firmware-sweep-check/,
# then runs tests/test_firmware_sweep.c on the report: a line per point with
# status=ok and the checksum of the host's own render of that point. The image
# must link span perspective (span_end), which only the second point uses. A points
# file with a bad line must stop the build at the bake, naming FILE:LINE, with no
# scene.c written. Prints a FAIL line (and the log) for each check that fails, then the
# totals; the points' report lines are in the report. Exit status: non-zero if any
# check failed.
set -u
board=qemu-m0
top=build/firmware-sweep-check
dir=$top/$board
scene=scenes/effects/fog.json
flags="--size 64x64 --apron off --tile 16 --depth 16"
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }
mkdir -p "$top"

if make --no-print-directory -s firmware-sweep BOARD=$board SCENE=$scene BAKE_FLAGS="$flags" \
    POINTS=tests/sweep_points.txt FW_BUILD_DIR="$dir" > "$top/sweep.log" 2>&1; then
    pass
else
    cat "$top/sweep.log"
    fail "make firmware-sweep BOARD=$board failed"
fi

if make --no-print-directory -s build/release/tests/test_firmware_sweep > "$top/test.log" 2>&1 &&
    SWEEP_DIR="$dir" build/release/tests/test_firmware_sweep > "$top/test.log" 2>&1 &&
    grep -q '^\[  PASSED  \] 1 test' "$top/test.log"; then
    pass
else
    cat "$top/test.log"
    grep -E '^(point|sweep) ' "$dir/report.txt" 2>/dev/null
    fail "the sweep's report does not match the host (tests/test_firmware_sweep.c)"
fi

if arm-none-eabi-nm --defined-only "$dir/firmware.elf" 2>/dev/null | awk '{print $3}' | grep -qx span_end; then
    pass
else
    fail "$dir/firmware.elf does not link span perspective (span_end), which a point uses"
fi

# A bad line: the bake names it, and the build stops before any C is written.
bad=$top/bad_points.txt
printf '%s\n' '--perspective affine' '--depth 24' > "$bad"
rm -rf "$top/bad"
if make --no-print-directory -s firmware-sweep BOARD=$board SCENE=$scene BAKE_FLAGS="$flags" \
    POINTS="$bad" FW_BUILD_DIR="$top/bad" > "$top/bad.log" 2>&1; then
    fail "a points file with --depth 24 on line 2 was accepted"
elif ! grep -q "tarn: $bad:2: --depth: expected 16 or 32, got '24'" "$top/bad.log"; then
    cat "$top/bad.log"
    fail "the bad points file's error does not name $bad:2"
elif [ -e "$top/bad/scene.c" ] || [ -e "$top/bad/scene.h" ]; then
    fail "the refused bake left $top/bad/scene.c or scene.h"
else
    pass
fi

echo "firmware sweep: $passed passed, $failed failed (its report: $dir/report.txt)"
[ "$failed" -eq 0 ]
