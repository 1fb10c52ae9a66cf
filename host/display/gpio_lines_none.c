/* gpio_lines_none.c: the build found no libgpiod; every line request says so. */
#include "gpio_lines.h"

#include <string.h>

const char tarn_gpio_backend[] = "none";

int tarn_gpio_line_request(const char *option, const char *chip, unsigned offset, int initial,
                           tarn_gpio_line *line, tarn_error *err)
{
    (void)initial;
    memset(line, 0, sizeof *line);
    return tarn_fail(err, "%s: cannot drive %s:%u: this tarn was built without libgpiod "
                     "(install libgpiod-dev and rebuild)", option, chip, offset);
}
