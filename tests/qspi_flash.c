/* qspi_flash.c: the model of qspi_flash.h. */
#include "qspi_flash.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define XIP_BASE 0x10000000u
#define SSI_BASE 0x18000000u
#define PADS_BASE 0x40020000u
#define VTOR 0xE000ED08u

#define SR1_BUSY 0x01u
#define SR2_QE 0x02u

/* A transfer's phases as the wires carry them. */
typedef struct {
    uint32_t bits, lines;
} phase;

static void failed(qspi_flash *f, const char *format, ...)
{
    if (f->error[0] != '\0') return; /* the first one says most */
    va_list args;
    va_start(args, format);
    vsnprintf(f->error, sizeof f->error, format, args);
    va_end(args);
}

void qspi_flash_init(qspi_flash *f, const uint8_t *contents, size_t size, uint8_t status1, uint8_t status2)
{
    memset(f, 0, sizeof *f);
    f->contents = contents;
    f->size = size;
    f->status1 = status1;
    f->status2 = status2;
    f->ctrlr0 = 7u << 16; /* 8-bit frames, standard SPI, transmit and receive */
}

static uint32_t field(uint32_t reg, unsigned low, unsigned width)
{
    return (reg >> low) & ((1u << width) - 1u);
}

static uint32_t frame_format_lines(const qspi_flash *f)
{
    static const uint32_t lines[4] = {1u, 2u, 4u, 0u};
    return lines[field(f->ctrlr0, 21, 2)];
}

static void receive(qspi_flash *f, uint32_t value)
{
    if (f->rx_count == QSPI_FIFO_DEPTH) {
        failed(f, "the receive FIFO overflowed");
        return;
    }
    f->rx[(f->rx_head + f->rx_count++) % QSPI_FIFO_DEPTH] = value;
}

static uint32_t flash_byte(const qspi_flash *f, uint32_t address)
{
    return address < f->size ? f->contents[address] : 0xFFu;
}

/* The word the XIP window reads at `address`: the flash's bytes in address order,
 * as memory. */
static uint32_t flash_word(const qspi_flash *f, uint32_t address)
{
    return flash_byte(f, address) | flash_byte(f, address + 1u) << 8 | flash_byte(f, address + 2u) << 16 |
           flash_byte(f, address + 3u) << 24;
}

/* Fast Read Quad I/O's address phase and what follows: 24 address bits and 8 mode
 * bits on four lines, four dummy clocks, data on four lines. */
static int quad_read_shape_ok(qspi_flash *f, phase address, uint32_t wait, uint32_t data_lines)
{
    if (!(f->status2 & SR2_QE)) {
        failed(f, "a quad read with QE clear: IO2 and IO3 are still WP and HOLD");
        return 0;
    }
    if (address.bits != 32u || address.lines != 4u || wait != 4u || data_lines != 4u) {
        failed(f, "a quad read sent %u address and mode bits on %u lines, %u dummy clocks, data on %u lines "
                  "(the W25Q16JV takes 32 on 4, 4, 4)", address.bits, address.lines, wait, data_lines);
        return 0;
    }
    return 1;
}

/* A quad read's address word ({address[23:0], mode}): the data, and whether the
 * mode bits keep the flash in continuous read mode. */
static void quad_read(qspi_flash *f, uint32_t address_and_mode, uint32_t frames)
{
    const uint32_t address = address_and_mode >> 8, mode = address_and_mode & 0xFFu;
    for (uint32_t k = 0; k < frames; k++) receive(f, flash_word(f, address + 4u * k));
    f->continuous = (mode & 0x30u) == 0x20u;
}

/* A command a byte at a time (standard SPI, 8-bit frames, transmit and receive):
 * each byte sent brings one back. */
