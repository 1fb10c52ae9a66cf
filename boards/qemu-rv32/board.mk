# qemu-rv32: RISC-V rv32imac on QEMU's sifive_e (16 KB of RAM at 0x80000000, the
# image in the XIP flash window, as the HiFive1's 16 MB SPI flash would hold it). The
# full pond fits the flash; RAM takes the fast preset (qemu-m0's quality without
# its refraction apron): 40-pixel tiles, 16-bit depth, cluster bins and a 4224-byte
# stack (15,904 of 16,384 bytes: 4 KB until the clipper kept 16 bits below Q16.16 of a
# cut vertex, core/geometry/clip.c). Variables read by firmware/firmware.mk.
BOARD_ARCH := riscv
BOARD_CPU := -march=rv32imac_zicsr -mabi=ilp32 -mcmodel=medany
BOARD_SRC := boards/qemu-rv32/startup.S boards/qemu-rv32/board.c boards/common/stack_peak.c \
	boards/common/semihosting.c
BOARD_INCLUDE := -Iboards/common
BOARD_LDSCRIPT := boards/qemu-rv32/link.ld
BOARD_STACK_BYTES := 4224
# where the stack starts (startup.S calls main with interrupts off), for
# firmware/stack_bound.sh
BOARD_STACK_ENTRY := main
BOARD_SCENE := scenes/pond.json
BOARD_BAKE_FLAGS := --quality fast
BOARD_QEMU := qemu-system-riscv32
# $(1): the ELF; $(2): the host file the panel stream goes to (UART0); $(3): the
# report (semihosting)
BOARD_RUN = $(BOARD_QEMU) -M sifive_e -nographic -monitor none -serial file:$(2) \
	-icount shift=0 -semihosting-config enable=on,target=native,arg=firmware,arg=$(3) \
	-kernel $(1)
