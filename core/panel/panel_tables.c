/* panel_tables.c: each panel model's geometry, MADCTL per rotation and init sequence.
 *
 * Where these facts come from (docs/panels.md has the full argument):
 *  - Offsets and MADCTL of the ST7789 modules: TFT_eSPI, TFT_Drivers/ST7789_Rotation.h
 *    (rotations 0..3 = MADCTL 0x00, MX|MV, MX|MY, MV|MY; the 240x240 glass at row
 *    offset 80 in rotation 2 and column offset 80 in rotation 3, 0 otherwise), which
 *    Adafruit-ST7735-Library, Adafruit_ST7789.cpp confirms with its rotations numbered
 *    two further on (its rotation 0 is MX|MY with _rowstart = 320 - 240 = 80). Both
 *    say the controller's RAM is 240 columns by 320 rows and the 240x240 glass shows
 *    rows 0..239 of it: mirroring rows (MY) moves the glass to rows 80..319 of the
 *    address space.
 *  - ILI9341: Adafruit_ILI9341.cpp. Its setRotation(1) (MV|BGR) is our landscape
 *    rotation 0; our rotation r is its (r + 1) mod 4. Its init table gives the power,
 *    VCOM, frame rate and gamma values below (less the undocumented command 0xEF).
 *  - ST7789 init: the datasheet's SLPOUT wait (5 ms before the next command, 120 ms
 *    before a sleep-in; we wait 120 ms so the supply settles) and Adafruit's
 *    generic_st7789 table (INVON: the ST7789 modules are IPS glass, which shows
 *    inverted colours without it). */
#include "panel/panel_tables_internal.h"

#include "tarn/tarn_panel.h"

enum {
    MADCTL_MY = 0x80,  /* mirror RAM rows */
    MADCTL_MX = 0x40,  /* mirror RAM columns */
    MADCTL_MV = 0x20,  /* exchange columns and rows */
    MADCTL_BGR = 0x08, /* the glass's subpixels are blue-green-red */
    MADCTL_RGB = 0x00
};

/* ILI9341 settings that have no effect on what the drivers send afterwards. */
enum {
    ILI9341_POWER_CONTROL_B = 0xCF,
    ILI9341_POWER_ON_SEQUENCE = 0xED,
    ILI9341_DRIVER_TIMING_A = 0xE8,
    ILI9341_POWER_CONTROL_A = 0xCB,
    ILI9341_PUMP_RATIO = 0xF7,
    ILI9341_DRIVER_TIMING_B = 0xEA,
    ILI9341_POWER_CONTROL_1 = 0xC0,
    ILI9341_POWER_CONTROL_2 = 0xC1,
    ILI9341_VCOM_CONTROL_1 = 0xC5,
    ILI9341_VCOM_CONTROL_2 = 0xC7,
    ILI9341_VERTICAL_SCROLL_START = 0x37,
    ILI9341_FRAME_RATE = 0xB1,
    ILI9341_DISPLAY_FUNCTION = 0xB6,
    ILI9341_GAMMA_3_ENABLE = 0xF2,
    ILI9341_GAMMA_SET = 0x26,
    ILI9341_POSITIVE_GAMMA = 0xE0,
    ILI9341_NEGATIVE_GAMMA = 0xE1
};

/* The MADCTL steps carry a placeholder byte: panel.c sends the rotation's own. */
static const uint8_t st7789_init[] = {
    TARN_PANEL_SWRESET, 0, 150,
    TARN_PANEL_SLPOUT, 0, 120,
    TARN_PANEL_COLMOD, 1, 10, 0x55,
    TARN_PANEL_MADCTL, 1, 0, 0,
    TARN_PANEL_INVON, 0, 10,
    TARN_PANEL_NORON, 0, 10,
    TARN_PANEL_DISPON, 0, 10,
};

static const uint8_t ili9341_init[] = {
    TARN_PANEL_SWRESET, 0, 150,
    ILI9341_POWER_CONTROL_B, 3, 0, 0x00, 0xC1, 0x30,
    ILI9341_POWER_ON_SEQUENCE, 4, 0, 0x64, 0x03, 0x12, 0x81,
    ILI9341_DRIVER_TIMING_A, 3, 0, 0x85, 0x00, 0x78,
    ILI9341_POWER_CONTROL_A, 5, 0, 0x39, 0x2C, 0x00, 0x34, 0x02,
    ILI9341_PUMP_RATIO, 1, 0, 0x20,
    ILI9341_DRIVER_TIMING_B, 2, 0, 0x00, 0x00,
    ILI9341_POWER_CONTROL_1, 1, 0, 0x23,
    ILI9341_POWER_CONTROL_2, 1, 0, 0x10,
    ILI9341_VCOM_CONTROL_1, 2, 0, 0x3E, 0x28,
    ILI9341_VCOM_CONTROL_2, 1, 0, 0x86,
    TARN_PANEL_MADCTL, 1, 0, 0,
    ILI9341_VERTICAL_SCROLL_START, 1, 0, 0x00,
    TARN_PANEL_COLMOD, 1, 0, 0x55,
    ILI9341_FRAME_RATE, 2, 0, 0x00, 0x18,
    ILI9341_DISPLAY_FUNCTION, 3, 0, 0x08, 0x82, 0x27,
    ILI9341_GAMMA_3_ENABLE, 1, 0, 0x00,
    ILI9341_GAMMA_SET, 1, 0, 0x01,
    ILI9341_POSITIVE_GAMMA, 15, 0,
        0x0F, 0x31, 0x2B, 0x0C, 0x0E, 0x08, 0x4E, 0xF1, 0x37, 0x07, 0x10, 0x03, 0x0E, 0x09, 0x00,
    ILI9341_NEGATIVE_GAMMA, 15, 0,
        0x00, 0x0E, 0x14, 0x03, 0x11, 0x07, 0x31, 0xC1, 0x48, 0x08, 0x0F, 0x0C, 0x31, 0x36, 0x0F,
    TARN_PANEL_SLPOUT, 0, 120,
    TARN_PANEL_DISPON, 0, 120,
};

#define PACKED(table) (table), sizeof(table)

/* ST7789 rotations as TFT_eSPI numbers them; both ST7789 modules share the MADCTLs. */
#define ST7789_MADCTL {MADCTL_RGB, MADCTL_MX | MADCTL_MV | MADCTL_RGB, \
                       MADCTL_MX | MADCTL_MY | MADCTL_RGB, MADCTL_MV | MADCTL_MY | MADCTL_RGB}

static const tarn_panel_model_facts models[] = {
    [TARN_PANEL_ST7789_240X240] = {240, 240, ST7789_MADCTL, {0, 0, 0, 80}, {0, 0, 80, 0},
                                   PACKED(st7789_init)},
    [TARN_PANEL_ST7789_240X320] = {240, 320, ST7789_MADCTL, {0, 0, 0, 0}, {0, 0, 0, 0},
                                   PACKED(st7789_init)},
    [TARN_PANEL_ILI9341_320X240] = {320, 240,
                                    {MADCTL_MV | MADCTL_BGR, MADCTL_MY | MADCTL_BGR,
                                     MADCTL_MX | MADCTL_MY | MADCTL_MV | MADCTL_BGR,
                                     MADCTL_MX | MADCTL_BGR},
                                    {0, 0, 0, 0}, {0, 0, 0, 0}, PACKED(ili9341_init)},
};

const tarn_panel_model_facts *tarn__panel_model_facts_of(unsigned model)
{
    return model < sizeof models / sizeof models[0] ? &models[model] : NULL;
}
