/* gpio_lines_gpiod2.c: output lines through libgpiod 2.x: a line request per line
 * (gpiod_chip_request_lines with one offset), gpiod_line_request_set_value. Built
 * instead of gpio_lines_gpiod1.c where pkg-config finds libgpiod 2. */
#include "gpio_lines.h"

#include <errno.h>
#include <gpiod.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char tarn_gpio_backend[] = "gpiod2";

typedef struct {
    struct gpiod_chip *chip;
    struct gpiod_line_request *request;
    unsigned offset;
} gpiod2_line;

static int gpiod2_set(void *user, int value)
{
    gpiod2_line *l = user;
    return gpiod_line_request_set_value(l->request, l->offset,
                                        value ? GPIOD_LINE_VALUE_ACTIVE : GPIOD_LINE_VALUE_INACTIVE) == 0
               ? 0
               : -1;
}

static void gpiod2_release(void *user)
{
    gpiod2_line *l = user;
    gpiod_line_request_release(l->request);
    gpiod_chip_close(l->chip);
    free(l);
}

/* The chip by name ("gpiochip0") or path ("/dev/gpiochip0"). */
static struct gpiod_chip *open_chip(const char *chip)
{
    char path[128];
    if (strchr(chip, '/') != NULL) return gpiod_chip_open(chip);
    snprintf(path, sizeof path, "/dev/%s", chip);
    return gpiod_chip_open(path);
}

/* Why a line cannot be had: it does not exist, or someone holds it. */
static int explain_line(const char *option, const char *chip, unsigned offset, struct gpiod_chip *c,
                        int request_errno, tarn_error *err)
{
    struct gpiod_chip_info *info = gpiod_chip_get_info(c);
    size_t lines = info ? gpiod_chip_info_get_num_lines(info) : 0;
    if (info) gpiod_chip_info_free(info);
    if (offset >= lines)
        return tarn_fail(err, "%s: %s has no line %u (it has %zu; check gpioinfo %s)", option, chip, offset,
                         lines, chip);
    struct gpiod_line_info *line = gpiod_chip_get_line_info(c, offset);
    char who[80] = "";
    if (line != NULL && gpiod_line_info_is_used(line) && gpiod_line_info_get_consumer(line))
        snprintf(who, sizeof who, " (held by '%s')", gpiod_line_info_get_consumer(line));
    if (line) gpiod_line_info_free(line);
    return tarn_fail(err, "%s: line %u of %s: %s%s (check gpioinfo %s)", option, offset, chip,
                     request_errno == EBUSY ? "busy" : strerror(request_errno), who, chip);
}

static struct gpiod_line_request *request_output(struct gpiod_chip *chip, unsigned offset, int initial)
{
    struct gpiod_line_settings *settings = gpiod_line_settings_new();
    struct gpiod_line_config *config = gpiod_line_config_new();
    struct gpiod_request_config *request_config = gpiod_request_config_new();
    struct gpiod_line_request *request = NULL;
    if (settings && config && request_config &&
        gpiod_line_settings_set_direction(settings, GPIOD_LINE_DIRECTION_OUTPUT) == 0 &&
        gpiod_line_settings_set_output_value(settings, initial ? GPIOD_LINE_VALUE_ACTIVE
                                                               : GPIOD_LINE_VALUE_INACTIVE) == 0 &&
        gpiod_line_config_add_line_settings(config, &offset, 1, settings) == 0) {
        gpiod_request_config_set_consumer(request_config, "tarn");
        request = gpiod_chip_request_lines(chip, request_config, config);
    }
    int e = errno;
    if (request_config) gpiod_request_config_free(request_config);
    if (config) gpiod_line_config_free(config);
    if (settings) gpiod_line_settings_free(settings);
    errno = e;
    return request;
}

int tarn_gpio_line_request(const char *option, const char *chip, unsigned offset, int initial,
                           tarn_gpio_line *line, tarn_error *err)
{
    memset(line, 0, sizeof *line);
    gpiod2_line *l = calloc(1, sizeof *l);
    if (l == NULL) return tarn_fail(err, "%s: out of memory", option);
    l->offset = offset;
    l->chip = open_chip(chip);
    if (l->chip == NULL) {
        int e = errno;
        free(l);
        return tarn_fail(err, "%s: cannot open GPIO chip '%s': %s (check gpiodetect and the permissions of /dev/gpiochip*)",
                         option, chip, strerror(e));
    }
    l->request = request_output(l->chip, offset, initial);
    if (l->request == NULL) {
        int e = errno;
        explain_line(option, chip, offset, l->chip, e, err);
        gpiod_chip_close(l->chip);
        free(l);
        return -1;
    }
    line->user = l;
    line->set = gpiod2_set;
    line->release = gpiod2_release;
    snprintf(line->name, sizeof line->name, "%s %s:%u", option, chip, offset);
    return 0;
}
