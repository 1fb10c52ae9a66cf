# qemu-m3: Cortex-M3 on QEMU's mps2-an385 (4 MB of RAM), rendering the full pond, and
# the moving pond the real boards loop, at
# the default quality. Variables read by firmware/firmware.mk; the rest, as for
# every emulated Cortex-M board, from boards/common/qemu_cortex_m.mk.
BOARD_DIR := boards/qemu-m3
BOARD_CPU := -mcpu=cortex-m3 -mthumb -mfloat-abi=soft
BOARD_QEMU_MACHINE := mps2-an385
BOARD_STACK_BYTES := 8192
# the walk keeps 64 vertices transformed, projected and lit (tarn_config.h's
# TARN_VERTEX_CACHE_SLOTS; 16 on the 16 KB boards): each tile of the moving pond
# finds its vertices again, and 16 slots lost most of a grid row's; 1.5 KB more stack
BOARD_VERTEX_CACHE_SLOTS := 64
BOARD_SCENES := scenes/pond.json scenes/pond-orbit.json
BOARD_BAKE_FLAGS :=
include boards/common/qemu_cortex_m.mk
