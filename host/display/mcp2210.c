/* mcp2210.c: the MCP2210 protocol (mcp2210.h). Byte positions are those of the
 * datasheet's command and response tables (DS22288A section 3). */
#include "mcp2210.h"

#include <string.h>

#define ALL_CS_HIGH 0x01FFu /* nine GP pins */

static void put_u16_le(uint8_t *out, uint32_t value)
{
    out[0] = (uint8_t)value;
    out[1] = (uint8_t)(value >> 8);
}

/* One command report and its response; `reply` gets the response. 0, or -1 with
 * bridge->link.error set when the bridge did not answer or answered another command. */
static int exchange(tarn_mcp2210 *b, const uint8_t command[TARN_MCP2210_REPORT_BYTES],
                    uint8_t reply[TARN_MCP2210_REPORT_BYTES])
{
    b->link.counts.transfers++;
    b->link.counts.link_ns += TARN_MCP2210_EXCHANGE_NS;
    if (b->seam.write(b->seam.user, command) != 0)
        return tarn_fail(&b->link.error, "%s: cannot send command 0x%02X: the bridge is gone (unplugged? check the USB cable and lsusb for 04d8:00de)",
                         b->name, command[0]);
    int got = b->seam.read(b->seam.user, reply, TARN_MCP2210_TIMEOUT_MS);
    if (got < 0)
        return tarn_fail(&b->link.error, "%s: no response to command 0x%02X: the bridge is gone (unplugged? check the USB cable and lsusb for 04d8:00de)",
                         b->name, command[0]);
    if (got == 0)
        return tarn_fail(&b->link.error, "%s: no response to command 0x%02X within %d ms (check the bridge; replug it)",
                         b->name, command[0], TARN_MCP2210_TIMEOUT_MS);
    if (reply[0] != command[0])
        return tarn_fail(&b->link.error, "%s: response 0x%02X to command 0x%02X (expected its echo; is this an MCP2210?)",
                         b->name, reply[0], command[0]);
    return 0;
}

static int status_error(tarn_mcp2210 *b, uint8_t command, uint8_t status)
{
    if (status == TARN_MCP2210_BUS_NOT_AVAILABLE)
        return tarn_fail(&b->link.error, "%s: command 0x%02X: the SPI bus is owned by an external master (status 0xF7)",
                         b->name, command);
    if (status == TARN_MCP2210_UNKNOWN_COMMAND)
        return tarn_fail(&b->link.error, "%s: command 0x%02X: unknown to the bridge (status 0xF9)", b->name, command);
    return tarn_fail(&b->link.error, "%s: command 0x%02X failed with status 0x%02X", b->name, command, status);
}

/* A settings command that must complete with status 0x00. */
static int command_ok(tarn_mcp2210 *b, const uint8_t command[TARN_MCP2210_REPORT_BYTES])
{
    uint8_t reply[TARN_MCP2210_REPORT_BYTES];
    if (exchange(b, command, reply) != 0) return -1;
    return reply[1] == TARN_MCP2210_OK ? 0 : status_error(b, command[0], reply[1]);
}

/* 0x30: bytes 4-5 are the GP0..GP8 output values (3.2.8, table 3-48). */
static int set_gpio(tarn_mcp2210 *b, uint8_t pin, int level)
{
    uint16_t values = level ? (uint16_t)(b->gpio_values | 1u << pin) : (uint16_t)(b->gpio_values & ~(1u << pin));
    if (values == b->gpio_values) return 0;
    uint8_t command[TARN_MCP2210_REPORT_BYTES] = {TARN_MCP2210_SET_GPIO_VALUE};
    put_u16_le(command + 4, values);
    if (command_ok(b, command) != 0) return -1;
    b->gpio_values = values;
    return 0;
}

/* 0x40 (3.2.2, table 3-35): bit rate at 4-7, idle CS at 8-9, active CS at 10-11, the
 * three delays at 12-17 (none), bytes per transaction at 18-19, SPI mode at 20. */
