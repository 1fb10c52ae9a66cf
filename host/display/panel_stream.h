/* panel_stream.h: the emulated boards' panel byte stream (format in tarn_panel.h):
 * decoding it into transport calls, and writing it from transport calls.
 *
 * The decoder replays every record on any transport: the panel emulator's, to see
 * what a board drew, or a real link's. A stream must be well formed to the last
 * byte and end with an 'E' record of status 0; otherwise the error names the byte
 * offset and what was expected there, e.g.
 *   "board.bin: byte 1043: 'D' record of 480 bytes, but the stream ends after 17".
 * Records before the fault have been replayed by then: the emulator shows how far
 * the board got. */
#ifndef TARN_HOST_PANEL_STREAM_H
#define TARN_HOST_PANEL_STREAM_H

#include <stddef.h>
#include <stdint.h>
#include "error.h"
#include "tarn/tarn_panel.h"

/* 0, or -1 with `err` set (also when a transport call fails). */
int tarn_panel_stream_decode(const uint8_t *bytes, size_t count,
                             const tarn_panel_transport *transport, tarn_error *err);

/* The same for a whole file; errors start with its path. */
int tarn_panel_stream_decode_file(const char *path, const tarn_panel_transport *transport,
                                  tarn_error *err);

/* A growing buffer of stream records. Zero-initialise it; its transport appends a
 * record per call (data calls longer than 65535 bytes become several records) and
 * fails only when memory runs out. */
typedef struct {
    uint8_t *bytes;
    size_t count, capacity;
} tarn_panel_stream_writer;

tarn_panel_transport tarn_panel_stream_transport(tarn_panel_stream_writer *writer);

/* Appends the 'E' record. 0, or -1 when memory ran out. */
int tarn_panel_stream_end(tarn_panel_stream_writer *writer, uint8_t status);

void tarn_panel_stream_writer_free(tarn_panel_stream_writer *writer);

#endif
