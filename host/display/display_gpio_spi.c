/* display_gpio_spi.c: the bit-banged SPI backend (display_gpio_spi.h). */
#include "display_gpio_spi.h"

static int drive(tarn_gpio_spi *spi, tarn_gpio_line *line, int level)
{
    spi->link.counts.transfers++;
    if (tarn_gpio_line_set(line, level) != 0)
        return tarn_fail(&spi->link.error, "gpio-spi: cannot drive %s", line->name);
    return 0;
}

static int shift_out(tarn_gpio_spi *spi, uint8_t byte)
{
    for (int bit = 7; bit >= 0; bit--) {
        int level = (byte >> bit) & 1;
        if (level != spi->mosi_level) {
            if (drive(spi, spi->mosi, level) != 0) return -1;
            spi->mosi_level = level;
        }
        if (drive(spi, spi->sck, 1) != 0 || drive(spi, spi->sck, 0) != 0) return -1;
    }
    spi->link.counts.spi_bytes++;
    return 0;
}

/* CS framing per call: selected while the bytes go, released after, so a panel
 * that lost a bit finds the byte boundary again at the next call. */
static int send_bytes(tarn_panel_link *link, int dc, const uint8_t *bytes, size_t count)
{
    tarn_gpio_spi *spi = (tarn_gpio_spi *)link; /* the link is its first member */
    if (spi->dc_level != dc) {
        if (drive(spi, spi->dc, dc) != 0) return -1;
        spi->dc_level = dc;
    }
    if (drive(spi, spi->cs, 0) != 0) return -1;
    for (size_t i = 0; i < count; i++)
        if (shift_out(spi, bytes[i]) != 0) return -1;
    return drive(spi, spi->cs, 1);
}

static int gpio_spi_reset(tarn_panel_link *link, int asserted)
{
    tarn_gpio_spi *spi = (tarn_gpio_spi *)link;
    return drive(spi, spi->reset, asserted ? 0 : 1);
}

void tarn_gpio_spi_init(tarn_gpio_spi *spi, tarn_gpio_line *sck, tarn_gpio_line *mosi, tarn_gpio_line *cs,
                        tarn_gpio_line *dc, tarn_gpio_line *reset)
{
    tarn_gpio_spi s = {tarn_panel_link_make(send_bytes), sck, mosi, cs, dc, reset, -1, -1};
    *spi = s;
}

tarn_panel_transport tarn_gpio_spi_transport(tarn_gpio_spi *spi)
{
    spi->link.reset = spi->reset && spi->reset->set ? gpio_spi_reset : NULL;
    return tarn_panel_link_transport(&spi->link);
}
