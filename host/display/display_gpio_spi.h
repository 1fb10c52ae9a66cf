/* display_gpio_spi.h: SPI bit-banged on GPIO lines, for boards whose SPI controller
 * is taken. Mode 0, MSB first: MOSI is set (only when it changes), SCK rises (the
 * panel samples), SCK falls. Each edge is a GPIO ioctl through libgpiod, so the
 * link runs at the speed of system calls: `tarn show` measures and prints it. */
#ifndef TARN_HOST_DISPLAY_GPIO_SPI_H
#define TARN_HOST_DISPLAY_GPIO_SPI_H

#include "gpio_lines.h"
#include "panel_link.h"
#include "tarn/tarn_panel.h"

typedef struct {
    tarn_panel_link link;                         /* first (panel_link.h); its counts'
                                                     transfers are line sets, and no
                                                     link_ns is modelled */
    tarn_gpio_line *sck, *mosi, *cs, *dc, *reset; /* reset may hold no line */
    int mosi_level, dc_level;                     /* -1: not driven yet */
} tarn_gpio_spi;

/* Lines already requested by the caller; SCK low, CS high. */
void tarn_gpio_spi_init(tarn_gpio_spi *spi, tarn_gpio_line *sck, tarn_gpio_line *mosi, tarn_gpio_line *cs,
                        tarn_gpio_line *dc, tarn_gpio_line *reset);

tarn_panel_transport tarn_gpio_spi_transport(tarn_gpio_spi *spi);

#endif
