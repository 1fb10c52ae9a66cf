/* panel_spi.c: the ST7789's link on the RP2040 (firmware/panel_spi.h): SPI0 as a
 * master and DMA channel 0 feeding its transmit FIFO.
 *
 * SPI0 (PL022, datasheet §4.4): Motorola frames of 8 bits, mode 3 (SPO = 1, SPH = 1:
 * the ST7789 samples on the rising edge, and modules without a CS pin need the clock
 * to idle high), CPSDVSR 4 and SCR 0: 125 MHz / 4 = 31.25 MHz, within the ST7789's
 * write cycle of 16 ns. Received bytes are never read; the receive FIFO overruns
 * harmlessly (the overrun only sets a flag). TXDMAE makes the transmit FIFO raise
 * DREQ_SPI0_TX whenever it has room.
 *
 * DMA channel 0 (datasheet §2.5): bytes from memory (INCR_READ) to SSPDR (fixed),
 * paced by DREQ_SPI0_TX, chained to itself (no chaining). A transfer is over when
 * the channel is no longer BUSY and the SPI's transmit FIFO is empty and BSY clear:
 * only then has the last bit left TX. */
#include "panel_spi.h"
#include "panel_pins.h"
#include "rp2040.h"

#define SPI_CPSDVSR 4u
#define SPI_SCR 0u
#define ABORT_POLLS 100000u
#define DMA_CTRL_SPI0_TX (DMA_CTRL_EN | DMA_CTRL_HIGH_PRIORITY | DMA_CTRL_DATA_SIZE_BYTE | \
                          DMA_CTRL_INCR_READ | 0u << DMA_CTRL_CHAIN_TO_Pos | \
                          DREQ_SPI0_TX << DMA_CTRL_TREQ_SEL_Pos)

static void gpio_write(uint32_t gpio, int high)
{
    if (high) SIO_GPIO_OUT_SET = 1u << gpio;
    else SIO_GPIO_OUT_CLR = 1u << gpio;
}

/* Called once clock_init has taken IO_BANK0, PADS_BANK0, SPI0 and DMA out of reset.
 * The pads keep their reset state: output enabled, input enabled, 4 mA. */
void panel_spi_init(void)
{
    /* levels first, then outputs: no glitch. Reset held until tarn_panel_init
     * pulses it; CS asserted for good (the link has this one device). */
    gpio_write(PANEL_CS_GPIO, 0);
    gpio_write(PANEL_DC_GPIO, 1);
    gpio_write(PANEL_RESET_GPIO, 1);
    gpio_write(PANEL_BACKLIGHT_GPIO, 1);
    SIO_GPIO_OE_SET = 1u << PANEL_CS_GPIO | 1u << PANEL_DC_GPIO | 1u << PANEL_RESET_GPIO |
                      1u << PANEL_BACKLIGHT_GPIO;
    IO_BANK0_GPIO_CTRL(PANEL_CS_GPIO) = GPIO_FUNC_SIO;
    IO_BANK0_GPIO_CTRL(PANEL_DC_GPIO) = GPIO_FUNC_SIO;
    IO_BANK0_GPIO_CTRL(PANEL_RESET_GPIO) = GPIO_FUNC_SIO;
    IO_BANK0_GPIO_CTRL(PANEL_BACKLIGHT_GPIO) = GPIO_FUNC_SIO;
    IO_BANK0_GPIO_CTRL(PANEL_SCK_GPIO) = GPIO_FUNC_SPI;
    IO_BANK0_GPIO_CTRL(PANEL_TX_GPIO) = GPIO_FUNC_SPI;

    SPI0_SSPCR1 = 0;
    SPI0_SSPCPSR = SPI_CPSDVSR;
    SPI0_SSPCR0 = SPI_SCR << SSPCR0_SCR_Pos | SSPCR0_SPH | SSPCR0_SPO | SSPCR0_DSS_8BIT;
    SPI0_SSPDMACR = SSPDMACR_TXDMAE;
    SPI0_SSPCR1 = SSPCR1_SSE;

    DMA_CH0_AL1_CTRL = 0; /* disabled until the first transfer */
    DMA_CH0_WRITE_ADDR = SPI0_SSPDR_ADDRESS;
}

void panel_spi_dc(int data)
{
    gpio_write(PANEL_DC_GPIO, data);
}

void panel_spi_reset_line(int asserted)
{
    gpio_write(PANEL_RESET_GPIO, !asserted);
}

void panel_spi_start(const uint8_t *bytes, size_t count)
{
    DMA_CH0_READ_ADDR = (uint32_t)(uintptr_t)bytes;
    DMA_CH0_WRITE_ADDR = SPI0_SSPDR_ADDRESS;
    DMA_CH0_TRANS_COUNT = (uint32_t)count;
    DMA_CH0_CTRL_TRIG = DMA_CTRL_SPI0_TX; /* the write starts it */
}

int panel_spi_poll(void)
{
    const uint32_t ctrl = DMA_CH0_AL1_CTRL;
    if (ctrl & DMA_CTRL_AHB_ERROR) return -1;
    if (ctrl & DMA_CTRL_BUSY) return 1;
    const uint32_t status = SPI0_SSPSR;
    return (status & SSPSR_TFE) && !(status & SSPSR_BSY) ? 0 : 1;
}

void panel_spi_abort(void)
{
    DMA_CHAN_ABORT = 1u; /* channel 0 */
    for (uint32_t i = 0; i < ABORT_POLLS && (DMA_CHAN_ABORT & 1u); i++) {}
    DMA_CH0_AL1_CTRL = DMA_CTRL_READ_ERROR | DMA_CTRL_WRITE_ERROR; /* clears them, and EN */
}
