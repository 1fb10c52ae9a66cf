/* qspi_flash.h: the RP2040's XIP SSI (DW_apb_ssi, datasheet §4.10, the registers
 * and modes boot2 uses) and a Winbond W25Q16JV behind it (the Pico's flash: its
 * status registers, write enable, status write, Fast Read Quad I/O and its
 * continuous read mode), for tests/test_boot2.c. What the SSI sends is checked
 * against what the flash takes (each phase's bits and lines, the dummy clocks); a
 * mismatch, a register written where the SSI ignores it, or a command the flash
 * does not know is recorded in `error` and the transfer gives nothing back. */
#ifndef TARN_TEST_QSPI_FLASH_H
#define TARN_TEST_QSPI_FLASH_H

#include <stddef.h>
#include <stdint.h>

#define QSPI_FIFO_DEPTH 16

typedef struct {
    /* the flash */
    const uint8_t *contents; /* read from address 0 up */
    size_t size;
    uint8_t status1, status2;
    int write_enabled, busy_polls, continuous;
    int status_writes;         /* 01h commands taken */
    /* the SSI's registers and FIFOs */
    uint32_t ctrlr0, ctrlr1, enabled, baudr, rx_sample_delay, spi_ctrlr0;
    uint32_t tx[QSPI_FIFO_DEPTH], rx[QSPI_FIFO_DEPTH];
    int tx_count, rx_head, rx_count;
    /* the rest of the bus boot2 touches */
    uint32_t pads[6];         /* PADS_QSPI: voltage select, SCLK, SD0..SD3 */
    uint32_t vtor;
    char error[200];
} qspi_flash;

/* A flash of `size` bytes at `contents`, with its status registers as given, and
 * the SSI as the bootrom leaves it (off, standard SPI). */
void qspi_flash_init(qspi_flash *f, const uint8_t *contents, size_t size, uint8_t status1, uint8_t status2);

/* The bus at the SSI (0x18000000), the QSPI pads (0x40020000), VTOR, and the XIP
 * window (0x10000000): a load there is what the XIP cache fetches, one access of
 * the SSI as set. Any other address is an error. */
uint32_t qspi_flash_load(void *f, uint32_t address);
void qspi_flash_store(void *f, uint32_t address, uint32_t value);

#endif
