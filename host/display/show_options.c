/* show_options.c: `tarn show`'s command line (show_options.h). Quality knobs are
 * every command's, through tarn_cli_parse_quality_option (quality_options.h). */
#include "show_options.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "option_values.h"
#include "quality_options.h"

const char tarn_show_usage[] =
    "usage: tarn show SCENE --display DISPLAY --panel MODEL [--rotation 0..3] [--frames N] [--fps F]\n"
    "                 [--time MS] [--hz N] [--send bands|tiles|changed] [--dither] [QUALITY]\n"
    "  DISPLAY emulator:OUT.png [--via panel|spidev|gpio-spi|mcp2210]\n"
    "          spidev:/dev/spidevB.C --dc CHIP:LINE [--reset CHIP:LINE] [--backlight CHIP:LINE]\n"
    "          gpio-spi:CHIP --sck N --mosi N --cs N --dc N [--reset N] [--backlight N]\n"
    "          mcp2210[:SERIAL] [--cs GP] [--dc GP] [--reset GP]   (GP pins 0..8; defaults 0, 1, 2)\n"
    "  MODEL   st7789-240x240, st7789-240x320, ili9341-320x240\n";

static const struct {
    const char *name;
    tarn_panel_model model;
} panel_names[] = {
    {"st7789-240x240", TARN_PANEL_ST7789_240X240},
    {"st7789-240x320", TARN_PANEL_ST7789_240X320},
    {"ili9341-320x240", TARN_PANEL_ILI9341_320X240},
};

int tarn_show_panel_model(const char *name)
{
    for (size_t i = 0; name && i < sizeof panel_names / sizeof panel_names[0]; i++)
        if (strcmp(name, panel_names[i].name) == 0) return (int)panel_names[i].model;
    return -1;
}

static int parse_number(const char *name, const char *text, unsigned long min, unsigned long max,
                        unsigned long *out, tarn_error *err)
{
    char *end;
    errno = 0;
    unsigned long value = text && *text >= '0' && *text <= '9' ? strtoul(text, &end, 10) : 0;
    if (text == NULL || *text < '0' || *text > '9' || errno != 0 || *end != '\0' || value < min || value > max)
        return tarn_fail(err, "%s: expected a whole number %lu..%lu, got '%s'", name, min, max, text ? text : "");
    *out = value;
    return 0;
}

/* "kind" or "kind:target". */
static int parse_display(const char *text, tarn_show_options *o, tarn_error *err)
{
    static const struct {
        const char *prefix;
        tarn_display_kind kind;
        int target_required;
    } kinds[] = {{"emulator", TARN_DISPLAY_EMULATOR, 1},
                 {"spidev", TARN_DISPLAY_SPIDEV, 1},
                 {"gpio-spi", TARN_DISPLAY_GPIO_SPI, 1},
                 {"mcp2210", TARN_DISPLAY_MCP2210, 0}};
    o->display_text = text;
    for (size_t i = 0; text && i < sizeof kinds / sizeof kinds[0]; i++) {
        size_t length = strlen(kinds[i].prefix);
        if (strncmp(text, kinds[i].prefix, length) != 0 || (text[length] != ':' && text[length] != '\0')) continue;
        o->display = kinds[i].kind;
        o->target = text[length] == ':' && text[length + 1] != '\0' ? text + length + 1 : NULL;
        if (o->target == NULL && kinds[i].target_required) break;
        return 0;
    }
    return tarn_fail(err, "--display: expected emulator:OUT.png, spidev:/dev/spidevB.C, gpio-spi:CHIP or "
                     "mcp2210[:SERIAL], got '%s'", text ? text : "");
}

static int parse_via(const char *text, tarn_show_options *o, tarn_error *err)
{
    if (text && strcmp(text, "panel") == 0) o->via = TARN_DISPLAY_EMULATOR;
    else if (text && strcmp(text, "spidev") == 0) o->via = TARN_DISPLAY_SPIDEV;
    else if (text && strcmp(text, "gpio-spi") == 0) o->via = TARN_DISPLAY_GPIO_SPI;
    else if (text && strcmp(text, "mcp2210") == 0) o->via = TARN_DISPLAY_MCP2210;
    else return tarn_fail(err, "--via: expected panel, spidev, gpio-spi or mcp2210, got '%s'", text ? text : "");
    return 0;
}

static int parse_send(const char *text, tarn_show_options *o, tarn_error *err)
{
    if (text && strcmp(text, "bands") == 0) o->send = TARN_SEND_BANDS;
    else if (text && strcmp(text, "tiles") == 0) o->send = TARN_SEND_TILES;
    else if (text && strcmp(text, "changed") == 0) o->send = TARN_SEND_CHANGED;
    else return tarn_fail(err, "--send: expected bands, tiles or changed, got '%s'", text ? text : "");
    return 0;
}

/* Options naming a line or pin: kept as text, checked by the backend that uses them. */
static const char **line_option(tarn_show_options *o, const char *name)
{
    if (strcmp(name, "--dc") == 0) return &o->dc;
    if (strcmp(name, "--reset") == 0) return &o->reset;
    if (strcmp(name, "--backlight") == 0) return &o->backlight;
    if (strcmp(name, "--sck") == 0) return &o->sck;
    if (strcmp(name, "--mosi") == 0) return &o->mosi;
    if (strcmp(name, "--cs") == 0) return &o->cs;
    return NULL;
}

