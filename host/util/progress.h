/* progress.h: a progress line on stderr for work that can take more than a few
 * seconds, e.g.
 *   tarn sweep: pond, error against the reference: 37/112, about 1 min 20 s left
 * It is drawn only when stderr is a terminal (never into a log or a pipe) and the
 * command was not given --quiet, redrawn in place at most five times a second, and
 * erased when the work ends, so that what stays on the screen is the command's own
 * output and its errors. */
#ifndef TARN_HOST_PROGRESS_H
#define TARN_HOST_PROGRESS_H

#include <stddef.h>
#include <time.h>

typedef struct {
    char label[160];
    unsigned long total;
    int shown;                   /* drawn on stderr: a terminal, not quiet */
    struct timespec start, last; /* CLOCK_MONOTONIC: the work's start, the last redraw */
} tarn_progress;

/* `label` is what the work is ("tarn render: frames"); `total` its steps. */
void tarn_progress_start(tarn_progress *p, const char *label, unsigned long total, int quiet);

/* `done` of the total steps are done. */
void tarn_progress_step(tarn_progress *p, unsigned long done);

/* Erases the line. */
void tarn_progress_end(tarn_progress *p);

/* "about 1 min 20 s left" when `done` of `total` took `elapsed_s` seconds at a
 * steady pace ("" before the first step is done). */
void tarn_progress_time_left(double elapsed_s, unsigned long done, unsigned long total, char *out, size_t size);

#endif
