# qemu-m0-backdrop: the qemu-m0 board (the same chip, startup, memory and stack) with
# the pond baked --backdrop on: tarn bake draws the opaque objects once, for this
# frame and quality, into a palette picture in flash (13-bit indices into 5,719
# colours padded to 8,192, and the depth around the water: 181,214 bytes; the image
# takes 258,860 of the 262,144), and each frame draws only the water over it
# (docs/bake.md, "Backdrop"). The image is the same, byte for byte; the flash buys
# the cost of the opaque pass (docs/firmware.md).
include boards/qemu-m0/board.mk
BOARD_BAKE_FLAGS := --quality fast --backdrop on
# a backdrop is one frame's picture: the still pond only (a moving scene's bake is refused)
BOARD_SCENES := scenes/pond.json
