#!/bin/sh
# Throughput of each panel link, from counted bytes and transfers (never wall time):
# `tarn show` through each backend's own code against the panel emulator, two frames
# of the pond (the second at +33 ms, so the water moved), on an ST7789 240x240.
#   link_bytes_per_s, link_fps: at the link's clock (spidev, emulator: --hz; MCP2210:
#     1 ms per USB command/response + its SPI bits at 12 Mbps)
#   ceiling_fps: a whole frame in bands at the SPI clock: the physical limit
#   gpio-spi: GPIO line changes per byte (its speed is the system call's, see wall_*)
# Usage: scripts/bench-panels.sh [HZ]   (TARN_BIN overrides build/release/tarn)
set -eu
tarn=${TARN_BIN:-build/release/tarn}
hz=${1:-62500000}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
printf '%-9s %-8s %5s %15s %14s %17s %9s %12s\n' link send tile bytes_per_frame frame2_bytes link_bytes_per_s link_fps ceiling_fps
for run in "panel bands 32" "panel tiles 16" "spidev bands 32" "spidev tiles 16" "gpio-spi bands 32" \
           "mcp2210 bands 32" "mcp2210 changed 16" "mcp2210 changed 32"; do
    set -- $run
    # frame 1 alone, then frames 1 and 2: the difference is what frame 2 cost
    one=$("$tarn" show scenes/pond.json --panel st7789-240x240 --display "emulator:$out/p.png" --via "$1" \
        --send "$2" --tile "$3" --hz "$hz" --frames 1)
    two=$("$tarn" show scenes/pond.json --panel st7789-240x240 --display "emulator:$out/p.png" --via "$1" \
        --send "$2" --tile "$3" --hz "$hz" --frames 2)
    field() { printf '%s\n' "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }
    first=$(field "$one" spi_bytes)
    both=$(field "$two" spi_bytes)
    rate=$(field "$two" link_bytes_per_s)
    fps=$(field "$two" link_fps)
    ceiling=$(field "$two" ceiling_fps)
    if [ "$1" = gpio-spi ]; then
        rate="$(awk -v t="$(field "$two" transfers)" -v b="$both" 'BEGIN { printf "%.1f sets/B", t / b }')"
        fps=-
        ceiling=-
    fi
    printf '%-9s %-8s %5s %15s %14s %17s %9s %12s\n' "$1" "$2" "$3" "$first" "$((both - first))" "$rate" "$fps" "$ceiling"
done
