/* display_spidev.h: a panel on Linux spidev, DC and reset on GPIO lines.
 *
 * Pixels go out through SPI_IOC_MESSAGE ioctls split to the driver's transfer
 * limit (the spidev module's bufsiz parameter, 4096 bytes by default: the driver
 * rejects a message longer than that), commands and their parameters at a slower
 * clock than pixels (the per-transfer speed_hz of struct spi_ioc_transfer). The
 * ioctl sits behind a seam so the tests and `--display emulator` run this exact
 * code against the panel emulator. */
#ifndef TARN_HOST_DISPLAY_SPIDEV_H
#define TARN_HOST_DISPLAY_SPIDEV_H

#include <stddef.h>
#include <stdint.h>
#include "error.h"
#include "gpio_lines.h"
#include "panel_link.h"
#include "tarn/tarn_panel.h"

typedef int (*tarn_spidev_ioctl_fn)(void *user, int fd, unsigned long request, void *arg);

#define TARN_SPIDEV_BUFSIZ_DEFAULT 4096u
#define TARN_SPIDEV_PARAMETER_BYTES_MAX 16u /* data calls this short are parameters: command clock */

typedef struct {
    tarn_panel_link link;         /* first (panel_link.h): counts, error, delay */
    int fd;                       /* -1 when not open */
    tarn_spidev_ioctl_fn ioctl;
    void *ioctl_user;
    tarn_gpio_line *dc, *reset;   /* reset may hold no line (set == NULL) */
    uint32_t pixel_hz, command_hz;
    size_t chunk_bytes;           /* the driver's bufsiz */
    int dc_level;                 /* -1 before the first transfer */
    char path[128];
} tarn_spidev;

/* The transfer limit from /sys/module/spidev/parameters/bufsiz, or the default. */
size_t tarn_spidev_bufsiz(void);

/* Opens `path` and sets SPI mode 0, 8 bits a word and `pixel_hz`. 0, or -1 with one
 * line naming the device and what to check; nothing is left open on failure. */
int tarn_spidev_open(tarn_spidev *spi, const char *path, uint32_t pixel_hz, tarn_error *err);

/* The same setup on an already open `fd` through `ioctl` (the tests' seam). */
int tarn_spidev_attach(tarn_spidev *spi, const char *path, int fd, tarn_spidev_ioctl_fn ioctl,
                       void *ioctl_user, uint32_t pixel_hz, tarn_error *err);

/* The transport: command() drives DC low and sends one byte at command_hz, data()
 * drives DC high and sends in chunk_bytes pieces, reset() drives the reset line
 * (asserted = low), delay_ms() calls link.delay. The caller sets dc, reset and, to
 * replace the sleep, link.delay. */
tarn_panel_transport tarn_spidev_transport(tarn_spidev *spi);

/* Closes the device (real fds only); safe to call twice. */
void tarn_spidev_close(tarn_spidev *spi);

#endif
