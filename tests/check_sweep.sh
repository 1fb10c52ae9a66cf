#!/bin/sh
# check_sweep.sh: tarn sweep runs end to end and its numbers are sane; the presets
# measure what docs/sweep.md claims.
#
# 1. The quick grid on the fog scene at its 120x120, with host cost (callgrind) and
#    qemu-m0 cost (one boot, checksums checked against the host by the sweep):
#    every point has a PSNR and a host cost; more exp2 entries never raise the exp2
#    error (each mode); `exact` has the highest PSNR of the presets and `fast` the
#    lowest cost on the host and on qemu-m0; front.md and the PNG exist.
# 2. The presets of every scene of docs/sweep/front.md, re-measured (--grid presets)
#    against its preset tables: the yardstick's numbers to the digit, the host's cost within 0.5%,
#    a board's within 1%. A board runs every point of a grid in one image, linked
#    for all the points it holds: the full grid's links the refraction code that
#    the presets alone (fast, on a 16 KB board) leave out, and that moves the
#    fast pond on qemu-rv32 by 8 instructions a pixel (1148 against 1140).
# 3. Bad input: one line, exit 2, no output left.
set -u
tarn=${TARN_BIN:-build/release/tarn}
out=build/sweep-check
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }
rm -rf "$out"
mkdir -p "$out"

if "$tarn" sweep scenes/effects/fog.json --grid quick --boards qemu-m0 --out "$out/quick" \
    > "$out/quick.log" 2>&1; then pass; else cat "$out/quick.log"; fail "the quick sweep failed"; fi
csv=$out/quick/sweep.csv

# column numbers by name, so the checks read as the header does
col() { head -1 "$csv" | tr ',' '\n' | grep -nx "$1" | cut -d: -f1; }
psnr=$(col psnr_db) host=$(col host_insn_per_pixel) m0=$(col qemu-m0_insn_per_pixel)
entries=$(col exp2_entries) mode=$(col exp2_mode) exp2err=$(col exp2_max_lsb) preset=$(col preset)

rows=$(tail -n +2 "$csv" | wc -l)
sane=$(tail -n +2 "$csv" | awk -F, -v p="$psnr" -v h="$host" \
    '$p > 10 && $p <= 99.99 && $h > 100 && $h < 100000' | wc -l)
if [ "$rows" -ge 8 ] && [ "$sane" -eq "$rows" ]; then pass; else
    fail "$sane of $rows points have a PSNR in (10, 99.99] and a host cost in (100, 100000)"; fi

# exp2 error by entries within each mode: never higher for a larger table
if tail -n +2 "$csv" | awk -F, -v e="$entries" -v m="$mode" -v x="$exp2err" '{print $m, $e, $x}' | sort -u |
    sort -k1,1 -k2,2n | awk '$1 == mode && $3 > last + 1e-9 {bad = 1} {mode = $1; last = $3}
                              END {exit bad}'; then pass; else fail "a larger exp2 table had a larger error"; fi

# The cells of a preset's row in a scene's section of a front.md.
preset_row() {
    awk -v scene="$2" '/^## / {here = ($2 == scene)} here' "$1" | sed -n "s/^| \`$3\` | \(.*\)|\$/\1/p" | head -1
}
preset_field() { awk -F, -v p="$preset" -v n="$1" -v c="$2" 'NR > 1 && $p == n {print $c}' "$csv"; }
lowest_cost_is_fast() {
    best=$(awk -F, -v p="$preset" -v c="$1" 'NR > 1 && $p != "" {print $c, $p}' "$csv" | sort -n | head -1 | cut -d' ' -f2)
    [ "$best" = fast ]
}
highest_psnr=$(awk -F, -v p="$preset" -v c="$psnr" 'NR > 1 && $p != "" {print $c, $p}' "$csv" | sort -rn | head -1 | cut -d' ' -f2)
if [ "$highest_psnr" = exact ] || [ "$(preset_field exact "$psnr")" = "$(preset_field "$highest_psnr" "$psnr")" ]; then
    pass; else fail "the exact preset is not the most accurate: $highest_psnr is"; fi
if lowest_cost_is_fast "$host"; then pass; else fail "fast is not the cheapest preset on the host"; fi
if lowest_cost_is_fast "$m0"; then pass; else fail "fast is not the cheapest preset on qemu-m0"; fi
if [ -s "$out/quick/front.md" ] && head -c 8 "$out/quick/fog.png" | od -An -c | grep -q 'P   N   G'; then
    pass; else fail "front.md or fog.png missing"; fi

# 2. the published presets, re-measured, scene by scene
for scene in $(sed -n 's/^## \([a-z_]*\) (.*/\1/p' docs/sweep/front.md); do
    if "$tarn" sweep "scenes/$scene.json" --grid presets --boards qemu-m0,qemu-rv32 --out "$out/presets-$scene" \
        > "$out/presets-$scene.out" 2> "$out/presets-$scene.log"; then pass; else
        cat "$out/presets-$scene.log"; fail "the presets sweep of $scene failed"; fi
    for name in fast balanced exact; do
        claimed=$(preset_row docs/sweep/front.md "$scene" "$name")
        measured=$(preset_row "$out/presets-$scene/front.md" "$scene" "$name")
        if echo "$claimed|$measured" | awk -F'|' '{
                n = NF / 2; bad = (n < 9)
                for (i = 1; i <= n; i++) {
                    a = $i; b = $(i + n); gsub(/[ %]|\(.*\)/, "", a); gsub(/[ %]|\(.*\)/, "", b)
                    if (i <= 8) bad = bad || a != b       # the eight numbers of the yardstick: exact
                    else if (a + 0 > 0) bad = bad || (b - a > a * (i == 9 ? 0.005 : 0.01) ||
                                                      a - b > a * (i == 9 ? 0.005 : 0.01))
                    else bad = bad || a != b              # "does not fit" on both
                }
                exit bad }'; then pass; else
            fail "$scene, preset $name: docs/sweep/front.md claims [$claimed], measured [$measured]"; fi
    done
done

# 3. bad input
for args in "--grid huge" "scenes/nope.json --boards none --host-cost none" "--boards qemu-x9"; do
    # shellcheck disable=SC2086
    "$tarn" sweep $args --out "$out/bad" > "$out/bad.out" 2> "$out/bad.err"
    status=$?
    if [ $status -eq 2 ] && [ "$(grep -c '^tarn: ' "$out/bad.err")" -eq 1 ] && [ ! -e "$out/bad/sweep.csv" ]; then
        pass; else cat "$out/bad.err"; fail "tarn sweep $args: exit $status, expected 2, one line, no sweep.csv"; fi
done

echo "check_sweep: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
