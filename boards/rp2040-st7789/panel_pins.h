/* panel_pins.h: where the ST7789 module connects to the RP2040 (README.md has the
 * wiring table, with the Pico's pin numbers). SCK and TX are SPI0's (function 1 on
 * GPIO18 and GPIO19); the others are SIO outputs next to them on the same side of
 * a Pico. */
#ifndef TARN_RP2040_PANEL_PINS_H
#define TARN_RP2040_PANEL_PINS_H

#define PANEL_DC_GPIO 16u        /* D/CX, low for a command */
#define PANEL_CS_GPIO 17u        /* CS, active low */
#define PANEL_SCK_GPIO 18u       /* SPI0 SCK */
#define PANEL_TX_GPIO 19u        /* SPI0 TX: the panel's SDA/MOSI */
#define PANEL_BACKLIGHT_GPIO 20u /* BLK, high lights the backlight */
#define PANEL_RESET_GPIO 21u     /* RESX, active low */

#endif
