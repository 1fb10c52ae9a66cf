# qemu_rv32.mk: an emulated RISC-V board under QEMU (qemu-rv32, qemu-rv32-400k).
# Startup (rv32_startup.S) and sections (rv32_sections.ld, after the board's
# MEMORY) are shared; the panel stream leaves through the machine's UART, whose
# registers are the board's own uart.h, and the report and the exit go through
# semihosting (qemu_rv32_io.c). Included at the end of the board's board.mk, which
# sets BOARD_DIR, BOARD_CPU, BOARD_QEMU_MACHINE (with BOARD_QEMU_OPTIONS, any the
# machine needs), the stack, the scenes and the bake flags. Variables read by
# firmware/firmware.mk.
BOARD_ARCH := riscv
BOARD_SRC := boards/common/rv32_startup.S boards/common/qemu_rv32_io.c boards/common/stack_peak.c \
	boards/common/semihosting.c
BOARD_INCLUDE := -Iboards/common -I$(BOARD_DIR)
BOARD_LDSCRIPT := $(BOARD_DIR)/link.ld
# where the stack starts (rv32_startup.S calls main with interrupts off), for
# firmware/stack_bound.sh
BOARD_STACK_ENTRY := main
BOARD_QEMU := qemu-system-riscv32
# $(1): the ELF; $(2): the host file the panel stream goes to (the UART); $(3): the
# report (semihosting)
BOARD_RUN = $(BOARD_QEMU) -M $(BOARD_QEMU_MACHINE) $(BOARD_QEMU_OPTIONS) -nographic -monitor none \
	-serial file:$(2) -icount shift=0 \
	-semihosting-config enable=on,target=native,arg=firmware,arg=$(3) -kernel $(1)
