#!/bin/sh
# Prints the Markdown tables of docs/figures.md that come from the renderer: the
# pond under each knob (accuracy against the float reference, both ways, and host
# instructions per pixel from callgrind) and every water scene's accuracy.
# Usage: scripts/measure-figures.sh [TARN_BIN]   (after make; needs valgrind)
set -eu
cd "$(dirname "$0")/.."
TARN=${1:-build/release/tarn}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM

# "psnr / maxerr / over2 / over8" from a compare line
figures() {
    sed -E 's/.*psnr=([0-9.]+) maxerr=([0-9]+) over2=([0-9.]+%) over8=([0-9.]+%).*/\1 dB \/ \2 \/ \3 \/ \4/'
}

host_insn_per_pixel() { # SCENE PIXELS KNOBS...
    scene=$1 pixels=$2
    shift 2
    valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" \
        "$TARN" render "$scene" -o "$work/frame.png" "$@" >/dev/null 2>&1
    ir=$(callgrind_annotate --inclusive=yes "$work/cg.out" | grep -m1 tarn_render_frame | awk '{gsub(",", "", $1); print $1}')
    echo $((ir / pixels))
}

echo "| knob (default otherwise) | unsnapped | snapped | host insn/px |"
echo "| --- | --- | --- | --- |"
for knob in "" "--quality exact" "--quality fast" "--perspective span:4" "--perspective span:16" \
            "--perspective affine" "--recip-steps 2" "--recip-steps 0" "--fog-bits 16" "--depth 16" \
            "--subpixel 2" "--subpixel 5" "--subpixel 6" "--tile 16" "--tile 64" "--apron off" \
            "--apron off --tile 16" "--bins off" "--water-block 2" "--quality fast --water-block 1" \
            "--depth-interpolation plane" "--quality fast --depth-interpolation exact"; do
    # shellcheck disable=SC2086
    unsnapped=$("$TARN" compare scenes/pond.json $knob | tail -1 | figures)
    # shellcheck disable=SC2086
    snapped=$("$TARN" compare scenes/pond.json --snapped $knob | tail -1 | figures)
    # shellcheck disable=SC2086
    echo "| ${knob:-default} | $unsnapped | $snapped | $(host_insn_per_pixel scenes/pond.json 57600 $knob) |"
done
echo
echo "| scene | unsnapped | snapped |"
echo "| --- | --- | --- |"
for scene in pond beach murky lake underwater effects/fog effects/absorption effects/depth_colour \
             effects/ramp effects/refraction effects/normals effects/fresnel effects/foam \
             effects/sparkles effects/underwater; do
    echo "| $scene | $("$TARN" compare "scenes/$scene.json" | tail -1 | figures) |" \
         "$("$TARN" compare "scenes/$scene.json" --snapped | tail -1 | figures) |"
done
