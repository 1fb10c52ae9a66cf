#!/bin/sh
# What each water effect costs on the Cortex-M0: every one-effect scene of
# scenes/effects/ (120 x 120, the same ground and water plane; `none` has no water
# material) built for qemu-m0 with the board's quality and run under QEMU with
# -icount shift=0. Prints one line a scene: instructions a pixel for a whole frame
# (panel stream included) and over `none`, or the bake's refusal of a scene the
# flags cannot draw (--backdrop still under the underwater view).
# Usage: scripts/bench-effects-target.sh [BAKE_FLAGS]   (default: the qemu-m0 board's)
set -eu
flags=${1:-$(sed -n 's/^BOARD_BAKE_FLAGS := //p' boards/qemu-m0/board.mk)}
base=
mkdir -p build/bench-effects
for scene in none fog absorption depth_colour ramp fresnel foam sparkles normals refraction underwater; do
    dir=build/bench-effects/$scene
    scene_flags=$flags
    # the underwater view needs a second full buffer: 16-pixel tiles fit the M0's RAM
    # (in place of the flags' own tile, since an option may be given once)
    [ "$scene" = underwater ] && scene_flags="$(printf '%s' "$flags" | sed 's/ *--tile [0-9]*//') --tile 16"
    if ! make --no-print-directory -s firmware-run BOARD=qemu-m0 FW_BUILD_DIR="$dir" SCENE="scenes/effects/$scene.json" \
        BAKE_FLAGS="$scene_flags" > "$dir.log" 2>&1; then
        # a bake that refuses the scene says why in one line (still water and the
        # underwater view); anything else is a failure
        refusal=$(sed -n 's/^tarn: .*: \(--backdrop still: .*\)$/\1/p' "$dir.log" | head -1)
        [ -n "$refusal" ] || { cat "$dir.log"; exit 1; }
        echo "effect-target board=qemu-m0 scene=$scene flags=\"$scene_flags\" refused=\"$refusal\""
        continue
    fi
    insn=$(tr ' ' '\n' < "$dir/report.txt" | sed -n 's/^insn_per_pixel=//p')
    [ -z "$base" ] && base=$insn
    echo "effect-target board=qemu-m0 scene=$scene flags=\"$scene_flags\" insn_per_pixel=$insn over_none=$((insn - base))"
done
