#!/bin/sh
# check_real_boards.sh: what a user sees when a real board's build cannot work
# (make firmware-check runs it after check_firmware.sh; tests/test_real_boards.c
# checks the images that do build).
#
# - A scene too large for the board's RAM: the STM32F411 (128 KB) and its moving pond at
#   --tile 64, whose renderer alone needs 163,840 bytes as baked (tarn memory). The link must fail, say by
#   how many bytes RAM overflowed and what to change, and leave no firmware.elf.
# - A stack reserve smaller than the deepest call chain (firmware/stack_bound.sh):
#   the build must fail, saying how many bytes the chain needs.
# - A missing cross compiler: the build must stop before anything else, naming the
#   compiler and the package that has it.
# - A scene too large for a board's flash (the Cortex-M0's 256 KB): the link must fail
#   the same way, and with the static view suggest baking without it.
# - The budget boards (qemu-m0-264k, qemu-rv32-400k) hold their chip's RAM, not the
#   emulator's 4 MB or 128 MB: with a stack as large as the whole budget, the link
#   must fail, RAM overflowed.
#
# All build into build/firmware-bad/, so the real builds stay as they are. Each of these
# builds must fail: it prints nothing when it fails as it should, a FAIL line and the
# end of the build's output when it does not, then the totals.
set -u
board=stm32f411-st7789
dir=build/firmware-bad/$board
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

rm -rf "$dir"
scene=scenes/pond-orbit.json # the board's own (BOARD_SCENES)
needs=$(build/release/tarn memory $scene --tile 64 | sed -n 's/.* baked_bytes=\([0-9]*\) .*/\1/p')
out=$(make --no-print-directory firmware BOARD=$board FW_DIR=$dir BAKE_FLAGS="--tile 64" 2>&1)
status=$?
overflow=$(printf '%s\n' "$out" | grep -E "region .RAM. overflowed by [0-9]+ bytes" | head -1)
note=$(printf '%s\n' "$out" | grep -E "^tarn: $board has too little RAM for $scene \[--tile 64\]: the renderer needs $needs bytes and the stack 8192; bake with a smaller --tile" | head -1)
if [ $status -ne 0 ] && [ -n "$overflow" ] && [ -n "$note" ] && [ ! -e "$dir/firmware.elf" ]; then
    pass
else
    fail "$board with the pond at --tile 64 should fail to link, saying by how much and what to change (status $status):"
    printf '%s\n' "$out" | grep -v '^  [A-Z]\+ ' | tail -5
fi

# a stack reserve below the deepest call chain: refused at build time, no image
rm -rf "$dir"
out=$(make --no-print-directory firmware BOARD=$board FW_DIR=$dir BOARD_STACK_BYTES=2048 2>&1)
status=$?
if [ $status -ne 0 ] && [ ! -e "$dir/firmware.elf" ] && printf '%s\n' "$out" |
    grep -qE "^tarn: $board's deepest call chain needs [0-9]+ bytes of stack; it reserves 2048 \(BOARD_STACK_BYTES"; then
    pass
else
    fail "$board with a 2 KB stack should fail to build, naming the chain's bytes (status $status)"
    printf '%s\n' "$out" | tail -3
fi

out=$(make --no-print-directory firmware BOARD=$board FW_DIR=$dir FW_CROSS=no-such-arm-none-eabi- 2>&1)
status=$?
if [ $status -ne 0 ] && printf '%s\n' "$out" |
    grep -q "^tarn: no-such-arm-none-eabi-gcc not found; install it: sudo apt-get install gcc-arm-none-eabi"; then
    pass
else
    fail "$board without its compiler should stop naming it (status $status): $out"
fi

