/* mcp2210_emulator.h: an MCP2210 behind the same seam hidapi sits behind, answering
 * each 64-byte command report as the datasheet (DS22288A section 3) says, with its
 * SPI pins and GP pins wired to an emulated panel module (panel_wiring.h).
 *
 * Modelled: chip settings (GP designations, default outputs and directions), GPIO
 * values and directions, SPI transfer settings, SPI transactions of the set length
 * in chunks of up to 60 bytes with CS asserted from the first byte to the last,
 * engine status 0x20 / 0x30 / 0x10, cancel, chip status, unknown commands (0xF9).
 * Faults to inject: busy answers (0xF8, data not accepted), an external master
 * owning the bus (0xF7), the engine finishing one poll late, and the device
 * unplugged after a number of reports. */
#ifndef TARN_HOST_MCP2210_EMULATOR_H
#define TARN_HOST_MCP2210_EMULATOR_H

#include <stdint.h>
#include "mcp2210.h"
#include "panel_wiring.h"

typedef struct {
    tarn_panel_wiring *module;       /* the panel on the SPI bus and GP pins */
    int8_t gp_wire[TARN_MCP2210_GP_PINS]; /* the module pin each GP pin drives, -1 none */

    /* chip state (volatile settings) */
    uint8_t designation[TARN_MCP2210_GP_PINS]; /* 0 GPIO, 1 chip select, 2 dedicated */
    uint16_t gpio_values, gpio_directions;     /* bit per GP; direction 1 = input */
    uint32_t bit_rate;
    uint16_t idle_cs, active_cs, transaction_bytes;
    uint8_t spi_mode;
    uint16_t transferred;                      /* bytes of the transaction in progress */
    int in_transaction, finish_pending;

    /* the response to the last command, until read */
    uint8_t reply[TARN_MCP2210_REPORT_BYTES];
    int have_reply;

    /* faults */
    unsigned busy_next;      /* answer the next this many 0x42 reports with 0xF8 */
    unsigned busy_every;     /* and every busy_every-th one (0: never) */
    int finish_late;         /* the last chunk answers 0x30; the engine goes on clocking
                                until a poll (0x42 of 0 bytes) answers 0x10. Meanwhile
                                new data and 0x40 answer 0xF8, as the datasheet says
                                of a transfer in progress */
    int external_master;     /* the bus belongs to someone else: 0x42 answers 0xF7 */
    uint64_t unplug_after;   /* reports accepted before the device vanishes (0: never) */

    /* counts */
    uint64_t reports, transfer_reports, busy_answers;
    unsigned gpio_while_clocking; /* 0x30s while the engine still clocked: on the real
                                     chip D/CX would change under the last byte */
    int gone;
} tarn_mcp2210_emulator;

/* Power-on defaults: every GP a GPIO input, SPI at 1 Mbps, transactions of 4 bytes,
 * CS pins idle high; `gp_wire` all -1 (the caller wires the module's pins). */
void tarn_mcp2210_emulator_init(tarn_mcp2210_emulator *emulator, tarn_panel_wiring *module);

tarn_mcp2210_seam tarn_mcp2210_emulator_seam(tarn_mcp2210_emulator *emulator);

#endif
