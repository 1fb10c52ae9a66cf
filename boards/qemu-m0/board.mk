# qemu-m0: Cortex-M0 on QEMU's microbit (nRF51: 256 KB flash, 16 KB RAM). The pond's
# const data alone (261 KB) is larger than the flash, so this board renders the beach,
# another 240x240 water scene, with the refraction apron off, 32-pixel tiles and a
# 16-bit depth buffer: 12288 bytes of renderer memory, 16048 of the 16384 bytes of RAM
# with the stack (docs/firmware.md gives what fits and what does not). Variables read
# by firmware/firmware.mk.
BOARD_ARCH := arm
BOARD_CPU := -mcpu=cortex-m0 -mthumb -mfloat-abi=soft
BOARD_SRC := boards/common/cortex_m_startup.c boards/common/semihosting.c \
	boards/common/semihosted_io.c boards/qemu-m0/board.c
BOARD_INCLUDE := -Iboards/common
BOARD_LDSCRIPT := boards/qemu-m0/link.ld
BOARD_STACK_BYTES := 3584
# where the stack starts and what can interrupt it (handler:bytes the hardware pushes),
# for firmware/stack_bound.sh
BOARD_STACK_ENTRY := reset_handler systick_handler:36
BOARD_SCENE := scenes/beach.json
BOARD_BAKE_FLAGS := --apron off --tile 32 --depth 16
BOARD_QEMU := qemu-system-arm
# $(1): the ELF; $(2), $(3): the host files the panel stream and the report go to
BOARD_RUN = $(BOARD_QEMU) -M microbit -nographic -monitor none -serial none \
	-icount shift=0 -semihosting-config enable=on,target=native,arg=firmware,arg=$(2),arg=$(3) \
	-kernel $(1)
