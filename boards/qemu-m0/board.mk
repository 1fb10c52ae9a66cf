# qemu-m0: Cortex-M0 on QEMU's microbit (nRF51: 256 KB flash, 16 KB RAM). It renders
# the pond, every water effect, at the fast preset (core/scene/presets.c): the refraction
# apron off, 40-pixel tiles (6 x 6 for 240 x 240), a 16-bit depth buffer, span
# perspective, water blocks and cluster bins (baked, with the static view): 11,040
# bytes of renderer memory, with the stack 15,576 of the 16 KB of RAM (docs/firmware.md
# gives what fits and what does not). Variables read by firmware/firmware.mk; the
# rest, as for every emulated Cortex-M board, from boards/common/qemu_cortex_m.mk.
BOARD_DIR := boards/qemu-m0
BOARD_CPU := -mcpu=cortex-m0 -mthumb -mfloat-abi=soft
BOARD_QEMU_MACHINE := microbit
# the static-screen walk (core/tile/walk.c) deepened the bound (4252 bytes now)
BOARD_STACK_BYTES := 4352
# the flash the firmware may take besides the scene's const data (issue 4's budget;
# tests/check_firmware.sh holds the image to it)
BOARD_CODE_BYTES_MAX := 32768
BOARD_SCENE := scenes/pond.json
BOARD_BAKE_FLAGS := --quality fast
include boards/common/qemu_cortex_m.mk
