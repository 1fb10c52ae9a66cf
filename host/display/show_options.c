/* show_options.c: `tarn show`'s command line (show_options.h). Quality knobs are
 * every command's, through tarn_cli_parse_quality_option (quality_options.h). */
#include "show_options.h"

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

static const tarn_option_choice panel_models[] = {
    {"st7789-240x240", TARN_PANEL_ST7789_240X240, NULL},
    {"st7789-240x320", TARN_PANEL_ST7789_240X320, NULL},
    {"ili9341-320x240", TARN_PANEL_ILI9341_320X240, NULL},
};

/* --via: the backend whose own code drives the emulated panel. */
static const tarn_option_choice links[] = {
    {"panel", TARN_DISPLAY_EMULATOR, NULL}, {"spidev", TARN_DISPLAY_SPIDEV, NULL},
    {"gpio-spi", TARN_DISPLAY_GPIO_SPI, NULL}, {"mcp2210", TARN_DISPLAY_MCP2210, NULL}};

static const tarn_option_choice send_modes[] = {
    {"bands", TARN_SEND_BANDS, NULL}, {"tiles", TARN_SEND_TILES, NULL}, {"changed", TARN_SEND_CHANGED, NULL}};

int tarn_show_panel_model(const char *name)
{
    int model;
    return tarn_find_choice(name, TARN_CHOICES(panel_models), &model) == 0 ? model : -1;
}

/* Room for "st7789-240x240, st7789-240x320 or ili9341-320x240". */
#define PANEL_LIST_MAX 64

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

/* Options with a value: TARN_OPTION_VALUE, TARN_OPTION_UNKNOWN for none of them,
 * or -1. */
static int parse_valued(const char *name, const char *value, tarn_show_options *o, unsigned long *rotation,
                        tarn_error *err)
{
    unsigned long n;
    int word;
    const char **line = line_option(o, name);
    if (line != NULL) {
        if (value == NULL || *value == '\0') return tarn_fail(err, "%s: expected a line", name);
        *line = value;
        return 0;
    }
    if (strcmp(name, "--display") == 0) return parse_display(value, o, err);
    if (strcmp(name, "--via") == 0) {
        if (tarn_parse_choice(name, value, TARN_CHOICES(links), &word, err) != 0) return -1;
        o->via = (tarn_display_kind)word;
        return 0;
    }
    if (strcmp(name, "--send") == 0) {
        if (tarn_parse_choice(name, value, TARN_CHOICES(send_modes), &word, err) != 0) return -1;
        o->send = (tarn_send_mode)word;
        return 0;
    }
    if (strcmp(name, "--panel") == 0) {
        int model = tarn_show_panel_model(value);
        if (model < 0) {
            char models[PANEL_LIST_MAX];
            tarn_list_choices(TARN_CHOICES(panel_models), models, sizeof models);
            return tarn_fail(err, "--panel: unknown panel '%s' (expected %s)", value ? value : "", models);
        }
        o->panel_name = value;
        o->panel.model = (uint8_t)model;
        o->panel.width = 1; /* known; the preset is taken once the rotation is known */
        return 0;
    }
    if (strcmp(name, "--rotation") == 0) return tarn_parse_number(name, value, 0, 3, rotation, err);
    if (strcmp(name, "--hz") == 0) {
        if (tarn_parse_number(name, value, 100000, TARN_SHOW_HZ_MAX, &n, err) != 0) return -1;
        o->hz = (uint32_t)n;
    } else if (strcmp(name, "--frames") == 0) {
        if (tarn_parse_number(name, value, 1, TARN_SHOW_FRAMES_MAX, &n, err) != 0) return -1;
        o->frames = (uint32_t)n;
    } else if (strcmp(name, "--fps") == 0) {
        if (tarn_parse_number(name, value, 1, TARN_CLI_FPS_MAX, &n, err) != 0) return -1;
        o->fps = (uint8_t)n;
    } else if (strcmp(name, "--time") == 0) {
        if (tarn_parse_number(name, value, 0, UINT32_MAX, &n, err) != 0) return -1;
        o->time_ms = (uint32_t)n;
    } else {
        return tarn_cli_parse_quality_option(name, value, &o->quality, err);
    }
    return 0;
}

/* The options as they are read: what goes into tarn_show_options once all are. */
typedef struct {
    tarn_show_options *o;
    unsigned long rotation;
    int via_given, send_given;
} show_parse;

/* A tarn_option_reader. */
static int read_option(void *parse, const char *name, const char *value, tarn_error *err)
{
    show_parse *p = parse;
    if (strcmp(name, "--dither") == 0) {
        p->o->dither = 1;
        return TARN_OPTION_FLAG;
    }
    p->via_given |= strcmp(name, "--via") == 0;
    p->send_given |= strcmp(name, "--send") == 0;
    return parse_valued(name, value, p->o, &p->rotation, err);
}

static int check_combination(const show_parse *p, tarn_error *err)
{
    tarn_show_options *o = p->o;
    if (o->scene_path == NULL) return tarn_fail(err, "show: expected a scene file");
    if (o->display_text == NULL) return tarn_fail(err, "show: expected --display");
    if (o->panel_name == NULL) {
        char models[PANEL_LIST_MAX];
        tarn_list_choices(TARN_CHOICES(panel_models), models, sizeof models);
        return tarn_fail(err, "show: expected --panel %s", models);
    }
    if (p->via_given && o->display != TARN_DISPLAY_EMULATOR)
        return tarn_fail(err, "--via applies to --display emulator:OUT.png");
    tarn_display_kind link = o->display == TARN_DISPLAY_EMULATOR ? o->via : o->display;
    if (link == TARN_DISPLAY_SPIDEV && o->display == TARN_DISPLAY_SPIDEV && o->dc == NULL)
        return tarn_fail(err, "spidev: expected --dc CHIP:LINE (the panel's data/command pin)");
    if (link == TARN_DISPLAY_GPIO_SPI && o->display == TARN_DISPLAY_GPIO_SPI &&
        (o->sck == NULL || o->mosi == NULL || o->cs == NULL || o->dc == NULL))
        return tarn_fail(err, "gpio-spi: expected --sck N --mosi N --cs N --dc N");
    if (!p->send_given) o->send = link == TARN_DISPLAY_MCP2210 ? TARN_SEND_CHANGED : TARN_SEND_BANDS;
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
    show_parse p = {o, 0, 0, 0};
    if (tarn_parse_arguments(argc, argv, &o->scene_path, read_option, &p, err) != 0) return -1;
    if (check_combination(&p, err) != 0) return -1;
    if (tarn_cli_check_quality(&o->quality, err) != 0) return -1;
    o->panel = tarn_panel_preset((tarn_panel_model)o->panel.model, (unsigned)p.rotation);
    return 0;
}
