/* gpio_lines_gpiod1.c: output lines through libgpiod 1.x (Debian 12 ships 1.6):
 * gpiod_chip_open_lookup, gpiod_chip_get_line, gpiod_line_request_output,
 * gpiod_line_set_value, gpiod_line_release. */
#include "gpio_lines.h"

#include <errno.h>
#include <gpiod.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char tarn_gpio_backend[] = "gpiod1";

typedef struct {
    struct gpiod_chip *chip;
    struct gpiod_line *line;
} gpiod1_line;

static int gpiod1_set(void *user, int value)
{
    gpiod1_line *l = user;
    return gpiod_line_set_value(l->line, value ? 1 : 0) == 0 ? 0 : -1;
}

static void gpiod1_release(void *user)
{
    gpiod1_line *l = user;
    gpiod_line_release(l->line);
    gpiod_chip_close(l->chip);
    free(l);
}

int tarn_gpio_line_request(const char *option, const char *chip, unsigned offset, int initial,
                           tarn_gpio_line *line, tarn_error *err)
{
    memset(line, 0, sizeof *line);
    gpiod1_line *l = calloc(1, sizeof *l);
    if (l == NULL) return tarn_fail(err, "%s: out of memory", option);
    l->chip = gpiod_chip_open_lookup(chip);
    if (l->chip == NULL) {
        int e = errno;
        free(l);
        return tarn_fail(err, "%s: cannot open GPIO chip '%s': %s (check gpiodetect and the permissions of /dev/gpiochip*)",
                         option, chip, strerror(e));
    }
    unsigned lines = gpiod_chip_num_lines(l->chip);
    l->line = offset < lines ? gpiod_chip_get_line(l->chip, offset) : NULL;
    if (l->line == NULL) {
        gpiod_chip_close(l->chip);
        free(l);
        return tarn_fail(err, "%s: %s has no line %u (it has %u; check gpioinfo %s)", option, chip, offset,
                         lines, chip);
    }
    if (gpiod_line_request_output(l->line, "tarn", initial ? 1 : 0) != 0) {
        int e = errno;
        const char *holder = gpiod_line_consumer(l->line);
        char who[80] = "";
        if (holder != NULL) snprintf(who, sizeof who, " (held by '%s')", holder);
        gpiod_chip_close(l->chip);
        free(l);
        return tarn_fail(err, "%s: line %u of %s: %s%s (check gpioinfo %s)", option, offset, chip,
                         e == EBUSY ? "busy" : strerror(e), who, chip);
    }
    line->user = l;
    line->set = gpiod1_set;
    line->release = gpiod1_release;
    snprintf(line->name, sizeof line->name, "%s %s:%u", option, chip, offset);
    return 0;
}
