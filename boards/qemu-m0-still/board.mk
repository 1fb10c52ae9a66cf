# qemu-m0-still: the qemu-m0 board (the same chip, startup, memory and stack) with
# the pond baked --backdrop still: tarn bake draws the opaque objects and the
# water's still terms (fog, depth colour, fresnel, the lit surface) once, for this
# frame and quality, into a palette picture in flash (a 14-bit index a pixel into
# the colours it uses, each water pixel marked with its object and where foam can
# show, and the depth of water where it is under one unit, or under 1.25 units
# (--landing-depth 1.25, as much as the flash holds) where a refracted sample may
# land within a foam band; docs/firmware.md gives the bytes), and each frame finds
# only the water's moving terms over it: the highlights, once a 4x4 block
# (--water-block 4), the foam lines (docs/bake.md, "Still water") and, with an apron
# (--apron on), each water pixel's refracted sample, read from the picture wherever
# it lands, so the apron takes no RAM. The panel stream equals the host's render
# through the same backdrop (tarn render --backdrop still), byte for byte.
# Per-pixel perspective and 32-bit depth shape only the picture, drawn on the host:
# they cost the board nothing and bring the pond 1.2 dB nearer the reference
# (docs/firmware.md, "Still water").
include boards/qemu-m0/board.mk
BOARD_BAKE_FLAGS := --quality fast --backdrop still --landing-depth 1.25 --water-block 4 --apron on --perspective pixel --depth 32
# a backdrop is one frame's picture: the still pond only (a moving scene's bake is refused)
BOARD_SCENES := scenes/pond.json
