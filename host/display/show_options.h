/* show_options.h: the command line of `tarn show`, parsed and range-checked.
 *
 *   tarn show SCENE --display DISPLAY --panel MODEL [--rotation 0..3]
 *             [--dc LINE] [--reset LINE] [--backlight LINE] [--sck N --mosi N --cs N]
 *             [--hz N] [--frames N] [--fps F] [--time MS] [--send bands|tiles|changed]
 *             [--dither] [--via panel|spidev|gpio-spi|mcp2210] [QUALITY]
 * DISPLAY: emulator:OUT.png | spidev:/dev/spidevB.C | gpio-spi:CHIP | mcp2210[:SERIAL]
 * MODEL:   st7789-240x240 | st7789-240x320 | ili9341-320x240
 * LINE:    CHIP:OFFSET (gpio-spi: or just OFFSET on its chip); mcp2210: a GP pin 0..8 */
#ifndef TARN_HOST_SHOW_OPTIONS_H
#define TARN_HOST_SHOW_OPTIONS_H

#include <stdint.h>
#include "error.h"
#include "tarn/tarn_panel.h"
#include "tarn/tarn_render.h"

typedef enum {
    TARN_DISPLAY_EMULATOR,
    TARN_DISPLAY_SPIDEV,
    TARN_DISPLAY_GPIO_SPI,
    TARN_DISPLAY_MCP2210
} tarn_display_kind;

/* How frames go out: full-width bands in one RAMWR, a window per tile, or only the
 * tiles that changed since the last frame (a window each). */
typedef enum {
    TARN_SEND_BANDS,
    TARN_SEND_TILES,
    TARN_SEND_CHANGED
} tarn_send_mode;

typedef struct {
    const char *scene_path;
    tarn_display_kind display;
    const char *display_text;      /* the --display value, for messages */
    const char *target;            /* the part after "kind:": PNG path, device, chip, serial (or NULL) */
    tarn_display_kind via;         /* emulator only: the backend whose code drives it */
    tarn_panel panel;
    const char *panel_name;
    const char *dc, *reset, *backlight, *sck, *mosi, *cs; /* NULL: not given */
    uint32_t hz;                   /* SPI clock for pixels */
    uint32_t frames;               /* 0: until interrupted */
    uint8_t fps;                   /* animation clock: frame k at time_ms + k * 1000 / fps */
    uint32_t time_ms;
    tarn_send_mode send;
    int dither;
    tarn_quality quality;
} tarn_show_options;

#define TARN_SHOW_HZ_DEFAULT 40000000u
#define TARN_SHOW_HZ_MAX 125000000u
#define TARN_SHOW_FRAMES_MAX 1000000u

/* argv[1] is "show". 0, or -1 with one line in `err`. */
int tarn_show_parse(int argc, char **argv, tarn_show_options *options, tarn_error *err);

/* The panel model named `name`; -1 when none is. */
int tarn_show_panel_model(const char *name);

extern const char tarn_show_usage[];

#endif
