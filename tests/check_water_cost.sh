#!/bin/sh
# What each water effect costs on the host, and proof that a scene without water
# does no water work: callgrind counts the instructions of a frame (inclusive of
# tarn_render_frame) and of the water pixel (tarn__water_shade), per pixel.
# Prints one line per scene:
#   water-cost scene=NAME insn_per_pixel=N water_insn_per_pixel=N
# and writes them to WATER_COST_OUT too (when set), for tests/check_doc_figures.sh
# to hold docs/figures.md's table to without measuring again.
# Usage: TARN_BIN=build/release/tarn [WATER_COST_OUT=FILE] tests/check_water_cost.sh
set -u
TARN_BIN=${TARN_BIN:-build/release/tarn}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM
passed=0
failed=0

# Inclusive instructions of a function in a callgrind profile, 0 if it never ran.
inclusive() {
    callgrind_annotate --inclusive=yes "$1" 2>/dev/null |
        awk -v fn="$2" '$0 ~ (":" fn " ") || $0 ~ (":" fn "$") { gsub(",", "", $1); print $1; exit }'
}

for scene in none fog absorption depth_colour ramp refraction normals fresnel foam sparkles underwater; do
    profile="$work/$scene.out"
    valgrind --tool=callgrind --callgrind-out-file="$profile" \
        "$TARN_BIN" render "scenes/effects/$scene.json" -o "$work/$scene.png" >/dev/null 2>&1
    frame=$(inclusive "$profile" tarn_render_frame)
    water=$(inclusive "$profile" tarn__water_shade)
    pixels=$((120 * 120))
    echo "water-cost scene=$scene insn_per_pixel=$(( ${frame:-0} / pixels )) water_insn_per_pixel=$(( ${water:-0} / pixels ))" |
        tee -a "$work/lines"
    if [ -z "$frame" ]; then failed=$((failed + 1)); echo "FAIL: no profile for $scene"; continue; fi
    if [ "$scene" = none ] && [ -n "$water" ]; then
        failed=$((failed + 1)); echo "FAIL: a scene without water ran the water pixel"
    elif [ "$scene" != none ] && [ "$scene" != underwater ] && [ -z "$water" ]; then
        failed=$((failed + 1)); echo "FAIL: $scene drew no water pixel"
    else
        passed=$((passed + 1))
    fi
done
[ -n "${WATER_COST_OUT:-}" ] && [ "$failed" -eq 0 ] && cp "$work/lines" "$WATER_COST_OUT"
echo "water-cost: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
