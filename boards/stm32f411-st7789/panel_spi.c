/* panel_spi.c: the ST7789's link on the STM32F411 (firmware/panel_spi.h): SPI1 as
 * a transmit-only master and DMA2 stream 3 feeding it.
 *
 * SPI1 (RM0383 §20.3): master, 8-bit frames, MSB first, mode 3 (CPOL = 1, CPHA = 1:
 * the ST7789 samples on the rising edge, and modules without a CS pin need the clock
 * to idle high), software NSS (SSM = SSI = 1, CS is a GPIO), BR = /4: 25 MHz from
 * the 100 MHz APB2, within the ST7789's write cycle of 16 ns. BIDIMODE with BIDIOE
 * makes it transmit-only on MOSI, so no received byte piles up and overruns.
 * TXDMAEN lets the DMA write DR whenever TXE is set (RM0383 §20.3.9).
 *
 * DMA2 stream 3, channel 3 (RM0383 §9.3.3): memory to peripheral, bytes, memory
 * increment, direct mode (no FIFO), high priority. A transfer is over when the
 * stream has cleared EN itself and then, as RM0383 §20.3.8 asks before touching the
 * SPI, TXE is set and BSY clear: only then has the last bit left MOSI. */
#include "panel_spi.h"
#include "panel_pins.h"

#define SPI_BR_DIV4 1u
#define DMA_CHANNEL_SPI1_TX 3u
#define ABORT_POLLS 100000u

static void pin_write(uint32_t port, uint32_t pin, int high)
{
    GPIO_BSRR(port) = high ? 1u << pin : 1u << (pin + 16u);
}

static void pin_mode(uint32_t port, uint32_t pin, uint32_t mode)
{
    GPIO_MODER(port) = (GPIO_MODER(port) & ~(3u << (2u * pin))) | mode << (2u * pin);
    GPIO_OSPEEDR(port) = (GPIO_OSPEEDR(port) & ~(3u << (2u * pin))) | GPIO_OSPEEDR_HIGH << (2u * pin);
}

static void pin_alternate(uint32_t port, uint32_t pin, uint32_t function)
{
    /* pins 0..7 only: SCK and MOSI are PA5 and PA7 */
    GPIO_AFRL(port) = (GPIO_AFRL(port) & ~(0xFu << (4u * pin))) | function << (4u * pin);
    pin_mode(port, pin, GPIO_MODER_AF);
}

void panel_spi_init(void)
{
    RCC_AHB1ENR |= RCC_AHB1ENR_GPIOAEN | RCC_AHB1ENR_GPIOBEN | RCC_AHB1ENR_DMA2EN;
    RCC_APB2ENR |= RCC_APB2ENR_SPI1EN;
    (void)RCC_APB2ENR; /* the clocks run before the first access */

    /* levels first, then outputs: no glitch. Reset held until tarn_panel_init
     * pulses it; CS asserted for good (the link has this one device). */
    pin_write(PANEL_CS_PORT, PANEL_CS_PIN, 0);
    pin_write(PANEL_DC_PORT, PANEL_DC_PIN, 1);
    pin_write(PANEL_RESET_PORT, PANEL_RESET_PIN, 1);
    pin_write(PANEL_BACKLIGHT_PORT, PANEL_BACKLIGHT_PIN, 1);
    pin_mode(PANEL_CS_PORT, PANEL_CS_PIN, GPIO_MODER_OUTPUT);
    pin_mode(PANEL_DC_PORT, PANEL_DC_PIN, GPIO_MODER_OUTPUT);
    pin_mode(PANEL_RESET_PORT, PANEL_RESET_PIN, GPIO_MODER_OUTPUT);
    pin_mode(PANEL_BACKLIGHT_PORT, PANEL_BACKLIGHT_PIN, GPIO_MODER_OUTPUT);
    pin_alternate(PANEL_SCK_PORT, PANEL_SCK_PIN, GPIO_AF5_SPI1);
    pin_alternate(PANEL_MOSI_PORT, PANEL_MOSI_PIN, GPIO_AF5_SPI1);

    SPI1_CR1 = 0;
    SPI1_CR1 = SPI_CR1_BIDIMODE | SPI_CR1_BIDIOE | SPI_CR1_SSM | SPI_CR1_SSI | SPI_CR1_MSTR |
               (SPI_BR_DIV4 << SPI_CR1_BR_Pos) | SPI_CR1_CPOL | SPI_CR1_CPHA;
    SPI1_CR2 = SPI_CR2_TXDMAEN;
    SPI1_CR1 |= SPI_CR1_SPE;

    DMA2_S3CR = 0;
    DMA2_LIFCR = DMA_STREAM3_ALL_FLAGS;
    DMA2_S3PAR = SPI1_DR_ADDRESS;
    DMA2_S3FCR = 0; /* direct mode */
}

void panel_spi_dc(int data)
{
    pin_write(PANEL_DC_PORT, PANEL_DC_PIN, data);
}

void panel_spi_reset_line(int asserted)
{
    pin_write(PANEL_RESET_PORT, PANEL_RESET_PIN, !asserted);
}

void panel_spi_start(const uint8_t *bytes, size_t count)
{
    DMA2_LIFCR = DMA_STREAM3_ALL_FLAGS; /* a stream starts only with its flags clear */
    DMA2_S3M0AR = (uint32_t)(uintptr_t)bytes;
    DMA2_S3NDTR = (uint32_t)count;
    DMA2_S3CR = (DMA_CHANNEL_SPI1_TX << DMA_SxCR_CHSEL_Pos) | DMA_SxCR_PL_HIGH | DMA_SxCR_MINC |
                DMA_SxCR_DIR_M2P;
    DMA2_S3CR |= DMA_SxCR_EN;
}

int panel_spi_poll(void)
{
    /* FEIF is left out: in direct mode it only reports what the FIFO would have done */
    if (DMA2_LISR & (DMA_STREAM3_TEIF | DMA_STREAM3_DMEIF)) return -1;
    if (DMA2_S3CR & DMA_SxCR_EN) return 1;
    const uint32_t status = SPI1_SR;
    return (status & SPI_SR_TXE) && !(status & SPI_SR_BSY) ? 0 : 1;
}

void panel_spi_abort(void)
{
    DMA2_S3CR &= ~DMA_SxCR_EN;
    for (uint32_t i = 0; i < ABORT_POLLS && (DMA2_S3CR & DMA_SxCR_EN); i++) {}
    DMA2_LIFCR = DMA_STREAM3_ALL_FLAGS;
}