# a scene too large for a board's flash: a sphere of 8,192 vertices on the Cortex-M0's
# 256 KB. The link must fail saying by how much and what to change (with the static
# view, that its meshes would take less), and leave no firmware.elf.
m0_dir=build/firmware-bad/qemu-m0
mkdir -p build/firmware-bad
cat > build/firmware-bad/big-sphere.json <<'SCENE'
{
  "frame": {"width": 240, "height": 240},
  "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov": 60, "near": 0.1, "far": 100},
  "materials": {"red": {"colour": "#d0452f"}},
  "objects": [{"type": "sphere", "material": "red", "radius": 1, "segments": 128, "rings": 64}]
}
SCENE
for view in on off; do
    rm -rf "$m0_dir"
    out=$(make --no-print-directory firmware BOARD=qemu-m0 FW_DIR=$m0_dir SCENE=build/firmware-bad/big-sphere.json \
        BAKE_FLAGS="--quality fast --static-view $view" 2>&1)
    status=$?
    note=$(printf '%s\n' "$out" | grep "^tarn: qemu-m0's flash cannot hold build/firmware-bad/big-sphere.json: use smaller textures")
    suggests=$(printf '%s\n' "$note" | grep -c -- "or bake with --static-view off")
    if [ $status -ne 0 ] && [ ! -e "$m0_dir/firmware.elf" ] && [ -n "$note" ] &&
        printf '%s\n' "$out" | grep -qE "region .FLASH. overflowed by [0-9]+ bytes" &&
        [ "$suggests" -eq "$([ $view = on ] && echo 1 || echo 0)" ]; then
        pass
    else
        fail "qemu-m0 with a sphere too large for its flash (--static-view $view) should fail to link, saying what to change (status $status):"
        printf '%s\n' "$out" | grep -v '^  [A-Z]\+ ' | tail -4
    fi
done

# the pond's backdrop at 240x400 (a palette index and the water's depth for 96,000
# pixels) overflows the same flash: the note says the backdrop can go
rm -rf "$m0_dir"
out=$(make --no-print-directory firmware BOARD=qemu-m0 FW_DIR=$m0_dir SCENE=scenes/pond.json \
    BAKE_FLAGS="--quality fast --backdrop on --size 240x400" 2>&1)
status=$?
if [ $status -ne 0 ] && [ ! -e "$m0_dir/firmware.elf" ] &&
    printf '%s\n' "$out" | grep -qE "region .FLASH. overflowed by [0-9]+ bytes" &&
    printf '%s\n' "$out" | grep "^tarn: qemu-m0's flash cannot hold scenes/pond.json" | grep -q -- "or bake without --backdrop:"; then
    pass
else
    fail "qemu-m0 with a backdrop too large for its flash should fail to link, saying the backdrop can go (status $status):"
    printf '%s\n' "$out" | grep -v '^  [A-Z]\+ ' | tail -4
fi

# the budget boards' RAM is the chip's: a stack of the whole budget leaves no room
for budget in qemu-m0-264k:264 qemu-rv32-400k:400; do
    b=${budget%:*} kb=${budget#*:}
    rm -rf "build/firmware-bad/$b"
    out=$(make --no-print-directory firmware BOARD=$b FW_BUILD_DIR=build/firmware-bad/$b \
        BOARD_STACK_BYTES=$((kb * 1024)) 2>&1)
    status=$?
    overflow=$(printf '%s\n' "$out" | grep -E "region .RAM. overflowed by [0-9]+ bytes" | head -1)
    if [ $status -ne 0 ] && [ ! -e "build/firmware-bad/$b/firmware.elf" ] && [ -n "$overflow" ] &&
        printf '%s\n' "$out" | grep -q "^tarn: $b has too little RAM for"; then
        pass
    else
        fail "$b with a stack of its whole ${kb} KB of RAM should fail to link, RAM overflowed (status $status):"
        printf '%s\n' "$out" | grep -v '^  [A-Z]\+ ' | tail -4
    fi
done

rm -rf build/firmware-bad
echo "real boards, builds that must fail: $passed refused as they should be, $failed not"
[ "$failed" -eq 0 ]
