# qemu-m0-still: the qemu-m0 board (the same chip, startup, memory and stack) with
# the pond baked --backdrop still: tarn bake draws the opaque objects and the
# water's still terms (fog, depth colour, fresnel, the lit surface) once, for this
# frame and quality, into a palette picture in flash (14-bit indices into 14,276
# colours padded to 16,384, each water pixel marked with its object, and the depth
# only where foam shows), and each frame finds only the water's moving terms over
# it: the highlights, a 2x2 block at a time, and the foam lines (docs/bake.md,
# "Still water"). Each channel lies within 1 of the scene drawn whole where a
# pixel finds its own highlight; the panel stream equals the host's render through
# the same backdrop (tarn render --backdrop still), byte for byte.
include boards/qemu-m0/board.mk
BOARD_BAKE_FLAGS := --quality fast --backdrop still