/* Options with a value; 1 if `name` is none of them. */
static int parse_valued(const char *name, const char *value, tarn_show_options *o, unsigned long *rotation,
                        tarn_error *err)
{
    unsigned long n;
    const char **line = line_option(o, name);
    if (line != NULL) {
        if (value == NULL || *value == '\0') return tarn_fail(err, "%s: expected a line", name);
        *line = value;
        return 0;
    }
    if (strcmp(name, "--display") == 0) return parse_display(value, o, err);
    if (strcmp(name, "--via") == 0) return parse_via(value, o, err);
    if (strcmp(name, "--send") == 0) return parse_send(value, o, err);
    if (strcmp(name, "--panel") == 0) {
        int model = tarn_show_panel_model(value);
        if (model < 0)
            return tarn_fail(err, "--panel: unknown panel '%s' (expected st7789-240x240, st7789-240x320 or "
                             "ili9341-320x240)", value ? value : "");
        o->panel_name = value;
        o->panel.model = (uint8_t)model;
        o->panel.width = 1; /* known; the preset is taken once the rotation is known */
        return 0;
    }
    if (strcmp(name, "--rotation") == 0) return parse_number(name, value, 0, 3, rotation, err);
    if (strcmp(name, "--hz") == 0) {
        if (parse_number(name, value, 100000, TARN_SHOW_HZ_MAX, &n, err) != 0) return -1;
        o->hz = (uint32_t)n;
    } else if (strcmp(name, "--frames") == 0) {
        if (parse_number(name, value, 1, TARN_SHOW_FRAMES_MAX, &n, err) != 0) return -1;
        o->frames = (uint32_t)n;
    } else if (strcmp(name, "--fps") == 0) {
        if (parse_number(name, value, 1, TARN_CLI_FPS_MAX, &n, err) != 0) return -1;
        o->fps = (uint8_t)n;
    } else if (strcmp(name, "--time") == 0) {
        if (parse_number(name, value, 0, UINT32_MAX, &n, err) != 0) return -1;
        o->time_ms = (uint32_t)n;
    } else {
        return tarn_cli_parse_quality_option(name, value, &o->quality, err);
    }
    return 0;
}

static int check_combination(tarn_show_options *o, int via_given, int send_given, tarn_error *err)
{
    if (o->scene_path == NULL) return tarn_fail(err, "show: expected a scene file");
    if (o->display_text == NULL) return tarn_fail(err, "show: expected --display (see tarn show --help)");
    if (o->panel_name == NULL) return tarn_fail(err, "show: expected --panel st7789-240x240, st7789-240x320 or ili9341-320x240");
    if (via_given && o->display != TARN_DISPLAY_EMULATOR)
        return tarn_fail(err, "--via applies to --display emulator:OUT.png");
    tarn_display_kind link = o->display == TARN_DISPLAY_EMULATOR ? o->via : o->display;
    if (link == TARN_DISPLAY_SPIDEV && o->display == TARN_DISPLAY_SPIDEV && o->dc == NULL)
        return tarn_fail(err, "spidev: expected --dc CHIP:LINE (the panel's data/command pin)");
    if (link == TARN_DISPLAY_GPIO_SPI && o->display == TARN_DISPLAY_GPIO_SPI &&
        (o->sck == NULL || o->mosi == NULL || o->cs == NULL || o->dc == NULL))
        return tarn_fail(err, "gpio-spi: expected --sck N --mosi N --cs N --dc N");
    if (!send_given) o->send = link == TARN_DISPLAY_MCP2210 ? TARN_SEND_CHANGED : TARN_SEND_BANDS;
    if (o->frames == 0 && o->display == TARN_DISPLAY_EMULATOR) o->frames = 1;
    if (o->fps == 0) o->fps = TARN_CLI_FPS_DEFAULT;
    return 0;
}

int tarn_show_parse(int argc, char **argv, tarn_show_options *o, tarn_error *err)
{
    memset(o, 0, sizeof *o);
    o->quality = tarn_quality_default();
    if (tarn_cli_apply_preset(argc - 2, argv + 2, &o->quality, err) != 0) return -1;
    o->hz = TARN_SHOW_HZ_DEFAULT;
    unsigned long rotation = 0;
    int via_given = 0, send_given = 0;
    for (int i = 2; i < argc; i++) {
        const char *arg = argv[i];
        if (arg[0] != '-') {
            if (o->scene_path != NULL) return tarn_fail(err, "unexpected argument '%s'", arg);
            o->scene_path = arg;
            continue;
        }
        if (strcmp(arg, "--dither") == 0) {
            o->dither = 1;
            continue;
        }
        via_given |= strcmp(arg, "--via") == 0;
        send_given |= strcmp(arg, "--send") == 0;
        int result = parse_valued(arg, i + 1 < argc ? argv[i + 1] : NULL, o, &rotation, err);
        if (result < 0) return -1;
        if (result > 0) return tarn_fail(err, "unknown option '%s'", arg);
        i++;
    }
    if (check_combination(o, via_given, send_given, err) != 0) return -1;
    if (tarn_cli_check_quality(&o->quality, err) != 0) return -1;
    o->panel = tarn_panel_preset((tarn_panel_model)o->panel.model, (unsigned)rotation);
    return 0;
}
