/* test_gpio_lines_gpiod1.c: the libgpiod 1.x backend against a GPIO chip emulated
 * at the library's own calls.
 *
 * No GPIO chip is attached to the build machine and the kernel has no gpio-sim, so
 * this file defines the libgpiod 1.x functions host/display/gpio_lines_gpiod1.c calls, and
 * the link takes them instead of the library's: a chip "gpiochip0" with 32 lines,
 * line 7 held by another consumer. It proves what a user sees when a line does not
 * exist or is busy, and that nothing stays requested or open after a failure,
 * including the lines a display had already requested before a later one failed.
 * Built only where the Makefile picks the libgpiod 1.x backend (Debian 12). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <gpiod.h>
#include <string.h>

#include "display.h"
#include "gpio_lines.h"

#define CHIP_LINES 32u
#define BUSY_LINE 7u

struct gpiod_chip {
    int open;
};
struct gpiod_line {
    unsigned offset;
    int requested, value;
};

static struct gpiod_chip chip;
static struct gpiod_line lines[CHIP_LINES];
static int chips_open, lines_requested;

static void reset_chip(void)
{
    memset(&chip, 0, sizeof chip);
    memset(lines, 0, sizeof lines);
    for (unsigned i = 0; i < CHIP_LINES; i++) lines[i].offset = i;
    chips_open = lines_requested = 0;
}

struct gpiod_chip *gpiod_chip_open_lookup(const char *descr)
{
    if (strcmp(descr, "gpiochip0") != 0) {
        errno = ENOENT;
        return NULL;
    }
    chips_open++;
    return &chip;
}

void gpiod_chip_close(struct gpiod_chip *c)
{
    (void)c;
    chips_open--;
}

unsigned int gpiod_chip_num_lines(struct gpiod_chip *c)
{
    (void)c;
    return CHIP_LINES;
}

struct gpiod_line *gpiod_chip_get_line(struct gpiod_chip *c, unsigned int offset)
{
    (void)c;
    if (offset >= CHIP_LINES) {
        errno = EINVAL;
        return NULL;
    }
    return &lines[offset];
}

int gpiod_line_request_output(struct gpiod_line *line, const char *consumer, int default_val)
{
    (void)consumer;
    if (line->offset == BUSY_LINE || line->requested) {
        errno = EBUSY;
        return -1;
    }
    line->requested = 1;
    line->value = default_val;
    lines_requested++;
    return 0;
}

const char *gpiod_line_consumer(struct gpiod_line *line)
{
    return line->offset == BUSY_LINE ? "spi0 CS0" : NULL;
}

int gpiod_line_set_value(struct gpiod_line *line, int value)
{
    if (!line->requested) {
        errno = EPERM;
        return -1;
    }
    line->value = value;
    return 0;
}

void gpiod_line_release(struct gpiod_line *line)
{
    if (line->requested) lines_requested--;
    line->requested = 0;
}

static void assert_request_fails(const char *chip_name, unsigned offset, const char *message)
{
    tarn_gpio_line line;
    tarn_error err;
    assert_int_not_equal(tarn_gpio_line_request("--dc", chip_name, offset, 1, &line, &err), 0);
    assert_string_equal(err.message, message);
    assert_int_equal(chips_open, 0);
    assert_int_equal(lines_requested, 0);
}

static void test_missing_and_busy_lines_say_which(void **state)
{
    (void)state;
    reset_chip();
    assert_string_equal(tarn_gpio_backend, "gpiod1");
    assert_request_fails("gpiochip0", 40, "--dc: gpiochip0 has no line 40 (it has 32; check gpioinfo gpiochip0)");
    assert_request_fails("gpiochip0", BUSY_LINE,
                         "--dc: line 7 of gpiochip0: busy (held by 'spi0 CS0') (check gpioinfo gpiochip0)");
    assert_request_fails("gpiochip5", 1,
                         "--dc: cannot open GPIO chip 'gpiochip5': No such file or directory (check gpiodetect and "
                         "the permissions of /dev/gpiochip*)");
}

static void test_a_line_is_driven_then_released(void **state)
{
    (void)state;
    reset_chip();
    tarn_gpio_line line;
    tarn_error err;
    assert_int_equal(tarn_gpio_line_request("--reset", "gpiochip0", 24, 1, &line, &err), 0);
    assert_int_equal(lines[24].value, 1); /* requested at its initial level */
    assert_int_equal(tarn_gpio_line_set(&line, 0), 0);
    assert_int_equal(lines[24].value, 0);
    tarn_gpio_line_release(&line);
    assert_int_equal(lines_requested, 0);
    assert_int_equal(chips_open, 0);
}

/* gpio-spi requests DC, reset, SCK, MOSI, then CS; CS is the busy line, so four are
 * held when it fails: the display must give all of them back. */
static void test_a_failed_display_releases_what_it_had(void **state)
{
    (void)state;
    reset_chip();
    tarn_show_options o;
    memset(&o, 0, sizeof o);
    o.display = TARN_DISPLAY_GPIO_SPI;
    o.display_text = "gpio-spi:gpiochip0";
    o.target = "gpiochip0";
    o.dc = "25";
    o.reset = "24";
    o.sck = "11";
    o.mosi = "10";
    o.cs = "7";
    tarn_display display;
    tarn_error err;
    assert_int_not_equal(tarn_display_open(&display, &o, &err), 0);
    assert_string_equal(err.message, "--cs: line 7 of gpiochip0: busy (held by 'spi0 CS0') (check gpioinfo gpiochip0)");
    assert_int_equal(lines_requested, 0);
    assert_int_equal(chips_open, 0);

    o.cs = "8"; /* a free line: the display opens, holds five lines, and gives them back */
    assert_int_equal(tarn_display_open(&display, &o, &err), 0);
    assert_int_equal(lines_requested, 5);
    tarn_display_close(&display);
    assert_int_equal(lines_requested, 0);
    assert_int_equal(chips_open, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_missing_and_busy_lines_say_which),
        cmocka_unit_test(test_a_line_is_driven_then_released),
        cmocka_unit_test(test_a_failed_display_releases_what_it_had),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
