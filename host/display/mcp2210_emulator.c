/* mcp2210_emulator.c: the MCP2210 as its datasheet describes it (mcp2210_emulator.h).
 * Byte positions follow DS22288A section 3's command and response tables. */
#include "mcp2210_emulator.h"

#include <string.h>

static uint16_t get_u16_le(const uint8_t *in)
{
    return (uint16_t)(in[0] | in[1] << 8);
}

static void put_u16_le(uint8_t *out, uint32_t value)
{
    out[0] = (uint8_t)value;
    out[1] = (uint8_t)(value >> 8);
}

void tarn_mcp2210_emulator_init(tarn_mcp2210_emulator *e, tarn_panel_wiring *module)
{
    memset(e, 0, sizeof *e);
    e->module = module;
    for (unsigned pin = 0; pin < TARN_MCP2210_GP_PINS; pin++) e->gp_wire[pin] = -1;
    e->gpio_directions = 0x01FF;
    e->gpio_values = 0x01FF;
    e->bit_rate = 1000000;
    e->idle_cs = e->active_cs = 0x01FF;
    e->transaction_bytes = 4;
}

/* GP pins that are GPIO outputs drive their module pins. */
static void drive_gpio(tarn_mcp2210_emulator *e)
{
    for (unsigned pin = 0; pin < TARN_MCP2210_GP_PINS; pin++) {
        int output = e->designation[pin] == 0 && !(e->gpio_directions >> pin & 1u);
        if (output && e->gp_wire[pin] >= 0)
            tarn_panel_wiring_set(e->module, (tarn_wire)e->gp_wire[pin], e->gpio_values >> pin & 1u);
    }
}

/* The chip-select pins take the idle or the active CS value. */
static void drive_cs(tarn_mcp2210_emulator *e, uint16_t values)
{
    for (unsigned pin = 0; pin < TARN_MCP2210_GP_PINS; pin++)
        if (e->designation[pin] == 1 && e->gp_wire[pin] >= 0)
            tarn_panel_wiring_set(e->module, (tarn_wire)e->gp_wire[pin], values >> pin & 1u);
}

/* 0x21, Set (VM) Current Chip Settings (3.2.4). */
static void set_chip_settings(tarn_mcp2210_emulator *e, const uint8_t *command)
{
    for (unsigned pin = 0; pin < TARN_MCP2210_GP_PINS; pin++) e->designation[pin] = command[4 + pin];
    e->gpio_values = get_u16_le(command + 13) & 0x01FF;
    e->gpio_directions = get_u16_le(command + 15) & 0x01FF;
    drive_gpio(e);
    drive_cs(e, e->idle_cs);
}

/* 0x40, Set (VM) SPI Transfer Settings (3.2.2). */
static void set_spi_settings(tarn_mcp2210_emulator *e, const uint8_t *command, uint8_t *reply)
{
    e->bit_rate = (uint32_t)get_u16_le(command + 4) | (uint32_t)get_u16_le(command + 6) << 16;
    e->idle_cs = get_u16_le(command + 8);
    e->active_cs = get_u16_le(command + 10);
    e->transaction_bytes = get_u16_le(command + 18);
    e->spi_mode = command[20];
    memcpy(reply + 4, command + 4, 17); /* the response echoes the settings */
    drive_cs(e, e->idle_cs);
}

static void end_transaction(tarn_mcp2210_emulator *e)
{
    e->in_transaction = 0;
    e->transferred = 0;
    drive_cs(e, e->idle_cs);
}

static int busy_now(tarn_mcp2210_emulator *e)
{
    if (e->busy_next > 0) {
        e->busy_next--;
        return 1;
    }
    return e->busy_every != 0 && e->transfer_reports % e->busy_every == 0;
}

