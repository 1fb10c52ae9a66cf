/* dma_transport.c: the real boards' panel transport, over the board's SPI and DMA
 * (panel_spi.h). board_panel_transport() (board.h) returns it.
 *
 * data() starts a DMA transfer and returns at once: while a tile's pixels go out,
 * the core renders the next tile (panel_sink.c alternates two tile buffers).
 * Every call first waits until the previous transfer has finished and the SPI is
 * idle, because D/CX must not change under a byte still being shifted out. Every
 * wait ends after TRANSFER_TIMEOUT_MS: the DMA is stopped and the call fails, which
 * ends the frame with TARN_ERR_SINK instead of hanging (display_main.c then resets
 * the panel and starts over). */
#include "board.h"
#include "panel_spi.h"

/* The longest transfer is a 64x64 tile, 8192 bytes: 2.7 ms at the boards' 25 MHz
 * or 31.25 MHz SPI clock. A transfer still running after this has failed. */
#define TRANSFER_TIMEOUT_MS 100u

/* Command bytes and command parameters (CASET, RASET...) come from the caller's
 * stack, which is gone once the call returns while the DMA is still reading: those
 * short writes are copied here first. Pixel data (the sink's tile buffers) is sent
 * from where it lies. */
#define COPIED_BYTES_MAX 16u
static uint8_t copied[COPIED_BYTES_MAX];

static int wait_idle(void)
{
    const uint32_t start = board_milliseconds();
    for (;;) {
        const int state = panel_spi_poll();
        if (state == 0) return 0;
        if (state < 0 || board_milliseconds() - start > TRANSFER_TIMEOUT_MS) {
            panel_spi_abort();
            return 1;
        }
    }
}

/* Sends `count` bytes with D/CX at `data`; only the last piece is left running. */
static int send(int data, const uint8_t *bytes, size_t count)
{
    if (wait_idle() != 0) return 1;
    panel_spi_dc(data);
    if (count <= COPIED_BYTES_MAX) {
        for (size_t i = 0; i < count; i++) copied[i] = bytes[i];
        bytes = copied;
    }
    while (count > PANEL_SPI_TRANSFER_MAX) {
        panel_spi_start(bytes, PANEL_SPI_TRANSFER_MAX);
        if (wait_idle() != 0) return 1;
        bytes += PANEL_SPI_TRANSFER_MAX;
        count -= PANEL_SPI_TRANSFER_MAX;
    }
    if (count > 0) panel_spi_start(bytes, count);
    return 0;
}

static int dma_command(void *user, uint8_t command)
{
    (void)user;
    return send(0, &command, 1);
}

static int dma_data(void *user, const uint8_t *bytes, size_t count)
{
    (void)user;
    return send(1, bytes, count);
}

static int dma_reset(void *user, int asserted)
{
    (void)user;
    if (wait_idle() != 0) return 1;
    panel_spi_reset_line(asserted);
    return 0;
}

/* At least `milliseconds` after the last byte left: the tick may be about to
 * advance when the wait starts, hence the one extra. */
static int dma_delay(void *user, uint16_t milliseconds)
{
    (void)user;
    if (wait_idle() != 0) return 1;
    const uint32_t start = board_milliseconds();
    while (board_milliseconds() - start < (uint32_t)milliseconds + 1u) {}
    return 0;
}

static const tarn_panel_transport dma_transport = {
    0, dma_command, dma_data, dma_reset, dma_delay
};

const tarn_panel_transport *board_panel_transport(void)
{
    return &dma_transport;
}