static int set_transaction_bytes(tarn_mcp2210 *b, uint16_t bytes)
{
    if (b->transaction_bytes == bytes) return 0;
    uint8_t command[TARN_MCP2210_REPORT_BYTES] = {TARN_MCP2210_SET_SPI_SETTINGS};
    put_u16_le(command + 4, b->wiring.bit_rate);
    put_u16_le(command + 6, b->wiring.bit_rate >> 16);
    put_u16_le(command + 8, ALL_CS_HIGH);
    put_u16_le(command + 10, ALL_CS_HIGH & ~(1u << b->wiring.cs));
    put_u16_le(command + 18, bytes);
    command[20] = 0; /* mode 0: what the ST7789 and ILI9341 sample */
    if (command_ok(b, command) != 0) return -1;
    b->transaction_bytes = bytes;
    return 0;
}

/* One 0x42 report of `count` (0..60) bytes, re-sent while the bridge answers 0xF8.
 * Returns the engine status byte (0x10, 0x20, 0x30), or -1. */
static int send_chunk(tarn_mcp2210 *b, const uint8_t *bytes, size_t count)
{
    uint8_t command[TARN_MCP2210_REPORT_BYTES] = {TARN_MCP2210_TRANSFER_SPI, (uint8_t)count};
    uint8_t reply[TARN_MCP2210_REPORT_BYTES];
    if (count > 0) memcpy(command + 4, bytes, count);
    for (unsigned attempt = 0; attempt < TARN_MCP2210_BUSY_RETRIES; attempt++) {
        if (exchange(b, command, reply) != 0) return -1;
        if (reply[1] == TARN_MCP2210_BUSY) {
            b->link.counts.busy_replies++;
            continue;
        }
        if (reply[1] != TARN_MCP2210_OK) return status_error(b, command[0], reply[1]);
        b->link.counts.spi_bytes += count;
        b->link.counts.link_ns += tarn_link_ns(count, b->wiring.bit_rate);
        return reply[3];
    }
    return tarn_fail(&b->link.error, "%s: the bridge stayed busy (0xF8) for %u tries of one chunk (replug it)",
                     b->name, TARN_MCP2210_BUSY_RETRIES);
}

/* One SPI transaction of `count` bytes: CS low for all of them, 60 a report. */
static int transaction(tarn_mcp2210 *b, const uint8_t *bytes, size_t count)
{
    if (set_transaction_bytes(b, (uint16_t)count) != 0) return -1;
    int engine = 0;
    for (size_t done = 0; done < count;) {
        size_t piece = count - done < TARN_MCP2210_CHUNK_BYTES ? count - done : TARN_MCP2210_CHUNK_BYTES;
        engine = send_chunk(b, bytes + done, piece);
        if (engine < 0) return -1;
        done += piece;
    }
    /* the response to the last chunk may come before the engine finished */
    for (unsigned poll = 0; engine != TARN_MCP2210_ENGINE_FINISHED; poll++) {
        if (poll == TARN_MCP2210_BUSY_RETRIES)
            return tarn_fail(&b->link.error, "%s: the SPI transaction of %zu bytes never finished (engine status 0x%02X)",
                             b->name, count, (unsigned)engine);
        engine = send_chunk(b, NULL, 0);
        if (engine < 0) return -1;
    }
    return 0;
}

static int spi_bytes(tarn_panel_link *link, int dc, const uint8_t *bytes, size_t count)
{
    tarn_mcp2210 *b = (tarn_mcp2210 *)link; /* the link is its first member */
    if (set_gpio(b, b->wiring.dc, dc) != 0) return -1;
    for (size_t done = 0; done < count;) {
        size_t piece = count - done < TARN_MCP2210_TRANSACTION_MAX ? count - done : TARN_MCP2210_TRANSACTION_MAX;
        if (transaction(b, bytes + done, piece) != 0) return -1;
        done += piece;
    }
    return 0;
}

