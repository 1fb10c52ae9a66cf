# qemu-m0: Cortex-M0 on QEMU's microbit (nRF51: 256 KB flash, 16 KB RAM). It renders
# the pond, every water effect, at the fast preset (core/quality.c): the refraction
# apron off, 40-pixel tiles (6 x 6 for 240 x 240), a 16-bit depth buffer, span
# perspective, water blocks and cluster bins (baked, with the static view): 11,040
# bytes of renderer memory, with the stack 15,576 of the 16 KB of RAM (docs/firmware.md
# gives what fits and what does not). Variables read by firmware/firmware.mk.
BOARD_ARCH := arm
BOARD_CPU := -mcpu=cortex-m0 -mthumb -mfloat-abi=soft
BOARD_SRC := boards/common/cortex_m_startup.c boards/common/stack_peak.c boards/common/semihosting.c \
	boards/common/semihosted_io.c boards/qemu-m0/board.c
BOARD_INCLUDE := -Iboards/common
BOARD_LDSCRIPT := boards/qemu-m0/link.ld
# the static-screen walk (core/triangles.c) deepened the bound (4252 bytes now)
BOARD_STACK_BYTES := 4352
# the flash the firmware may take besides the scene's const data (issue 4's budget;
# tests/check_firmware.sh holds the image to it)
BOARD_CODE_BYTES_MAX := 32768
# where the stack starts and what can interrupt it (handler:bytes the hardware pushes),
# for firmware/stack_bound.sh
BOARD_STACK_ENTRY := reset_handler systick_handler:36
BOARD_SCENE := scenes/pond.json
BOARD_BAKE_FLAGS := --quality fast
BOARD_QEMU := qemu-system-arm
# $(1): the ELF; $(2), $(3): the host files the panel stream and the report go to
BOARD_RUN = $(BOARD_QEMU) -M microbit -nographic -monitor none -serial none \
	-icount shift=0 -semihosting-config enable=on,target=native,arg=firmware,arg=$(2),arg=$(3) \
	-kernel $(1)
