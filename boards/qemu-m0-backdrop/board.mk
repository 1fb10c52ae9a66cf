# qemu-m0-backdrop: the qemu-m0 board (the same chip, startup, memory and stack) with
# the pond baked --backdrop on: tarn bake draws the opaque objects once, for this
# frame and quality, into a palette picture in flash (a 13-bit index a pixel into
# the colours it uses, and the depth around the water), and each frame draws only
# the water over it (docs/bake.md, "Backdrop"), refracting: a refracted sample is
# read from the picture wherever it lands, so the 18-pixel apron takes flash (the
# depth it keeps), not RAM. 18 pixels is the widest whose depth fits the microbit's
# flash beside the code; each water pixel finds its own effects (--water-block 1:
# refracted effects are never shared, so blocks would save nothing), and per-pixel
# perspective and a 64-entry exp2 shape only the picture and the fog's table,
# drawn on the host (docs/firmware.md, "Refraction in 16 KB"). The image is the
# same, byte for byte.
include boards/qemu-m0/board.mk
BOARD_BAKE_FLAGS := --quality fast --backdrop on --apron 18 --water-block 1 --exp2 64 --perspective pixel --depth 16
# a backdrop is one frame's picture: the still pond only (a moving scene's bake is refused)
BOARD_SCENES := scenes/pond.json
