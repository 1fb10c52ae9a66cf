#include "panel_stream.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DATA_RECORD_MAX 65535u

/* ---- Decoding ---- */

typedef struct {
    const uint8_t *bytes;
    size_t count;
    size_t record; /* offset of the record being read */
    const tarn_panel_transport *transport;
    tarn_error *err;
} stream_reader;

static size_t bytes_after_record_type(const stream_reader *r)
{
    return r->count - r->record - 1u;
}

/* The record needs `n` bytes after its type byte. */
static int need(const stream_reader *r, size_t n, const char *what)
{
    if (bytes_after_record_type(r) >= n) return 0;
    return tarn_fail(r->err, "byte %zu: '%c' record needs %s, but the stream ends after %zu more byte(s)",
                     r->record, r->bytes[r->record], what, bytes_after_record_type(r));
}

static int transport_failed(const stream_reader *r)
{
    return tarn_fail(r->err, "byte %zu: the transport failed on the '%c' record", r->record,
                     r->bytes[r->record]);
}

static uint16_t u16_be(const uint8_t *bytes)
{
    return (uint16_t)((bytes[0] << 8) | bytes[1]);
}

/* Each replays one record and sets its length: 0, or -1 with the error set. */
static int decode_command(const stream_reader *r, const uint8_t *body, size_t *length)
{
    if (need(r, 1, "a command byte") != 0) return -1;
    if (r->transport->command(r->transport->user, body[0]) != 0) return transport_failed(r);
    *length = 2;
    return 0;
}

static int decode_data(const stream_reader *r, const uint8_t *body, size_t *length)
{
    if (need(r, 2, "2 length bytes") != 0) return -1;
    uint16_t count = u16_be(body);
    if (count == 0)
        return tarn_fail(r->err, "byte %zu: 'D' record of length 0 (expected 1..65535)", r->record);
    if (bytes_after_record_type(r) - 2u < count)
        return tarn_fail(r->err, "byte %zu: 'D' record of %u bytes, but the stream ends after %zu",
                         r->record, count, bytes_after_record_type(r) - 2u);
    if (r->transport->data(r->transport->user, body + 2, count) != 0) return transport_failed(r);
    *length = 3u + count;
    return 0;
}

static int decode_reset(const stream_reader *r, const uint8_t *body, size_t *length)
{
    if (need(r, 1, "a level byte") != 0) return -1;
    if (body[0] > 1)
        return tarn_fail(r->err, "byte %zu: 'R' level %u (expected 0 or 1)", r->record, body[0]);
    /* a link without the line has nothing to do */
    if (r->transport->reset != NULL && r->transport->reset(r->transport->user, body[0]) != 0)
        return transport_failed(r);
    *length = 2;
    return 0;
}

static int decode_delay(const stream_reader *r, const uint8_t *body, size_t *length)
{
    if (need(r, 2, "2 bytes of milliseconds") != 0) return -1;
    if (r->transport->delay_ms != NULL &&
        r->transport->delay_ms(r->transport->user, u16_be(body)) != 0)
        return transport_failed(r);
    *length = 3;
    return 0;
}

/* The 'E' record must be the stream's last two bytes and carry status 0. */
static int decode_end(const stream_reader *r, const uint8_t *body)
{
    if (need(r, 1, "a status byte") != 0) return -1;
    if (body[0] != 0)
        return tarn_fail(r->err, "byte %zu: 'E' record with status %u: the firmware did not finish",
                         r->record, body[0]);
    if (bytes_after_record_type(r) > 1)
        return tarn_fail(r->err, "byte %zu: %zu byte(s) after the 'E' record (expected the stream to end)",
                         r->record + 2u, bytes_after_record_type(r) - 1u);
    return 0;
}

int tarn_panel_stream_decode(const uint8_t *bytes, size_t count,
                             const tarn_panel_transport *transport, tarn_error *err)
{
    stream_reader r = {bytes, count, 0, transport, err};
    while (r.record < count) {
        const uint8_t *body = bytes + r.record + 1;
        size_t length = 0;
        int status;
        switch (bytes[r.record]) {
        case TARN_STREAM_COMMAND: status = decode_command(&r, body, &length); break;
        case TARN_STREAM_DATA: status = decode_data(&r, body, &length); break;
        case TARN_STREAM_RESET: status = decode_reset(&r, body, &length); break;
        case TARN_STREAM_DELAY: status = decode_delay(&r, body, &length); break;
        case TARN_STREAM_END: return decode_end(&r, body);
        default:
            return tarn_fail(err, "byte %zu: unknown record type 0x%02X (expected 'C', 'D', 'R', 'W' or 'E')",
                             r.record, bytes[r.record]);
        }
        if (status != 0) return -1;
        r.record += length;
    }
    return tarn_fail(err, "byte %zu: the stream ends without an 'E' record", count);
}

