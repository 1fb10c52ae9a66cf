/* display_spidev.c: the spidev backend (display_spidev.h). */
#include "display_spidev.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/spi/spidev.h>
#include <stdio.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

/* Commands and parameters go at no more than this: panels' command timing is the
 * slow part of their datasheets, and the bytes are few. */
#define COMMAND_HZ_MAX 10000000u

size_t tarn_spidev_bufsiz(void)
{
    FILE *f = fopen("/sys/module/spidev/parameters/bufsiz", "r");
    unsigned long value = 0;
    if (f != NULL) {
        if (fscanf(f, "%lu", &value) != 1) value = 0;
        fclose(f);
    }
    return value >= 64 && value <= (1ul << 24) ? (size_t)value : TARN_SPIDEV_BUFSIZ_DEFAULT;
}

static int real_ioctl(void *user, int fd, unsigned long request, void *arg)
{
    (void)user;
    return ioctl(fd, request, arg);
}

static int spidev_send(tarn_panel_link *link, int dc, const uint8_t *bytes, size_t count);

int tarn_spidev_attach(tarn_spidev *spi, const char *path, int fd, tarn_spidev_ioctl_fn ioctl_fn,
                       void *ioctl_user, uint32_t pixel_hz, tarn_error *err)
{
    memset(spi, 0, sizeof *spi);
    spi->link = tarn_panel_link_make(spidev_send);
    spi->fd = fd;
    spi->ioctl = ioctl_fn;
    spi->ioctl_user = ioctl_user;
    spi->pixel_hz = pixel_hz;
    spi->command_hz = pixel_hz < COMMAND_HZ_MAX ? pixel_hz : COMMAND_HZ_MAX;
    spi->chunk_bytes = tarn_spidev_bufsiz();
    spi->dc_level = -1;
    snprintf(spi->path, sizeof spi->path, "%s", path);
    uint8_t mode = SPI_MODE_0, bits = 8;
    uint32_t hz = pixel_hz;
    if (ioctl_fn(ioctl_user, fd, SPI_IOC_WR_MODE, &mode) != 0) {
        int e = errno;
        return tarn_fail(err, "spidev:%s: not an SPI device (%s); expected /dev/spidevB.C (check ls /dev/spidev*)",
                         path, strerror(e));
    }
    if (ioctl_fn(ioctl_user, fd, SPI_IOC_WR_BITS_PER_WORD, &bits) != 0 ||
        ioctl_fn(ioctl_user, fd, SPI_IOC_WR_MAX_SPEED_HZ, &hz) != 0) {
        int e = errno;
        return tarn_fail(err, "spidev:%s: cannot set 8-bit words at %u Hz: %s (check --hz)", path,
                         (unsigned)pixel_hz, strerror(e));
    }
    return 0;
}

int tarn_spidev_open(tarn_spidev *spi, const char *path, uint32_t pixel_hz, tarn_error *err)
{
    int fd = open(path, O_RDWR | O_CLOEXEC);
    if (fd < 0) {
        int e = errno;
        spi->fd = -1;
        return tarn_fail(err, "spidev:%s: cannot open: %s (check that SPI is enabled, e.g. dtparam=spi=on, "
                         "ls /dev/spidev*, and that you are in group spi)", path, strerror(e));
    }
    if (tarn_spidev_attach(spi, path, fd, real_ioctl, NULL, pixel_hz, err) != 0) {
        close(fd);
        spi->fd = -1;
        return -1;
    }
    return 0;
}

/* One message of one transfer: the driver's unit, at most chunk_bytes long. */
static int transfer(tarn_spidev *spi, const uint8_t *bytes, size_t count, uint32_t hz)
{
    struct spi_ioc_transfer t;
    memset(&t, 0, sizeof t);
    t.tx_buf = (uintptr_t)bytes;
    t.len = (uint32_t)count;
    t.speed_hz = hz;
    t.bits_per_word = 8;
    if (spi->ioctl(spi->ioctl_user, spi->fd, SPI_IOC_MESSAGE(1), &t) < 0) {
        int e = errno;
        return tarn_fail(&spi->link.error, "spidev:%s: a transfer of %zu bytes failed: %s (was the device removed?)",
                         spi->path, count, strerror(e));
    }
    spi->link.counts.spi_bytes += count;
    spi->link.counts.transfers++;
    spi->link.counts.link_ns += tarn_link_ns(count, hz);
    return 0;
}

static int set_dc(tarn_spidev *spi, int level)
{
    if (spi->dc_level == level) return 0;
    if (tarn_gpio_line_set(spi->dc, level) != 0)
        return tarn_fail(&spi->link.error, "spidev:%s: cannot drive %s", spi->path, spi->dc->name);
    spi->dc_level = level;
    return 0;
}

static int spidev_send(tarn_panel_link *link, int dc, const uint8_t *bytes, size_t count)
{
    tarn_spidev *spi = (tarn_spidev *)link; /* the link is its first member */
    if (set_dc(spi, dc) != 0) return -1;
    uint32_t hz = !dc || count <= TARN_SPIDEV_PARAMETER_BYTES_MAX ? spi->command_hz : spi->pixel_hz;
    for (size_t done = 0; done < count;) {
        size_t piece = count - done < spi->chunk_bytes ? count - done : spi->chunk_bytes;
        if (transfer(spi, bytes + done, piece, hz) != 0) return -1;
        done += piece;
    }
    return 0;
}

static int spidev_reset(tarn_panel_link *link, int asserted)
{
    tarn_spidev *spi = (tarn_spidev *)link;
    if (tarn_gpio_line_set(spi->reset, asserted ? 0 : 1) != 0)
        return tarn_fail(&link->error, "spidev:%s: cannot drive %s", spi->path, spi->reset->name);
    return 0;
}

tarn_panel_transport tarn_spidev_transport(tarn_spidev *spi)
{
    spi->link.reset = spi->reset && spi->reset->set ? spidev_reset : NULL;
    return tarn_panel_link_transport(&spi->link);
}

void tarn_spidev_close(tarn_spidev *spi)
{
    if (spi->fd >= 0 && spi->ioctl == real_ioctl) close(spi->fd);
    spi->fd = -1;
}
