/* gpio_lines.c: what every line backend shares: option parsing, set, release. */
#include "gpio_lines.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

int tarn_gpio_parse_spec(const char *option, const char *spec, char *chip, size_t chip_size,
                         unsigned *offset, tarn_error *err)
{
    const char *colon = spec ? strrchr(spec, ':') : NULL;
    if (colon != NULL && colon != spec && (size_t)(colon - spec) < chip_size && colon[1] >= '0' &&
        colon[1] <= '9') {
        char *end;
        errno = 0;
        unsigned long value = strtoul(colon + 1, &end, 10);
        if (errno == 0 && *end == '\0' && value <= 1023) {
            memcpy(chip, spec, (size_t)(colon - spec));
            chip[colon - spec] = '\0';
            *offset = (unsigned)value;
            return 0;
        }
    }
    return tarn_fail(err, "%s: expected CHIP:LINE, e.g. gpiochip0:25 (see gpioinfo), got '%s'", option,
                     spec ? spec : "");
}

int tarn_gpio_line_set(tarn_gpio_line *line, int value)
{
    return line->set == NULL ? 0 : line->set(line->user, value);
}

void tarn_gpio_line_release(tarn_gpio_line *line)
{
    if (line->release != NULL) line->release(line->user);
    line->set = NULL;
    line->release = NULL;
    line->user = NULL;
}