static void byte_command(qspi_flash *f, const uint32_t *bytes, int count)
{
    const uint32_t command = bytes[0] & 0xFFu;
    receive(f, 0u); /* while the command goes out */
    switch (command) {
    case 0x05:
    case 0x35:
        for (int k = 1; k < count; k++) {
            const uint32_t busy = f->busy_polls > 0 ? SR1_BUSY : 0u;
            if (f->busy_polls > 0 && command == 0x05) f->busy_polls--;
            receive(f, command == 0x05 ? (uint32_t)f->status1 | busy : f->status2);
        }
        return;
    case 0x06:
        f->write_enabled = f->busy_polls == 0;
        break;
    case 0x01:
        if (!f->write_enabled || f->busy_polls > 0) {
            failed(f, "a status write without a write enable before it, or while busy");
            break;
        }
        if (count < 3) failed(f, "a status write of %d bytes: status register 2 is the third", count);
        f->status1 = (uint8_t)bytes[1];
        if (count >= 3) f->status2 = (uint8_t)bytes[2];
        f->status_writes++;
        f->write_enabled = 0;
        f->busy_polls = 3; /* the write takes a while: BUSY for three polls */
        break;
    default:
        failed(f, "command %02Xh in standard SPI, which this model of the W25Q16JV does not take", command);
        break;
    }
    for (int k = 1; k < count; k++) receive(f, 0xFFu);
}

/* An EEPROM-read transfer (TMOD 3): command and address from the transmit FIFO,
 * then NDF + 1 frames back. */
static void eeprom_read(qspi_flash *f)
{
    const uint32_t spi = f->spi_ctrlr0, lines = frame_format_lines(f), trans = field(spi, 0, 2);
    static const uint32_t instruction_bits[4] = {0u, 4u, 8u, 16u};
    const uint32_t inst_bits = instruction_bits[field(spi, 8, 2)];
    const int words = inst_bits != 0u ? 2 : 1;
    if (f->tx_count < words) return; /* the transfer starts when its address is in */
    const phase command = {inst_bits, trans == 2u ? lines : 1u};
    const phase address = {field(spi, 2, 4) * 4u, trans == 0u ? 1u : lines};
    const uint32_t address_word = f->tx[words - 1], wait = field(spi, 11, 5);
    f->tx_count = 0;
    if (field(f->ctrlr0, 16, 5) != 31u) failed(f, "a read of other than 32-bit frames");
    if (inst_bits == 0u && !f->continuous)
        failed(f, "a read without a command while the flash is not in continuous read mode");
    else if (inst_bits != 0u && (f->continuous || command.bits != 8u || command.lines != 1u ||
                                 (f->tx[0] & 0xFFu) != 0xEBu))
        failed(f, "a command of %u bits on %u lines (%02Xh)%s", command.bits, command.lines, f->tx[0] & 0xFFu,
               f->continuous ? " in continuous read mode, which takes none" : "; expected EBh, 8 on 1");
    else if (quad_read_shape_ok(f, address, wait, lines))
        quad_read(f, address_word, field(f->ctrlr1, 0, 16) + 1u);
}

/* Whatever the transmit FIFO holds goes out as one transfer (the SSI holds chip
 * select while it has data): done when the program looks at the status. */
static void transfer(qspi_flash *f)
{
    if (!f->enabled || f->tx_count == 0) return;
    const uint32_t tmod = field(f->ctrlr0, 8, 2);
    if (tmod == 3u) {
        eeprom_read(f);
    } else if (tmod == 0u && frame_format_lines(f) == 1u && field(f->ctrlr0, 16, 5) == 7u) {
        byte_command(f, f->tx, f->tx_count);
        f->tx_count = 0;
    } else {
        failed(f, "a transfer in a mode this model does not take (CTRLR0 0x%08X)", f->ctrlr0);
        f->tx_count = 0;
    }
}

