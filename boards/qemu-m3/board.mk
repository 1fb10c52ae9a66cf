# qemu-m3: Cortex-M3 on QEMU's mps2-an385 (4 MB of RAM), rendering the full pond at
# the default quality. Variables read by firmware/firmware.mk.
BOARD_ARCH := arm
BOARD_CPU := -mcpu=cortex-m3 -mthumb -mfloat-abi=soft
BOARD_SRC := boards/common/cortex_m_startup.c boards/common/stack_peak.c boards/common/semihosting.c \
	boards/common/semihosted_io.c boards/qemu-m3/board.c
BOARD_INCLUDE := -Iboards/common
BOARD_LDSCRIPT := boards/qemu-m3/link.ld
BOARD_STACK_BYTES := 8192
# where the stack starts and what can interrupt it (handler:bytes the hardware pushes),
# for firmware/stack_bound.sh
BOARD_STACK_ENTRY := reset_handler systick_handler:36
BOARD_SCENE := scenes/pond.json
BOARD_BAKE_FLAGS :=
BOARD_QEMU := qemu-system-arm
# $(1): the ELF; $(2), $(3): the host files the panel stream and the report go to
BOARD_RUN = $(BOARD_QEMU) -M mps2-an385 -nographic -monitor none -serial none \
	-icount shift=0 -semihosting-config enable=on,target=native,arg=firmware,arg=$(2),arg=$(3) \
	-kernel $(1)
