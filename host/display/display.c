/* display.c: opening and closing the link `tarn show` drives (display.h). */
#include "display.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- Lines ---- */

/* A LINE option: CHIP:OFFSET, or (bit-bang) an offset on the display's chip. */
static int request_line(tarn_display *d, int which, const char *option, const char *text, const char *chip_default,
                        int initial, tarn_error *err)
{
    char chip[96];
    unsigned offset;
    if (chip_default != NULL && strchr(text, ':') == NULL) {
        char spec[128];
        snprintf(spec, sizeof spec, "%s:%s", chip_default, text);
        if (tarn_gpio_parse_spec(option, spec, chip, sizeof chip, &offset, err) != 0) return -1;
    } else if (tarn_gpio_parse_spec(option, text, chip, sizeof chip, &offset, err) != 0) {
        return -1;
    }
    return tarn_gpio_line_request(option, chip, offset, initial, &d->lines[which], err);
}

static int request_lines(tarn_display *d, const tarn_show_options *o, const char *chip_default, tarn_error *err)
{
    static const char *const names[LINE_COUNT] = {"--dc", "--reset", "--backlight", "--sck", "--mosi", "--cs"};
    const char *texts[LINE_COUNT] = {o->dc, o->reset, o->backlight, o->sck, o->mosi, o->cs};
    static const int initial[LINE_COUNT] = {1, 1, 1, 0, 0, 1}; /* data, out of reset, lit, SCK idle, CS idle */
    for (int i = 0; i < LINE_COUNT; i++) {
        if (texts[i] == NULL) continue;
        if (d->link != TARN_DISPLAY_GPIO_SPI && (i == LINE_SCK || i == LINE_MOSI || i == LINE_CS))
            return tarn_fail(err, "%s applies to --display gpio-spi:CHIP", names[i]);
        if (request_line(d, i, names[i], texts[i], chip_default, initial[i], err) != 0) return -1;
    }
    return 0;
}

/* ---- MCP2210 pins ---- */

static int gp_pin(const char *option, const char *text, uint8_t fallback, uint8_t *pin, tarn_error *err)
{
    if (text == NULL) {
        *pin = fallback;
        return 0;
    }
    const char *digits = strncmp(text, "gp", 2) == 0 || strncmp(text, "GP", 2) == 0 ? text + 2 : text;
    if (digits[0] >= '0' && digits[0] <= '8' && digits[1] == '\0') {
        *pin = (uint8_t)(digits[0] - '0');
        return 0;
    }
    return tarn_fail(err, "%s: expected an MCP2210 GP pin 0..8, got '%s'", option, text);
}

static int mcp2210_wiring_of(const tarn_show_options *o, tarn_mcp2210_wiring *w, tarn_error *err)
{
    if (o->sck || o->mosi) return tarn_fail(err, "--sck and --mosi apply to --display gpio-spi:CHIP");
    if (o->backlight) return tarn_fail(err, "--backlight: the MCP2210 link has no backlight pin; wire it to 3V3");
    w->bit_rate = o->hz < TARN_MCP2210_BIT_RATE_MAX ? o->hz : TARN_MCP2210_BIT_RATE_MAX;
    return gp_pin("--cs", o->cs, 0, &w->cs, err) || gp_pin("--dc", o->dc, 1, &w->dc, err) ||
                   gp_pin("--reset", o->reset, 2, &w->reset, err)
               ? -1
               : 0;
}

/* ---- Each link, real or on the emulated module ---- */

/* The display sends through `link`: its transport, its counts, its failures. */
static void send_through(tarn_display *d, tarn_panel_link *link, tarn_panel_transport transport)
{
    d->transport = transport;
    d->counts = &link->counts;
    d->link_error = &link->error;
}

/* A backend driving the emulated module pauses on the module's clock. */
static void pause_with_module(tarn_display *d, tarn_panel_link *link)
{
    link->delay = tarn_panel_wiring_delay;
    link->delay_user = &d->wiring;
}

/* spidev, attached, with its DC and reset lines in d->lines. */
static void send_through_spidev(tarn_display *d)
{
    d->spidev.dc = &d->lines[LINE_DC];
    d->spidev.reset = &d->lines[LINE_RESET];
    send_through(d, &d->spidev.link, tarn_spidev_transport(&d->spidev));
}

/* The bit-bang on the lines in d->lines. */
static void send_through_gpio_spi(tarn_display *d)
{
    tarn_gpio_spi_init(&d->gpio_spi, &d->lines[LINE_SCK], &d->lines[LINE_MOSI], &d->lines[LINE_CS],
                       &d->lines[LINE_DC], &d->lines[LINE_RESET]);
    send_through(d, &d->gpio_spi.link, tarn_gpio_spi_transport(&d->gpio_spi));
}

/* The MCP2210 protocol over `seam`, set up for `wiring`. */
static int send_through_mcp2210(tarn_display *d, tarn_mcp2210_seam seam, const tarn_mcp2210_wiring *wiring,
                                tarn_error *err)
{
    if (tarn_mcp2210_setup(&d->mcp2210, seam, wiring, d->name, err) != 0) return -1;
    send_through(d, &d->mcp2210.link, tarn_mcp2210_transport(&d->mcp2210));
    d->spi_hz = wiring->bit_rate;
    return 0;
}

static int open_spidev(tarn_display *d, const tarn_show_options *o, tarn_error *err)
{
    if (tarn_spidev_open(&d->spidev, o->target, o->hz, err) != 0) return -1;
    if (request_lines(d, o, NULL, err) != 0) return -1;
    send_through_spidev(d);
    d->spi_hz = o->hz;
    return 0;
}