static int bridge_reset(tarn_panel_link *link, int asserted)
{
    tarn_mcp2210 *b = (tarn_mcp2210 *)link;
    return set_gpio(b, b->wiring.reset, !asserted);
}

tarn_panel_transport tarn_mcp2210_transport(tarn_mcp2210 *b)
{
    b->link.reset = b->wiring.reset < TARN_MCP2210_GP_PINS ? bridge_reset : NULL;
    return tarn_panel_link_transport(&b->link);
}

/* 0x21 (3.2.4): GP designations at 4-12 (0x00 GPIO, 0x01 chip select), default
 * outputs at 13-14 (all high: CS idle, DC data, reset released), default
 * directions at 15-16 (0 = output for our pins, 1 = input for the rest). */
static int set_chip_settings(tarn_mcp2210 *b)
{
    uint8_t command[TARN_MCP2210_REPORT_BYTES] = {TARN_MCP2210_SET_CHIP_SETTINGS};
    uint16_t outputs = (uint16_t)(1u << b->wiring.cs | 1u << b->wiring.dc);
    if (b->wiring.reset < TARN_MCP2210_GP_PINS) outputs = (uint16_t)(outputs | 1u << b->wiring.reset);
    for (unsigned pin = 0; pin < TARN_MCP2210_GP_PINS; pin++) command[4 + pin] = pin == b->wiring.cs ? 0x01 : 0x00;
    put_u16_le(command + 13, ALL_CS_HIGH);
    put_u16_le(command + 15, ALL_CS_HIGH & ~outputs);
    if (command_ok(b, command) != 0) return -1;
    b->gpio_values = ALL_CS_HIGH;
    return 0;
}

static int check_wiring(const tarn_mcp2210_wiring *w, const char *name, tarn_error *err)
{
    if (w->cs >= TARN_MCP2210_GP_PINS || w->dc >= TARN_MCP2210_GP_PINS ||
        (w->reset != 0xFF && w->reset >= TARN_MCP2210_GP_PINS))
        return tarn_fail(err, "%s: GP pins are 0..8 (cs %u, dc %u, reset %u)", name, w->cs, w->dc, w->reset);
    if (w->cs == w->dc || w->cs == w->reset || w->dc == w->reset)
        return tarn_fail(err, "%s: cs, dc and reset need a GP pin each (cs %u, dc %u, reset %u)", name, w->cs,
                         w->dc, w->reset);
    if (w->bit_rate < 1500 || w->bit_rate > TARN_MCP2210_BIT_RATE_MAX)
        return tarn_fail(err, "%s: bit rate %u outside 1500..%u", name, (unsigned)w->bit_rate,
                         TARN_MCP2210_BIT_RATE_MAX);
    return 0;
}

int tarn_mcp2210_setup(tarn_mcp2210 *b, tarn_mcp2210_seam seam, const tarn_mcp2210_wiring *wiring,
                       const char *name, tarn_error *err)
{
    memset(b, 0, sizeof *b);
    b->link = tarn_panel_link_make(spi_bytes);
    b->seam = seam;
    b->wiring = *wiring;
    b->name = name;
    if (check_wiring(wiring, name, err) != 0) return -1;
    /* 0x10 (3.6.1): byte 3 is the bus owner, 0x02 an external master */
    uint8_t command[TARN_MCP2210_REPORT_BYTES] = {TARN_MCP2210_GET_STATUS};
    uint8_t reply[TARN_MCP2210_REPORT_BYTES];
    int failed = exchange(b, command, reply) != 0 ||
                 (reply[3] == 0x02 &&
                  tarn_fail(&b->link.error, "%s: the SPI bus is owned by an external master (check what else drives it)",
                            name)) ||
                 set_chip_settings(b) != 0;
    if (failed) {
        *err = b->link.error;
        return -1;
    }
    return 0;
}
