/* test_show_bad_input.c: `tarn show` on devices that are not there or not panels.
 *
 * Through the real binary ($TARN_BIN): a device path that does not exist or is no
 * SPI device, a GPIO chip that does not exist, no MCP2210 attached, an unknown
 * panel, an unknown display, a PNG that cannot be written. Each must exit with
 * status 2 and say what is wrong in one line starting "tarn: " that names the
 * device or the option, and nothing more, and write no file. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#define STDERR_PATH "build/test_show_bad_input.stderr"

typedef struct {
    const char *arguments;  /* after "tarn show scenes/pond.json" */
    const char *first_line; /* expected to start the only line of stderr, after "tarn: " */
} show_case;

static const show_case cases[] = {
    {"--panel st7789-240x240 --display spidev:/dev/spidev9.9 --dc gpiochip0:25",
     "spidev:/dev/spidev9.9: cannot open: No such file or directory (check that SPI is enabled"},
    {"--panel st7789-240x240 --display spidev:/dev/null --dc gpiochip0:25",
     "spidev:/dev/null: not an SPI device"},
    {"--panel st7789-240x240 --display gpio-spi:gpiochip99 --sck 11 --mosi 10 --cs 8 --dc 25",
     "--dc: cannot open GPIO chip 'gpiochip99'"},
    {"--panel st7789-240x240 --display mcp2210", "mcp2210: no MCP2210 attached (check lsusb for 04d8:00de"},
    {"--panel st7789-240x240 --display mcp2210:NOSUCHSERIAL --dc 9", "--dc: expected an MCP2210 GP pin 0..8, got '9'"},
    {"--panel st7735-128x160 --display emulator:build/show-bad.png", "--panel: unknown panel 'st7735-128x160'"},
    {"--panel st7789-240x240 --display hdmi:0", "--display: expected emulator:OUT.png, spidev:/dev/spidevB.C"},
    {"--panel st7789-240x240 --display spidev:/dev/spidev0.0", "spidev: expected --dc CHIP:LINE"},
    {"--panel st7789-240x240 --display emulator:build/no-such-dir/show.png", "build/no-such-dir/show.png"},
    {"--panel ili9341-320x240 --display emulator:build/show-bad.png",
     "scenes/pond.json: materials.water.water.refraction reaches"},
    {"--panel st7789-240x240 --display emulator:build/show-bad.png --via usb", "--via: expected panel, spidev"},
    {"--panel st7789-240x240 --display emulator:build/show-bad.png --tile 7", "--tile: expected a whole number 8..64"},
};

static void test_show_rejects_each_case(void **state)
{
    (void)state;
    const char *tarn = getenv("TARN_BIN");
    if (tarn == NULL) tarn = "build/release/tarn";
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const show_case *c = &cases[i];
        remove("build/show-bad.png");
        char command[1024];
        snprintf(command, sizeof command, "%s show scenes/pond.json %s >/dev/null 2>%s", tarn, c->arguments,
                 STDERR_PATH);
        int status = system(command);
        assert_true(WIFEXITED(status));
        if (WEXITSTATUS(status) != 2) fail_msg("case %zu (%s): exit status %d", i, c->arguments, WEXITSTATUS(status));
        FILE *f = fopen(STDERR_PATH, "r");
        assert_non_null(f);
        char text[4096];
        size_t length = fread(text, 1, sizeof text - 1, f);
        fclose(f);
        text[length] = '\0';
        char *newline = strchr(text, '\n');
        assert_non_null(newline);
        if (newline[1] != '\0') fail_msg("case %zu: more than one line: %s", i, text);
        *newline = '\0';
        if (strncmp(text, "tarn: ", 6) != 0 || strncmp(text + 6, c->first_line, strlen(c->first_line)) != 0)
            fail_msg("case %zu: got '%s', expected 'tarn: %s...'", i, text, c->first_line);
        struct stat st;
        assert_int_not_equal(stat("build/show-bad.png", &st), 0);
    }
    remove(STDERR_PATH);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_show_rejects_each_case),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