static int open_gpio_spi(tarn_display *d, const tarn_show_options *o, tarn_error *err)
{
    if (request_lines(d, o, o->target, err) != 0) return -1;
    send_through_gpio_spi(d);
    return 0;
}

static int open_mcp2210(tarn_display *d, const tarn_show_options *o, tarn_error *err)
{
    tarn_mcp2210_wiring wiring;
    tarn_mcp2210_seam seam;
    snprintf(d->name, sizeof d->name, "%s", o->display_text);
    if (mcp2210_wiring_of(o, &wiring, err) != 0 || tarn_mcp2210_usb_open(o->target, &d->usb, &seam, err) != 0)
        return -1;
    return send_through_mcp2210(d, seam, &wiring, err);
}

/* The emulated module behind the spidev backend: its ioctl, its lines. */
static int emulate_spidev(tarn_display *d, const tarn_show_options *o, tarn_error *err)
{
    if (tarn_spidev_attach(&d->spidev, "emulated", 0, tarn_panel_wiring_spidev_ioctl, &d->wiring, o->hz, err) != 0)
        return -1;
    d->spidev.chunk_bytes = d->wiring.spidev_bufsiz;
    d->lines[LINE_DC] = tarn_panel_wiring_line(&d->wiring, TARN_WIRE_DC);
    d->lines[LINE_RESET] = tarn_panel_wiring_line(&d->wiring, TARN_WIRE_RESET);
    send_through_spidev(d);
    pause_with_module(d, &d->spidev.link);
    return 0;
}

/* The emulated module's pins behind the bit-bang; it has no backlight line. */
static void emulate_gpio_spi(tarn_display *d)
{
    static const tarn_wire wires[LINE_COUNT] = {TARN_WIRE_DC, TARN_WIRE_RESET, TARN_WIRE_DC, /* unused */
                                                TARN_WIRE_SCK, TARN_WIRE_MOSI, TARN_WIRE_CS};
    for (int i = 0; i < LINE_COUNT; i++) d->lines[i] = tarn_panel_wiring_line(&d->wiring, wires[i]);
    memset(&d->lines[LINE_BACKLIGHT], 0, sizeof d->lines[LINE_BACKLIGHT]); /* the module's is always lit */
    send_through_gpio_spi(d);
    pause_with_module(d, &d->gpio_spi.link);
    d->spi_hz = 0;
}

/* The MCP2210 emulator with the module on its SPI bus and GP pins. */
static int emulate_mcp2210(tarn_display *d, const tarn_show_options *o, tarn_error *err)
{
    tarn_mcp2210_wiring wiring;
    if (mcp2210_wiring_of(o, &wiring, err) != 0) return -1;
    tarn_mcp2210_emulator *e = &d->mcp2210_emulator;
    tarn_mcp2210_emulator_init(e, &d->wiring);
    e->gp_wire[wiring.cs] = TARN_WIRE_CS;
    e->gp_wire[wiring.dc] = TARN_WIRE_DC;
    e->gp_wire[wiring.reset] = TARN_WIRE_RESET;
    snprintf(d->name, sizeof d->name, "mcp2210 (emulated)");
    if (send_through_mcp2210(d, tarn_mcp2210_emulator_seam(e), &wiring, err) != 0) return -1;
    pause_with_module(d, &d->mcp2210.link);
    return 0;
}

/* The emulator, directly or through a backend's own code (--via). */
static int open_emulated(tarn_display *d, const tarn_show_options *o, tarn_error *err)
{
    d->emulator = malloc(sizeof *d->emulator);
    if (d->emulator == NULL) return tarn_fail(err, "out of memory for the panel emulator");
    tarn_panel_emulator_init(d->emulator, (tarn_panel_model)o->panel.model, o->panel.rotation);
    tarn_panel_wiring_init(&d->wiring, tarn_panel_emulator_transport(d->emulator));
    d->spi_hz = o->hz;
    switch (d->link) {
    case TARN_DISPLAY_EMULATOR:
        tarn_counted_link_init(&d->direct, d->wiring.panel, o->hz);
        send_through(d, &d->direct.link, tarn_panel_link_transport(&d->direct.link));
        return 0;
    case TARN_DISPLAY_SPIDEV: return emulate_spidev(d, o, err);
    case TARN_DISPLAY_GPIO_SPI: emulate_gpio_spi(d); return 0;
    case TARN_DISPLAY_MCP2210: return emulate_mcp2210(d, o, err);
    }
    return tarn_fail(err, "unknown link");
}

int tarn_display_open(tarn_display *d, const tarn_show_options *o, tarn_error *err)
{
    memset(d, 0, sizeof *d);
    d->spidev.fd = -1;
    d->emulated = o->display == TARN_DISPLAY_EMULATOR;
    d->link = d->emulated ? o->via : o->display;
    int failed;
    switch (o->display) {
    case TARN_DISPLAY_SPIDEV: failed = open_spidev(d, o, err); break;
    case TARN_DISPLAY_GPIO_SPI: failed = open_gpio_spi(d, o, err); break;
    case TARN_DISPLAY_MCP2210: failed = open_mcp2210(d, o, err); break;
    default: failed = open_emulated(d, o, err); break;
    }
    if (failed) tarn_display_close(d);
    return failed ? -1 : 0;
}

const char *tarn_display_failure(const tarn_display *d)
{
    if (d->link_error != NULL && d->link_error->message[0] != '\0') return d->link_error->message;
    return "the panel link failed";
}

void tarn_display_close(tarn_display *d)
{
    if (!d->emulated)
        for (int i = 0; i < LINE_COUNT; i++) tarn_gpio_line_release(&d->lines[i]);
    tarn_spidev_close(&d->spidev);
    tarn_mcp2210_usb_close(d->usb);
    d->usb = NULL;
    free(d->emulator);
    d->emulator = NULL;
}