/* The whole file, read in chunks so that pipes work too. NULL with `err` set. */
static uint8_t *read_file(const char *path, size_t *count, tarn_error *err)
{
    FILE *file = fopen(path, "rb");
    if (file == NULL) return tarn_fail(err, "%s: cannot open: %s", path, strerror(errno)), NULL;
    uint8_t *bytes = NULL;
    size_t capacity = 0;
    *count = 0;
    for (;;) {
        if (*count == capacity) {
            capacity = capacity ? 2 * capacity : 65536;
            uint8_t *grown = realloc(bytes, capacity);
            if (grown == NULL) break;
            bytes = grown;
        }
        size_t got = fread(bytes + *count, 1, capacity - *count, file);
        *count += got;
        if (got == 0) break;
    }
    int failed = ferror(file) || !feof(file);
    fclose(file);
    if (!failed) return bytes;
    free(bytes);
    return tarn_fail(err, "%s: cannot read the whole file", path), NULL;
}

int tarn_panel_stream_decode_file(const char *path, const tarn_panel_transport *transport,
                                  tarn_error *err)
{
    size_t count;
    uint8_t *bytes = read_file(path, &count, err);
    if (bytes == NULL) return -1;
    tarn_error inner;
    int status = tarn_panel_stream_decode(bytes, count, transport, &inner);
    free(bytes);
    if (status != 0) return tarn_fail(err, "%s: %s", path, inner.message);
    return 0;
}

/* ---- Writing ---- */

static int append(tarn_panel_stream_writer *w, const uint8_t *bytes, size_t count)
{
    if (count > w->capacity - w->count) {
        size_t capacity = w->capacity ? w->capacity : 65536;
        while (capacity - w->count < count) capacity *= 2;
        uint8_t *grown = realloc(w->bytes, capacity);
        if (grown == NULL) return -1;
        w->bytes = grown;
        w->capacity = capacity;
    }
    memcpy(w->bytes + w->count, bytes, count);
    w->count += count;
    return 0;
}

static int append_record(tarn_panel_stream_writer *w, uint8_t type, const uint8_t *body,
                         size_t count)
{
    return append(w, &type, 1) != 0 ? -1 : append(w, body, count);
}

static int write_command(void *user, uint8_t command)
{
    return append_record(user, TARN_STREAM_COMMAND, &command, 1);
}

static int write_data(void *user, const uint8_t *bytes, size_t count)
{
    while (count > 0) {
        size_t chunk = count < DATA_RECORD_MAX ? count : DATA_RECORD_MAX;
        uint8_t length[2] = {(uint8_t)(chunk >> 8), (uint8_t)chunk};
        if (append_record(user, TARN_STREAM_DATA, length, 2) != 0 || append(user, bytes, chunk) != 0)
            return -1;
        bytes += chunk;
        count -= chunk;
    }
    return 0;
}

static int write_reset(void *user, int asserted)
{
    uint8_t level = asserted ? 1 : 0;
    return append_record(user, TARN_STREAM_RESET, &level, 1);
}

static int write_delay(void *user, uint16_t milliseconds)
{
    uint8_t ms[2] = {(uint8_t)(milliseconds >> 8), (uint8_t)milliseconds};
    return append_record(user, TARN_STREAM_DELAY, ms, 2);
}

tarn_panel_transport tarn_panel_stream_transport(tarn_panel_stream_writer *writer)
{
    tarn_panel_transport transport = {writer, write_command, write_data, write_reset, write_delay};
    return transport;
}

int tarn_panel_stream_end(tarn_panel_stream_writer *writer, uint8_t status)
{
    return append_record(writer, TARN_STREAM_END, &status, 1);
}

void tarn_panel_stream_writer_free(tarn_panel_stream_writer *writer)
{
    free(writer->bytes);
    writer->bytes = NULL;
    writer->count = writer->capacity = 0;
}
