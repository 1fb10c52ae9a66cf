# qemu-rv32-400k: rv32imc code on QEMU's riscv32 virt, held by its link.ld to the
# ESP32-C3's 4 MB of flash and 400 KB of RAM. It renders as qemu-m0-264k does: the
# moving pond and the same scene without its water, at the balanced preset with
# depth on a plane, in strips of the whole width (12 rows and a 24-pixel apron
# with water, 64 rows without), each opaque pixel drawn once and every vertex
# found once a frame, within 200 KB. Variables read by
# firmware/firmware.mk; the rest, as for every emulated RISC-V board, from
# boards/common/qemu_rv32.mk.
BOARD_DIR := boards/qemu-rv32-400k
BOARD_CPU := -march=rv32imc_zicsr -mabi=ilp32 -mcmodel=medany
BOARD_QEMU_MACHINE := virt
# no firmware before ours: the reset vector jumps straight to RAM's start, the image
BOARD_QEMU_OPTIONS := -bios none
BOARD_STACK_BYTES := 8192
# the walk keeps 64 vertices transformed, projected and lit (tarn_config.h's
# TARN_VERTEX_CACHE_SLOTS; 16 elsewhere): each strip of the moving pond finds its
# vertices again, and 16 slots lost most of a grid row's; 1.5 KB more stack
BOARD_VERTEX_CACHE_SLOTS := 64
# the scenes make bench-target measures, a line each; the first is the board's own
# build (build/firmware/qemu-rv32-400k), each other one builds in
# build/firmware/qemu-rv32-400k@NAME
BOARD_SCENES := scenes/pond-orbit.json scenes/pond-opaque.json
# water's coordinates on its triangles, as qemu-m0-264k's (boards/qemu-m0-264k/board.mk)
BOARD_BAKE_FLAGS := --quality balanced --depth-interpolation plane --frame strips --tile 12 --apron 24 --vertices frame --water-uv triangles
# without water nothing refracts: one strip is the ring, and taller strips cut
# fewer triangles in two; the room left keeps each vertex's view position too
# (--vertices frame-view), which the triangles clipped at the guard band read
# instead of transforming their vertices again
BOARD_BAKE_FLAGS.pond-opaque := --quality balanced --depth-interpolation plane --frame strips --tile 64 --vertices frame-view
include boards/common/qemu_rv32.mk
