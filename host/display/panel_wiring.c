/* panel_wiring.c: the emulated module's pins (panel_wiring.h). */
#include "panel_wiring.h"

#include <errno.h>
#include <linux/spi/spidev.h>
#include <string.h>

#include "display_spidev.h"

static int wire_set(void *user, int value)
{
    tarn_wiring_pin *pin = user;
    return tarn_panel_wiring_set(pin->wiring, pin->wire, value);
}

void tarn_panel_wiring_init(tarn_panel_wiring *w, tarn_panel_transport panel)
{
    memset(w, 0, sizeof *w);
    w->panel = panel;
    for (int i = 0; i < TARN_WIRE_COUNT; i++) {
        w->level[i] = i != TARN_WIRE_SCK;
        w->pins[i].wiring = w;
        w->pins[i].wire = (tarn_wire)i;
    }
    w->spidev_bufsiz = TARN_SPIDEV_BUFSIZ_DEFAULT;
    w->slowest_pixel_hz = UINT32_MAX;
    w->spi_mode = -1;
}

tarn_gpio_line tarn_panel_wiring_line(tarn_panel_wiring *w, tarn_wire wire)
{
    static const char *const names[TARN_WIRE_COUNT] = {"DC", "RESX", "CS", "SCK", "MOSI"};
    tarn_gpio_line line = {&w->pins[wire], wire_set, NULL, {0}};
    strncpy(line.name, names[wire], sizeof line.name - 1);
    return line;
}

static int clock_in(tarn_panel_wiring *w, uint8_t byte)
{
    int failed = w->level[TARN_WIRE_DC] ? w->panel.data(w->panel.user, &byte, 1)
                                        : w->panel.command(w->panel.user, byte);
    w->bytes++;
    w->command_bytes += !w->level[TARN_WIRE_DC];
    if (failed) w->failed = 1;
    return failed ? -1 : 0;
}

int tarn_panel_wiring_set(tarn_panel_wiring *w, tarn_wire wire, int level)
{
    level = level != 0;
    w->line_sets++;
    int was = w->level[wire];
    w->level[wire] = level;
    if (wire == TARN_WIRE_RESET && was != level && w->panel.reset)
        return w->panel.reset(w->panel.user, !level) == 0 ? 0 : -1;
    if (wire == TARN_WIRE_CS && level) w->bits = 0; /* deselecting drops a partial byte */
    if (wire == TARN_WIRE_SCK && !was && level && !w->level[TARN_WIRE_CS]) {
        w->shift = (uint8_t)(w->shift << 1 | w->level[TARN_WIRE_MOSI]);
        if (++w->bits == 8) {
            w->bits = 0;
            return clock_in(w, w->shift);
        }
    }
    return 0;
}

int tarn_panel_wiring_spi(tarn_panel_wiring *w, const uint8_t *bytes, size_t count)
{
    if (w->level[TARN_WIRE_DC]) {
        /* data in one call: the emulator takes pixels split anywhere */
        w->bytes += count;
        if (w->panel.data(w->panel.user, bytes, count) != 0) {
            w->failed = 1;
            return -1;
        }
        return 0;
    }
    for (size_t i = 0; i < count; i++)
        if (clock_in(w, bytes[i]) != 0) return -1;
    return 0;
}

int tarn_panel_wiring_spidev_ioctl(void *user, int fd, unsigned long request, void *arg)
{
    tarn_panel_wiring *w = user;
    (void)fd;
    w->ioctls++;
    if (request == SPI_IOC_WR_MODE) {
        w->spi_mode = *(const uint8_t *)arg;
        return 0;
    }
    if (request == SPI_IOC_WR_BITS_PER_WORD || request == SPI_IOC_WR_MAX_SPEED_HZ) return 0;
    if (request != SPI_IOC_MESSAGE(1)) {
        errno = ENOTTY;
        return -1;
    }
    const struct spi_ioc_transfer *t = arg;
    if (w->vanish_after_messages != 0 && w->ioctls > w->vanish_after_messages) {
        errno = ENODEV;
        return -1;
    }
    if (t->len > w->spidev_bufsiz) {
        errno = EMSGSIZE;
        return -1;
    }
    if (t->len > w->largest_transfer) w->largest_transfer = t->len;
    if (!w->level[TARN_WIRE_DC] && t->speed_hz > w->fastest_command_hz) w->fastest_command_hz = t->speed_hz;
    if (w->level[TARN_WIRE_DC] && t->len > TARN_SPIDEV_PARAMETER_BYTES_MAX && t->speed_hz < w->slowest_pixel_hz)
        w->slowest_pixel_hz = t->speed_hz;
    if (w->level[TARN_WIRE_DC] && t->len <= TARN_SPIDEV_PARAMETER_BYTES_MAX && t->speed_hz > w->fastest_parameter_hz)
        w->fastest_parameter_hz = t->speed_hz;
    w->level[TARN_WIRE_CS] = 0; /* the driver selects the device for the message */
    int status = tarn_panel_wiring_spi(w, (const uint8_t *)(uintptr_t)t->tx_buf, t->len);
    w->level[TARN_WIRE_CS] = 1;
    if (status != 0) {
        errno = EIO;
        return -1;
    }
    return (int)t->len;
}

int tarn_panel_wiring_delay(void *user, uint16_t milliseconds)
{
    tarn_panel_wiring *w = user;
    return w->panel.delay_ms(w->panel.user, milliseconds);
}
