/* panel_pins.h: where the ST7789 module connects to the STM32F411 (README.md has
 * the wiring table). SCK and MOSI are fixed by SPI1's alternate function; the
 * others are plain outputs, chosen to be free on both a WeAct "Black Pill" and a
 * Nucleo-F411RE. */
#ifndef TARN_STM32F411_PANEL_PINS_H
#define TARN_STM32F411_PANEL_PINS_H

#include "stm32f411.h"

#define PANEL_SCK_PORT GPIOA_BASE  /* PA5, SPI1_SCK, AF5 */
#define PANEL_SCK_PIN 5u
#define PANEL_MOSI_PORT GPIOA_BASE /* PA7, SPI1_MOSI, AF5 */
#define PANEL_MOSI_PIN 7u
#define PANEL_CS_PORT GPIOA_BASE   /* PA4: CS, active low */
#define PANEL_CS_PIN 4u
#define PANEL_DC_PORT GPIOB_BASE   /* PB0: D/CX, low for a command */
#define PANEL_DC_PIN 0u
#define PANEL_RESET_PORT GPIOB_BASE /* PB1: RESX, active low */
#define PANEL_RESET_PIN 1u
#define PANEL_BACKLIGHT_PORT GPIOB_BASE /* PB10: BLK, high lights the backlight */
#define PANEL_BACKLIGHT_PIN 10u

#endif
