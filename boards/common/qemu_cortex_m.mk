# qemu_cortex_m.mk: an emulated Cortex-M board under QEMU (qemu-m0, qemu-m0-264k,
# qemu-m3). The panel stream and the report go to host files through semihosting
# (semihosted_io.c); the instruction counter is the QEMU machine's
# (qemu_MACHINE.c: its SysTick's clock, so boards on one machine share it).
# Included at the end of the board's board.mk, which sets BOARD_DIR,
# BOARD_CPU, BOARD_QEMU_MACHINE, the stack, the scenes and the bake flags.
include boards/common/cortex_m.mk
BOARD_SRC += boards/common/stack_peak.c boards/common/semihosting.c \
	boards/common/semihosted_io.c boards/common/qemu_$(subst -,_,$(BOARD_QEMU_MACHINE)).c
BOARD_QEMU := qemu-system-arm
# $(1): the ELF; $(2), $(3): the host files the panel stream and the report go to,
# words 1 and 2 of the semihosting command line as semihosted_io.c reads them
BOARD_RUN = $(BOARD_QEMU) -M $(BOARD_QEMU_MACHINE) -nographic -monitor none -serial none \
	-icount shift=0 -semihosting-config enable=on,target=native,arg=firmware,arg=$(2),arg=$(3) \
	-kernel $(1)
