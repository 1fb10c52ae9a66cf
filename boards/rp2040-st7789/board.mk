# rp2040-st7789: a real board, built and checked here but not run (no BOARD_RUN).
# RP2040 (Cortex-M0+ at 125 MHz, 264 KB SRAM, the Pico's 2 MB QSPI flash) with an
# ST7789 240x240 on SPI0, fed by DMA channel 0 while the next tile renders. The
# output to flash is firmware.uf2 (hold BOOTSEL, copy it). It renders the moving pond
# (the camera circling, each frame at the board's millisecond clock) at the balanced
# preset with depth on a plane (as qemu-m0-264k, which counts its instructions) in
# strips of 8 rows, on both cores sharing one ring of strips, each taking
# a strip's opaque pass or its water and send as it comes free (two rings, one a
# core, would not fit 264 KB; README.md gives the figures). Variables read by
# firmware/firmware.mk; the rest, as for every real board, from
# boards/common/real_board.mk.
BOARD_DIR := boards/rp2040-st7789
BOARD_CPU := -mcpu=cortex-m0plus -mthumb -mfloat-abi=soft
BOARD_STACK_BYTES := 8192
# the walk keeps 64 vertices transformed, projected and lit (tarn_config.h's
# TARN_VERTEX_CACHE_SLOTS; 16 elsewhere): each strip of the moving pond finds its
# vertices again, and 16 slots lost most of a grid row's; 1.5 KB more stack
BOARD_VERTEX_CACHE_SLOTS := 64
# both cores draw each frame (firmware/display_main.c, cores.c), sharing its memory
# (tarn_strip_pipeline_begin); each has its strip buffers and a stack of its own,
# core 1's in SRAM4-5 (link.ld), which leaves SRAM0-3 room for the vertex pass
BOARD_CORES := 2
BOARD_CORE_SPLIT := pipeline
BOARD_SCENES := scenes/pond-orbit.json
# 8-row strips: the ring and its spare strip fit beside the code in SRAM, where
# 16 rows would not; refraction's 24-pixel apron and the vertex pass, as
# qemu-m0-264k's: the ring two strips shorter holds every vertex found once a
# frame (docs/firmware.md, "Clock, memory and frame rate"); water's coordinates on
# its triangles, as qemu-m0-264k's
BOARD_BAKE_FLAGS := --quality balanced --depth-interpolation plane --frame strips --tile 8 --apron 24 --vertices frame --water-uv triangles
# the second stage the bootrom loads (checksummed at build time), and the UF2 output
BOARD_BOOT2 := boards/rp2040-st7789/boot2.S
BOARD_FLASH_BASE := 0x10000000
BOARD_UF2_FAMILY := 0xe48bff56
include boards/common/real_board.mk
BOARD_SRC += $(BOARD_DIR)/cores.c
# each core's stack for firmware/stack_bound.sh: core 0's from the reset handler, and
# core 1's, as large, from its entry; each starts the other's without calling it
BOARD_STACK_ENTRY += second_core_main:core
BOARD_SECOND_STACK_ENTRY := second_core_main reset_handler:core
# the core's stages that run once a pixel, a triangle or a vertex, their arithmetic
# and tables, and the panel's conversion, run from SRAM (copied there at reset):
# from flash every fetch the XIP cache misses is a quad read of the flash (boot2.S), and
# the scene's textures and meshes, which stay in flash, have the cache to themselves
BOARD_RAM_CODE := core/raster core/water core/math core/tile core/geometry core/panel
