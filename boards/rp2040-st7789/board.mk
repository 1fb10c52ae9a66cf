# rp2040-st7789: a real board, built and checked here but not run (no BOARD_RUN).
# RP2040 (Cortex-M0+ at 125 MHz, 264 KB SRAM, the Pico's 2 MB QSPI flash) with an
# ST7789 240x240 on SPI0, fed by DMA channel 0 while the next tile renders. The
# output to flash is firmware.uf2 (hold BOOTSEL, copy it). It renders the full pond
# at the default quality: 81,920 bytes of renderer memory, two 8,192-byte tile
# buffers and an 8 KB stack in 256 KB (README.md gives the figures). Variables read
# by firmware/firmware.mk.
BOARD_ARCH := arm
BOARD_CPU := -mcpu=cortex-m0plus -mthumb -mfloat-abi=soft
BOARD_SRC := boards/common/cortex_m_startup.c boards/common/real_board.c \
	boards/rp2040-st7789/clock.c boards/rp2040-st7789/panel_spi.c
BOARD_INCLUDE := -Iboards/common -Iboards/rp2040-st7789
BOARD_LDSCRIPT := boards/rp2040-st7789/link.ld
BOARD_STACK_BYTES := 8192
# where the stack starts and what can interrupt it (handler:bytes the hardware pushes),
# for firmware/stack_bound.sh
BOARD_STACK_ENTRY := reset_handler systick_handler:36
BOARD_SCENE := scenes/pond.json
BOARD_BAKE_FLAGS :=
# the second stage the bootrom loads (checksummed at build time), and the UF2 output
BOARD_BOOT2 := boards/rp2040-st7789/boot2.S
BOARD_FLASH_BASE := 0x10000000
BOARD_UF2_FAMILY := 0xe48bff56