static uint32_t xip_load(qspi_flash *f, uint32_t address)
{
    if (!f->enabled || field(f->ctrlr0, 8, 2) != 3u) {
        failed(f, "an XIP read with the SSI off or not in EEPROM-read mode");
        return 0u;
    }
    /* the XIP block pushes the command and the address, as INST_L orders them */
    const uint32_t spi = f->spi_ctrlr0, offset = address - XIP_BASE, cmd = field(spi, 24, 8);
    if (field(spi, 8, 2) == 0u) {
        f->tx[f->tx_count++] = offset << 8 | cmd; /* {ADDR[23:0], XIP_CMD}: the mode bits */
    } else {
        f->tx[f->tx_count++] = cmd;
        f->tx[f->tx_count++] = offset << 8; /* with EBh, mode bits 0: continuous mode left */
    }
    transfer(f);
    if (f->rx_count == 0) return 0u;
    f->rx_count--;
    const uint32_t word = f->rx[f->rx_head];
    f->rx_head = (f->rx_head + 1) % QSPI_FIFO_DEPTH;
    return word;
}

static uint32_t *ssi_config(qspi_flash *f, uint32_t offset)
{
    switch (offset) {
    case 0x00: return &f->ctrlr0;
    case 0x04: return &f->ctrlr1;
    case 0x14: return &f->baudr;
    case 0xF0: return &f->rx_sample_delay;
    case 0xF4: return &f->spi_ctrlr0;
    default: return NULL;
    }
}

static void ssi_store(qspi_flash *f, uint32_t offset, uint32_t value)
{
    uint32_t *config = ssi_config(f, offset);
    if (config != NULL) {
        if (f->enabled) failed(f, "SSI register 0x%02X written while enabled: the SSI ignores it", offset);
        else *config = value;
    } else if (offset == 0x08) {
        f->enabled = value & 1u;
        if (!f->enabled) f->tx_count = f->rx_count = 0; /* disabling clears the FIFOs */
    } else if (offset == 0x60) {
        if (!f->enabled) failed(f, "the SSI's FIFO written while it is off");
        else if (f->tx_count == QSPI_FIFO_DEPTH) failed(f, "the transmit FIFO overflowed");
        else f->tx[f->tx_count++] = value;
    } else {
        failed(f, "SSI register 0x%02X written, which boot2 has no need of", offset);
    }
}

static uint32_t ssi_load(qspi_flash *f, uint32_t offset)
{
    if (offset == 0x28) { /* SR: all sent, so the transmit FIFO is empty and idle */
        transfer(f);
        return 1u << 2;
    }
    if (offset == 0x60) {
        if (f->rx_count == 0) {
            failed(f, "the receive FIFO read while empty");
            return 0u;
        }
        const uint32_t value = f->rx[f->rx_head];
        f->rx_head = (f->rx_head + 1) % QSPI_FIFO_DEPTH;
        f->rx_count--;
        return value;
    }
    const uint32_t *config = ssi_config(f, offset);
    if (config == NULL) failed(f, "SSI register 0x%02X read", offset);
    return config != NULL ? *config : 0u;
}

uint32_t qspi_flash_load(void *bus, uint32_t address)
{
    qspi_flash *f = bus;
    if (address >= XIP_BASE && address < XIP_BASE + 0x01000000u) return xip_load(f, address);
    if (address >= SSI_BASE && address < SSI_BASE + 0x100u) return ssi_load(f, address - SSI_BASE);
    if (address >= PADS_BASE && address < PADS_BASE + 0x18u) return f->pads[(address - PADS_BASE) / 4u];
    failed(f, "a load from 0x%08X", address);
    return 0u;
}

void qspi_flash_store(void *bus, uint32_t address, uint32_t value)
{
    qspi_flash *f = bus;
    if (address >= SSI_BASE && address < SSI_BASE + 0x100u)
        ssi_store(f, address - SSI_BASE, value);
    else if (address >= PADS_BASE && address < PADS_BASE + 0x18u)
        f->pads[(address - PADS_BASE) / 4u] = value;
    else if (address == VTOR)
        f->vtor = value;
    else
        failed(f, "a store of 0x%08X to 0x%08X", value, address);
}
