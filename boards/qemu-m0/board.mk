# qemu-m0: Cortex-M0 on QEMU's microbit (nRF51: 256 KB flash, 16 KB RAM). It renders
# the pond, every water effect, at the fast preset (core/scene/presets.c: a 16-bit
# depth buffer, span perspective, cluster bins, baked with the static view) with
# refraction: a 12-pixel apron, the opaque scene drawn that far around each 16-pixel
# tile for the refracted samples to read, and no water blocks, which share nothing
# that refracts: its renderer memory and stack within the 16 KB of RAM
# (docs/firmware.md's table gives the bytes). The widest apron that fits at a cost within five times the fast preset's
# (docs/firmware.md, "Refraction in 16 KB", measures the others). Variables read by
# firmware/firmware.mk; the rest, as for every emulated Cortex-M board, from
# boards/common/qemu_cortex_m.mk.
BOARD_DIR := boards/qemu-m0
BOARD_CPU := -mcpu=cortex-m0 -mthumb -mfloat-abi=soft
BOARD_QEMU_MACHINE := microbit
# the deepest bound of the builds make test bakes for this board, 4612 bytes
# (tests/check_firmware_link.sh's fog with --water-block 2: the water triangle's
# loop down to a sliver's exact plane division in core/raster/triangle_setup.c;
# 4556 until a triangle's setup kept the line its lit colour may lie on, 4604
# until floor shifts took the arithmetic shift), within a reserve a few words over it
BOARD_STACK_BYTES := 4640
# the flash the firmware may take besides the scene's const data (issue 4's budget;
# tests/check_firmware.sh holds the image to it)
BOARD_CODE_BYTES_MAX := 32768
BOARD_SCENES := scenes/pond.json scenes/pond-orbit.json
BOARD_BAKE_FLAGS := --quality fast --apron 12 --tile 16 --water-block 1
# The moving pond: each frame poses the scene and transforms, lights and projects
# every vertex, and finds the clusters' bins (4 bytes each) in RAM, which a static
# view spares. What fits 16 KB beside them is an 8-pixel apron. Its image links the
# vertex pipeline, the bins and the motion a static view leaves out, so its code is
# held to 40 KB instead of the 32 KB above (docs/firmware.md gives the figures).
BOARD_BAKE_FLAGS.pond-orbit := --quality fast --apron 8 --tile 16 --water-block 1
BOARD_CODE_BYTES_MAX.pond-orbit := 40960
include boards/common/qemu_cortex_m.mk
