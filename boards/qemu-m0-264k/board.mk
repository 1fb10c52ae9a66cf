# qemu-m0-264k: Cortex-M0 code on QEMU's mps2-an385 (whose CPU is a Cortex-M3:
# ARMv6-M code runs on it unchanged), held by its link.ld to the RP2040's 2 MB of
# flash and 264 KB of RAM. It renders at the exact preset (core/scene/presets.c:
# refraction with the full apron, 32-bit depth, per-pixel perspective, the finest
# tables) in 64-pixel tiles, the largest the core takes: 163,840 bytes of renderer
# memory, 172,216 of the 270,336 bytes of RAM with the 8 KB stack. Exact rather
# than balanced: 62.12 dB panel PSNR instead of 59.56 for about 5% more
# instructions (4949 a pixel against 4724); 64-pixel tiles rather than the preset's
# 32: the apron each tile draws around itself is a smaller share of it, which
# halves the cost and leaves the image as it is. The stack's bound is 4.4 KB; the
# 8 KB reserved (as on qemu-m3) leave room for the moving scenes of issue 21.
# Variables read by firmware/firmware.mk; the rest, as for every emulated Cortex-M
# board, from boards/common/qemu_cortex_m.mk.
BOARD_DIR := boards/qemu-m0-264k
BOARD_CPU := -mcpu=cortex-m0 -mthumb -mfloat-abi=soft
BOARD_QEMU_MACHINE := mps2-an385
BOARD_STACK_BYTES := 8192
# the scenes make bench-target measures, a line each; the first is the board's own
# build (build/firmware/qemu-m0-264k), each other one builds in
# build/firmware/qemu-m0-264k@NAME
BOARD_SCENES := scenes/pond.json scenes/pond-opaque.json
BOARD_BAKE_FLAGS := --quality exact --tile 64
include boards/common/qemu_cortex_m.mk
