/* panel_wiring.h: a panel module on the end of its wires, for emulated links.
 *
 * The module's pins (DC, RESX, CS, SCK, MOSI) as GPIO lines, its SPI input as bytes
 * or as a spidev ioctl, and behind them a panel transport (the panel emulator's):
 * a command byte is one clocked in while DC is low, a data byte one while DC is
 * high; RESX low holds the controller in reset. Backends that drive real wires
 * (spidev, the GPIO bit-bang, the MCP2210's pins) drive these instead and so run
 * their own code against the emulator. */
#ifndef TARN_HOST_PANEL_WIRING_H
#define TARN_HOST_PANEL_WIRING_H

#include <stddef.h>
#include <stdint.h>
#include "gpio_lines.h"
#include "tarn/tarn_panel.h"

typedef enum {
    TARN_WIRE_DC,
    TARN_WIRE_RESET, /* RESX: low = reset asserted */
    TARN_WIRE_CS,    /* low = selected */
    TARN_WIRE_SCK,   /* SPI mode 0: MOSI sampled on the rising edge, MSB first */
    TARN_WIRE_MOSI,
    TARN_WIRE_COUNT
} tarn_wire;

typedef struct tarn_panel_wiring tarn_panel_wiring;

typedef struct {
    tarn_panel_wiring *wiring;
    tarn_wire wire;
} tarn_wiring_pin;

struct tarn_panel_wiring {
    tarn_panel_transport panel;     /* where the decoded calls go */
    int level[TARN_WIRE_COUNT];
    uint8_t shift;                  /* bits clocked in so far */
    unsigned bits;
    tarn_wiring_pin pins[TARN_WIRE_COUNT];
    size_t spidev_bufsiz;           /* the emulated driver's transfer limit */
    /* what the link did */
    uint64_t line_sets, bytes, command_bytes, ioctls;
    size_t largest_transfer;
    uint32_t slowest_pixel_hz, fastest_command_hz; /* of transfers longer than 16 bytes; of command bytes */
    uint32_t fastest_parameter_hz;  /* of data transfers of 16 bytes or fewer (CASET, MADCTL...) */
    int spi_mode;                   /* what SPI_IOC_WR_MODE asked for; -1 before */
    uint64_t vanish_after_messages; /* fault: SPI_IOC_MESSAGE fails with ENODEV once this
                                       many have gone through (0: never), as when the
                                       device is unbound mid-frame */
    int failed;                     /* a panel call failed */
};

/* All wires high (deselected, out of reset, DC data), SCK low. */
void tarn_panel_wiring_init(tarn_panel_wiring *wiring, tarn_panel_transport panel);

/* A GPIO line driving one of the module's pins. */
tarn_gpio_line tarn_panel_wiring_line(tarn_panel_wiring *wiring, tarn_wire wire);

/* Drives a pin (what the line's set does). 0, or -1 when the panel call failed. */
int tarn_panel_wiring_set(tarn_panel_wiring *wiring, tarn_wire wire, int level);

/* Bytes clocked in while CS is low, each a command or data by DC's level now. */
int tarn_panel_wiring_spi(tarn_panel_wiring *wiring, const uint8_t *bytes, size_t count);

/* A spidev driver whose CS is the module's: tarn_spidev_ioctl_fn with the wiring as
 * `user`. Accepts the mode, word size and speed requests and SPI_IOC_MESSAGE(1) up
 * to spidev_bufsiz bytes (longer ones fail with EMSGSIZE, as the driver does);
 * anything else fails with ENOTTY. */
int tarn_panel_wiring_spidev_ioctl(void *user, int fd, unsigned long request, void *arg);

/* A delay for the backends: passes to the panel's delay_ms. */
int tarn_panel_wiring_delay(void *user, uint16_t milliseconds);

#endif
