# stm32f411-st7789: a real board, built and checked here but not run (no BOARD_RUN).
# STM32F411 (Cortex-M4 at 100 MHz, 512 KB flash, 128 KB RAM) with an ST7789 240x240
# on SPI1, fed by DMA2 while the next tile renders. It renders the moving pond (the
# camera circling, each frame at the board's millisecond clock) at the
# balanced preset with depth on a plane and water's coordinates on its triangles
# (as qemu-m0-264k), in 48-pixel tiles with a 24-pixel refraction apron: its
# renderer memory, two tile buffers and an 8 KB stack in the 128 KB (README.md
# gives the figures). Variables read by
# firmware/firmware.mk; the rest, as for every real board, from
# boards/common/real_board.mk.
#
# The float ABI is soft (-mfloat-abi=soft): the core has no float, so the M4F's FPU
# stays off, nothing saves FPU registers on an interrupt, and newlib's nofp
# multilib provides memset/memcpy.
BOARD_DIR := boards/stm32f411-st7789
BOARD_CPU := -mcpu=cortex-m4 -mthumb -mfloat-abi=soft
BOARD_STACK_BYTES := 8192
# the walk keeps 64 vertices transformed, projected and lit (tarn_config.h's
# TARN_VERTEX_CACHE_SLOTS; 16 on the 16 KB boards): each tile of the moving pond
# finds its vertices again, and 16 slots lost most of a grid row's; 1.5 KB more stack
BOARD_VERTEX_CACHE_SLOTS := 64
BOARD_SCENES := scenes/pond-orbit.json
# 48-pixel tiles, each drawing the opaque scene 24 pixels around itself for
# refraction: a tile redraws its apron four times over its own pixels, where the
# default's 32-pixel tiles with the whole 32-pixel apron redrew it nine times: half
# the instructions a pixel, at the panel PSNR of the RAM boards' quality, well above
# the 40 dB issue 22 asks of a moving scene (README.md gives both); the largest such
# tiles that divide the frame and leave the RAM room for an application's own
BOARD_BAKE_FLAGS := --quality balanced --depth-interpolation plane --water-uv triangles --tile 48 --apron 24
include boards/common/real_board.mk
