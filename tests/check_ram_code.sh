#!/bin/sh
# check_ram_code.sh: the core run as the RP2040 runs it. No emulator here models the
# RP2040, so its build (boards/rp2040-st7789/board.mk: its bake flags, its cores
# sharing one ring of strips, BOARD_CORE_SPLIT, and its placement, BOARD_RAM_CODE:
# the objects renamed .ram.*, copied from flash with .data at reset) is built for
# qemu-m0-264k, the board that stands for it, and run there, with the code of those
# objects at RAM addresses. The run draws the frame by the strip pipeline's steps
# too, and fails unless its checksum is the whole frame's (firmware/main.c). It
# builds into build/firmware/qemu-m0-264k@ram-code, beside the board's own builds,
# where tests/test_firmware.c (make check, after this) finds the run and compares its
# frames with the host's, byte for byte. (tests/test_real_boards.c checks the
# RP2040's own image.)
set -u
board_value() { sed -n "s/^$1 := //p" boards/rp2040-st7789/board.mk; }
ram_code=$(board_value BOARD_RAM_CODE) split=$(board_value BOARD_CORE_SPLIT) flags=$(board_value BOARD_BAKE_FLAGS)
[ -n "$ram_code" ] || { echo "FAIL: boards/rp2040-st7789/board.mk sets no BOARD_RAM_CODE"; exit 1; }
dir=build/firmware/qemu-m0-264k@ram-code
out=$(make --no-print-directory firmware-run BOARD=qemu-m0-264k FW_BUILD_DIR=$dir BOARD_RAM_CODE="$ram_code" \
    BOARD_CORE_SPLIT="${split:-parts}" SCENE=scenes/pond-orbit.json BAKE_FLAGS="$flags" 2>&1) || {
    printf '%s\n' "$out" | tail -20
    echo "FAIL: qemu-m0-264k as the RP2040 builds it (the core in RAM: $ram_code; cores: ${split:-parts}; $flags) did not build or run"
    exit 1
}
# the first per-pixel function of the rasterizer, and the RAM the link gave it
address=$(arm-none-eabi-nm "$dir/firmware.elf" | awk '$3 == "tarn__raster_triangle" {print $1}')
case $address in
2*) ;;
*) echo "FAIL: $dir/firmware.elf: tarn__raster_triangle is at '${address:-nowhere}', not in RAM (0x20000000..)"; exit 1 ;;
esac
tests/check_firmware.sh "$dir" || exit 1
bytes=$(arm-none-eabi-size -A "$dir/firmware.elf" | awk '$1 == ".data" {print $2}')
echo "ram code: qemu-m0-264k as the RP2040 builds it ($bytes bytes of .data, tarn__raster_triangle at 0x$address; cores: ${split:-parts}) ran; make check compares its frames"
