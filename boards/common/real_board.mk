# real_board.mk: a real Cortex-M board, built and checked here but never run (it
# gives no BOARD_RUN). board.h's side is real_board.c; the board's folder gives
# clock.h and clock.c (its clocks) and panel_spi.c (its pins, SPI and DMA), and
# headers from its folder are on the include path. Included at the end of the
# board's board.mk, which sets BOARD_DIR, BOARD_CPU, the stack, the scene and the
# bake flags.
include boards/common/cortex_m.mk
BOARD_SRC += boards/common/real_board.c $(BOARD_DIR)/clock.c $(BOARD_DIR)/panel_spi.c
BOARD_INCLUDE += -I$(BOARD_DIR)
