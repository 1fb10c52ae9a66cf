/* stream_transport.h: the emulated boards' panel transport. Each call becomes a
 * record of the byte stream tarn_panel.h defines ('C' command, 'D' data, 'R' reset,
 * 'W' delay), written through board_write(); the host decodes the stream into its
 * panel emulator. board_panel_transport() (board.h) returns this transport on the
 * boards that link stream_transport.c. */
#ifndef TARN_FIRMWARE_STREAM_TRANSPORT_H
#define TARN_FIRMWARE_STREAM_TRANSPORT_H

#include <stdint.h>

/* The 'E' record: the end of the panel stream, with the firmware's status. Returns
 * 0, or non-zero when board_write failed. */
int stream_transport_end(uint8_t status);

#endif
