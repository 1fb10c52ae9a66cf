/* panel_spi.h: what a real board's SPI, DMA and panel pins give dma_transport.c.
 * Each real board implements these in its panel_spi.c; board_init()
 * (boards/common/real_board.c) has already set the pins, the SPI and the DMA channel
 * up through panel_spi_init().
 *
 * A transfer is started and then polled: nothing here waits, so that the
 * transport alone owns every timeout. */
#ifndef TARN_FIRMWARE_PANEL_SPI_H
#define TARN_FIRMWARE_PANEL_SPI_H

#include <stddef.h>
#include <stdint.h>

/* The longest transfer panel_spi_start takes (the STM32's NDTR is 16 bits). */
#define PANEL_SPI_TRANSFER_MAX 65535u

/* Sets the pins, the SPI and the DMA channel up, once the clocks run (clock_init):
 * reset released, D/CX high, CS asserted for good and the backlight on. */
void panel_spi_init(void);

/* The D/CX line: 0 command, 1 data. Only while panel_spi_poll() says idle. */
void panel_spi_dc(int data);

/* The panel's RESX line (active low on the pin): 1 holds the panel in reset. */
void panel_spi_reset_line(int asserted);

/* Starts sending `count` bytes (1..PANEL_SPI_TRANSFER_MAX) by DMA and returns at
 * once; the bytes must stay untouched until panel_spi_poll() returns 0. Only while
 * idle. */
void panel_spi_start(const uint8_t *bytes, size_t count);

/* 0: idle (the DMA is done and the SPI has shifted the last bit out), 1: still
 * sending, -1: the DMA reported a bus error. */
int panel_spi_poll(void);

/* Stops a transfer (after a timeout or an error) and clears the DMA's error flags,
 * so that the next panel_spi_start begins from a clean state. */
void panel_spi_abort(void);

#endif
