# qemu-rv32: RISC-V rv32imac on QEMU's sifive_e (16 KB of RAM at 0x80000000, the
# image in the XIP flash window, as the HiFive1's 16 MB SPI flash would hold it). The
# full pond fits the flash; RAM takes the fast preset (qemu-m0's quality without
# its refraction apron): 40-pixel tiles, 16-bit depth, cluster bins and a 4352-byte
# stack (4 KB until the clipper kept 16 bits below Q16.16 of a
# cut vertex, core/geometry/clip.c; 4224 until a sliver's planes divided exactly,
# core/raster/triangle_setup.c; 4320 until a triangle's setup kept the line its lit
# colour may lie on, tarn_lit_line). Variables read by firmware/firmware.mk; the
# rest, as for every emulated RISC-V board, from boards/common/qemu_rv32.mk.
BOARD_DIR := boards/qemu-rv32
BOARD_CPU := -march=rv32imac_zicsr -mabi=ilp32 -mcmodel=medany
BOARD_QEMU_MACHINE := sifive_e
BOARD_STACK_BYTES := 4352
BOARD_SCENES := scenes/pond.json scenes/pond-orbit.json
BOARD_BAKE_FLAGS := --quality fast
# the moving pond finds its clusters' bins in RAM and poses its objects there:
# beside them fits qemu-m0's quality for it, refraction with an 8-pixel apron
BOARD_BAKE_FLAGS.pond-orbit := --quality fast --apron 8 --tile 16 --water-block 1
include boards/common/qemu_rv32.mk
