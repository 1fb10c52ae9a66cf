/* link_counts.h: what a display backend counts while it sends, for `tarn show` and
 * the benchmark: bytes that crossed the SPI wire, the transfers (ioctls, USB
 * reports, line changes) they took, and the time the link needs for them at its
 * clock, modelled from counted bits rather than measured, so figures do not drift
 * with the machine's load. */
#ifndef TARN_HOST_LINK_COUNTS_H
#define TARN_HOST_LINK_COUNTS_H

#include <stdint.h>

typedef struct {
    uint64_t spi_bytes;      /* command and data bytes clocked out to the panel */
    uint64_t transfers;      /* spidev ioctls, MCP2210 command reports, GPIO line sets */
    uint64_t link_ns;        /* the link's own time for them, from the clock and the counts */
    uint64_t busy_replies;   /* MCP2210: 0xF8 answers that were retried */
} tarn_link_counts;

/* ns that `bytes` take at `hz` bits per second, rounded up. */
static inline uint64_t tarn_link_ns(uint64_t bytes, uint32_t hz)
{
    return hz == 0 ? 0 : (bytes * 8u * 1000000000u + hz - 1u) / hz;
}

/* A pause between transfers; real backends sleep, emulated ones tell their panel. */
typedef int (*tarn_delay_fn)(void *user, uint16_t milliseconds);

/* nanosleep for `milliseconds`; `user` is unused. Always 0. */
int tarn_sleep_ms(void *user, uint16_t milliseconds);

#endif
