/* gpio_lines.h: output lines (DC, reset, backlight, and the bit-banged SPI's SCK,
 * MOSI and CS) as a small interface, so the display backends can be driven by
 * libgpiod on a board and by an emulator in the tests.
 *
 * tarn_gpio_line_request() is implemented by exactly one of gpio_lines_gpiod1.c
 * (libgpiod 1.x, as Debian 12 ships), gpio_lines_gpiod2.c (libgpiod 2.x) or
 * gpio_lines_none.c (built without libgpiod): the Makefile picks it from
 * `pkg-config --modversion libgpiod`. */
#ifndef TARN_HOST_GPIO_LINES_H
#define TARN_HOST_GPIO_LINES_H

#include <stddef.h>
#include "error.h"

typedef struct {
    void *user;
    int (*set)(void *user, int value);   /* 0, or -1 when the line could not be driven */
    void (*release)(void *user);         /* gives the line back; NULL: nothing to do */
    char name[96];                       /* "--dc gpiochip0:25", for messages */
} tarn_gpio_line;

/* A "CHIP:OFFSET" option value ("gpiochip0:25", "/dev/gpiochip1:4"). 0, or -1 with a
 * message naming `option`. */
int tarn_gpio_parse_spec(const char *option, const char *spec, char *chip, size_t chip_size,
                         unsigned *offset, tarn_error *err);

/* Requests `offset` of `chip` as an output driven to `initial`, for consumer "tarn".
 * 0, or -1 with one line naming the option, the chip and line, and what to check
 * (no such chip, no such line, line busy and who holds it, no permission). */
int tarn_gpio_line_request(const char *option, const char *chip, unsigned offset, int initial,
                           tarn_gpio_line *line, tarn_error *err);

/* "gpiod1", "gpiod2" or "none": the library this build drives lines with. */
extern const char tarn_gpio_backend[];

/* Drives the line; a line that was never requested (set == NULL) is ignored. */
int tarn_gpio_line_set(tarn_gpio_line *line, int value);

/* Releases the line if it is held; safe to call twice. */
void tarn_gpio_line_release(tarn_gpio_line *line);

#endif
