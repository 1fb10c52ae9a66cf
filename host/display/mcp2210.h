/* mcp2210.h: a panel behind Microchip's MCP2210 USB-to-SPI bridge.
 *
 * The bridge is a USB HID device that answers every 64-byte command report with a
 * 64-byte response (datasheet DS22288A, section 3). This file speaks that protocol
 * over a seam of two calls, so the same code runs on hidapi (mcp2210_hidapi.c) and
 * on the emulator of the datasheet (mcp2210_emulator.c):
 *   - 0x10 Get MCP2210 Status (3.6.1): the SPI bus must not be owned by an external master
 *   - 0x21 Set (VM) Current Chip Settings (3.2.4): the CS pin as chip select, DC and
 *     reset as GPIO outputs, idle high
 *   - 0x40 Set (VM) SPI Transfer Settings (3.2.2): bit rate, CS levels, mode 0, and
 *     the bytes per SPI transaction, re-sent whenever a transfer's length changes
 *   - 0x42 Transfer SPI Data (3.5.1): up to 60 bytes a report; 0xF8 (transfer in
 *     progress, data not accepted) is answered by sending the same chunk again;
 *     engine status 0x20 (started) and 0x30 (not finished) ask for more, 0x10 says
 *     the transaction ended (polled with empty chunks when it comes late)
 *   - 0x30 Set (VM) GPIO Current Pin Value (3.2.8): DC before command and data bytes,
 *     the reset line
 * A write or read that fails, or a response that does not echo its command, is the
 * bridge gone (unplugged): the transport call fails and `error` says so. */
#ifndef TARN_HOST_MCP2210_H
#define TARN_HOST_MCP2210_H

#include <stddef.h>
#include <stdint.h>
#include "error.h"
#include "panel_link.h"
#include "tarn/tarn_panel.h"

#define TARN_MCP2210_REPORT_BYTES 64u
#define TARN_MCP2210_CHUNK_BYTES 60u        /* SPI data bytes per 0x42 report */
#define TARN_MCP2210_TRANSACTION_MAX 65535u /* bytes per SPI transaction: a 16-bit field */
#define TARN_MCP2210_BIT_RATE_MAX 12000000u /* datasheet features: 1500 bps to 12 Mbps */
#define TARN_MCP2210_GP_PINS 9u
#define TARN_MCP2210_BUSY_RETRIES 10000u    /* 0xF8 answers to one chunk before giving up */
#define TARN_MCP2210_TIMEOUT_MS 1000

/* The command codes and status bytes this file uses (datasheet section 3). */
enum {
    TARN_MCP2210_GET_STATUS = 0x10,
    TARN_MCP2210_CANCEL_TRANSFER = 0x11,
    TARN_MCP2210_GET_CHIP_SETTINGS = 0x20,
    TARN_MCP2210_SET_CHIP_SETTINGS = 0x21,
    TARN_MCP2210_SET_GPIO_VALUE = 0x30,
    TARN_MCP2210_GET_GPIO_VALUE = 0x31,
    TARN_MCP2210_SET_SPI_SETTINGS = 0x40,
    TARN_MCP2210_GET_SPI_SETTINGS = 0x41,
    TARN_MCP2210_TRANSFER_SPI = 0x42,

    TARN_MCP2210_OK = 0x00,
    TARN_MCP2210_BUS_NOT_AVAILABLE = 0xF7, /* an external master owns the SPI bus */
    TARN_MCP2210_BUSY = 0xF8,              /* SPI transfer in progress: data not accepted */
    TARN_MCP2210_UNKNOWN_COMMAND = 0xF9,

    TARN_MCP2210_ENGINE_FINISHED = 0x10,
    TARN_MCP2210_ENGINE_STARTED = 0x20,
    TARN_MCP2210_ENGINE_NOT_FINISHED = 0x30
};

/* The seam the USB calls sit behind. */
typedef struct {
    void *user;
    /* 0, or -1 when the report could not be sent */
    int (*write)(void *user, const uint8_t report[TARN_MCP2210_REPORT_BYTES]);
    /* 64 when a report arrived, 0 on timeout, -1 when the device is gone */
    int (*read)(void *user, uint8_t report[TARN_MCP2210_REPORT_BYTES], int timeout_ms);
} tarn_mcp2210_seam;

/* Which GP pin does what. */
typedef struct {
    uint8_t cs, dc, reset;  /* 0..8; reset 0xFF: not wired */
    uint32_t bit_rate;      /* SPI bits per second, 1500..12000000 */
} tarn_mcp2210_wiring;

/* The model of the USB side for link_ns: a full-speed HID interrupt endpoint moves
 * one report each way per 1 ms frame, so a command and its response take 1 ms at
 * best. The SPI bits of the chunk are added at the bit rate. */
#define TARN_MCP2210_EXCHANGE_NS 1000000u

typedef struct {
    tarn_panel_link link;     /* first (panel_link.h); its counts' transfers are
                                 command reports */
    tarn_mcp2210_seam seam;
    tarn_mcp2210_wiring wiring;
    const char *name;         /* "mcp2210" or "mcp2210:SERIAL", for messages */
    uint16_t gpio_values;     /* the outputs as last set */
    uint16_t transaction_bytes; /* bytes per SPI transaction as last set; 0: not set */
} tarn_mcp2210;

/* Checks the bridge answers and owns its SPI bus, then sets the chip and SPI
 * settings for the wiring. 0, or -1 with one line in `err`. */
int tarn_mcp2210_setup(tarn_mcp2210 *bridge, tarn_mcp2210_seam seam, const tarn_mcp2210_wiring *wiring,
                       const char *name, tarn_error *err);

/* command() and data() as SPI transactions with DC set through GPIO; reset() when
 * the wiring has a reset pin; delay_ms() calls link.delay (a sleep unless replaced). */
tarn_panel_transport tarn_mcp2210_transport(tarn_mcp2210 *bridge);

#endif
