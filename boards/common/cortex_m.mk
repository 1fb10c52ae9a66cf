# cortex_m.mk: what every Cortex-M board's build shares, included by
# qemu_cortex_m.mk and real_board.mk once the board's board.mk has set BOARD_DIR (its
# folder, which holds its link.ld). Variables read by firmware/firmware.mk.
BOARD_ARCH := arm
BOARD_SRC := boards/common/cortex_m_startup.c
BOARD_INCLUDE := -Iboards/common
BOARD_LDSCRIPT := $(BOARD_DIR)/link.ld
# where the stack starts and what can interrupt it, for firmware/stack_bound.sh:
# cortex_m_startup.c's reset handler, and SysTick, the one interrupt it enables, with
# the bytes the hardware pushes on entry (8 words, plus 4 of alignment; no FPU
# context with -mfloat-abi=soft)
BOARD_STACK_ENTRY := reset_handler systick_handler:36
