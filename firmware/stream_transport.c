/* stream_transport.c: the panel transport as the byte stream of tarn_panel.h, for
 * the emulated boards (stream_transport.h). */
#include "stream_transport.h"
#include "board.h"
#include "tarn/tarn_panel.h"

static int stream_command(void *user, uint8_t command)
{
    const uint8_t record[2] = {TARN_STREAM_COMMAND, command};
    (void)user;
    return board_write(record, sizeof record);
}

static int stream_data(void *user, const uint8_t *bytes, size_t count)
{
    (void)user;
    while (count > 0) {
        size_t n = count > 0xFFFFu ? 0xFFFFu : count;
        const uint8_t record[3] = {TARN_STREAM_DATA, (uint8_t)(n >> 8), (uint8_t)n};
        if (board_write(record, sizeof record) != 0 || board_write(bytes, n) != 0) return 1;
        bytes += n;
        count -= n;
    }
    return 0;
}

static int stream_reset(void *user, int asserted)
{
    const uint8_t record[2] = {TARN_STREAM_RESET, (uint8_t)(asserted ? 1 : 0)};
    (void)user;
    return board_write(record, sizeof record);
}

static int stream_delay(void *user, uint16_t milliseconds)
{
    const uint8_t record[3] = {TARN_STREAM_DELAY, (uint8_t)(milliseconds >> 8),
                               (uint8_t)milliseconds};
    (void)user;
    return board_write(record, sizeof record);
}

int stream_transport_end(uint8_t status)
{
    const uint8_t record[2] = {TARN_STREAM_END, status};
    return board_write(record, sizeof record);
}

static const tarn_panel_transport stream_transport = {
    0, stream_command, stream_data, stream_reset, stream_delay
};

const tarn_panel_transport *board_panel_transport(void)
{
    return &stream_transport;
}