/* 0x42, Transfer SPI Data (3.5.1): responses 1 to 5 of tables 3-59 to 3-63. */
static void transfer_spi(tarn_mcp2210_emulator *e, const uint8_t *command, uint8_t *reply)
{
    e->transfer_reports++;
    if (e->external_master) {
        reply[1] = TARN_MCP2210_BUS_NOT_AVAILABLE;
        return;
    }
    if (busy_now(e)) {
        e->busy_answers++;
        reply[1] = TARN_MCP2210_BUSY;
        return;
    }
    if (e->finish_pending && command[1] != 0) { /* still clocking the last transaction */
        e->busy_answers++;
        reply[1] = TARN_MCP2210_BUSY;
        return;
    }
    reply[1] = TARN_MCP2210_OK;
    reply[2] = 0; /* no received bytes: the panel has no MISO here */
    if (e->finish_pending) {
        e->finish_pending = 0;
        reply[3] = TARN_MCP2210_ENGINE_FINISHED;
        return;
    }
    unsigned count = command[1] > TARN_MCP2210_CHUNK_BYTES ? TARN_MCP2210_CHUNK_BYTES : command[1];
    int starting = !e->in_transaction;
    if (starting && count > 0) {
        e->in_transaction = 1;
        drive_cs(e, e->active_cs);
    }
    unsigned room = (unsigned)(e->transaction_bytes - e->transferred);
    if (count > room) count = room; /* bytes past the transaction's length are not clocked */
    if (count > 0) tarn_panel_wiring_spi(e->module, command + 4, count);
    e->transferred = (uint16_t)(e->transferred + count);
    if (e->in_transaction && e->transferred >= e->transaction_bytes) {
        end_transaction(e);
        if (e->finish_late) {
            e->finish_pending = 1;
            reply[3] = TARN_MCP2210_ENGINE_NOT_FINISHED;
        } else {
            reply[3] = TARN_MCP2210_ENGINE_FINISHED;
        }
        return;
    }
    reply[3] = starting ? TARN_MCP2210_ENGINE_STARTED : TARN_MCP2210_ENGINE_NOT_FINISHED;
}

static void answer(tarn_mcp2210_emulator *e, const uint8_t *command, uint8_t *reply)
{
    reply[0] = command[0];
    reply[1] = TARN_MCP2210_OK;
    switch (command[0]) {
    case TARN_MCP2210_GET_STATUS: /* 3.6.1: release request status, bus owner */
        reply[2] = 0x01;
        reply[3] = e->external_master ? 0x02 : (e->in_transaction ? 0x01 : 0x00);
        break;
    case TARN_MCP2210_CANCEL_TRANSFER:
        end_transaction(e);
        break;
    case TARN_MCP2210_GET_CHIP_SETTINGS:
        for (unsigned pin = 0; pin < TARN_MCP2210_GP_PINS; pin++) reply[4 + pin] = e->designation[pin];
        put_u16_le(reply + 13, e->gpio_values);
        put_u16_le(reply + 15, e->gpio_directions);
        break;
    case TARN_MCP2210_SET_CHIP_SETTINGS:
        set_chip_settings(e, command);
        break;
    case TARN_MCP2210_SET_GPIO_VALUE: /* 3.2.8: only GPIO pins take the value */
        e->gpio_while_clocking += e->finish_pending != 0;
        e->gpio_values = get_u16_le(command + 4) & 0x01FF;
        drive_gpio(e);
        put_u16_le(reply + 4, e->gpio_values);
        break;
    case TARN_MCP2210_GET_GPIO_VALUE:
        put_u16_le(reply + 4, e->gpio_values);
        break;
    case TARN_MCP2210_SET_SPI_SETTINGS: /* 0xF8: transfer in progress, settings not written */
        if (e->finish_pending) reply[1] = TARN_MCP2210_BUSY;
        else set_spi_settings(e, command, reply);
        break;
    case TARN_MCP2210_GET_SPI_SETTINGS:
        reply[2] = 17;
        put_u16_le(reply + 4, e->bit_rate);
        put_u16_le(reply + 6, e->bit_rate >> 16);
        put_u16_le(reply + 8, e->idle_cs);
        put_u16_le(reply + 10, e->active_cs);
        put_u16_le(reply + 18, e->transaction_bytes);
        reply[20] = e->spi_mode;
        break;
    case TARN_MCP2210_TRANSFER_SPI:
        transfer_spi(e, command, reply);
        break;
    default:
        reply[1] = TARN_MCP2210_UNKNOWN_COMMAND;
    }
}

static int emulator_write(void *user, const uint8_t report[TARN_MCP2210_REPORT_BYTES])
{
    tarn_mcp2210_emulator *e = user;
    if (e->gone || (e->unplug_after != 0 && e->reports >= e->unplug_after)) {
        e->gone = 1;
        return -1;
    }
    e->reports++;
    memset(e->reply, 0, sizeof e->reply);
    answer(e, report, e->reply);
    e->have_reply = 1;
    return 0;
}

static int emulator_read(void *user, uint8_t report[TARN_MCP2210_REPORT_BYTES], int timeout_ms)
{
    tarn_mcp2210_emulator *e = user;
    (void)timeout_ms;
    if (e->gone) return -1;
    if (!e->have_reply) return 0;
    memcpy(report, e->reply, TARN_MCP2210_REPORT_BYTES);
    e->have_reply = 0;
    return (int)TARN_MCP2210_REPORT_BYTES;
}

tarn_mcp2210_seam tarn_mcp2210_emulator_seam(tarn_mcp2210_emulator *e)
{
    tarn_mcp2210_seam seam = {e, emulator_write, emulator_read};
    return seam;
}
