/* clock.h: the monotonic clock the tool times things by (frame times, progress,
 * benchmarks): never set back, unlike the time of day. */
#ifndef TARN_HOST_CLOCK_H
#define TARN_HOST_CLOCK_H

/* Seconds from an arbitrary start, to the nanosecond. */
double tarn_clock_seconds(void);

#endif
