#include "progress.h"

#include <stdio.h>
#include <unistd.h>

/* Redraws closer than this are skipped: a terminal needs no more. */
#define REDRAW_SECONDS 0.2

static double seconds_between(const struct timespec *from, const struct timespec *to)
{
    return (double)(to->tv_sec - from->tv_sec) + 1e-9 * (double)(to->tv_nsec - from->tv_nsec);
}

void tarn_progress_time_left(double elapsed_s, unsigned long done, unsigned long total, char *out, size_t size)
{
    if (done == 0 || done >= total) {
        out[0] = '\0';
        return;
    }
    const unsigned long left = (unsigned long)(elapsed_s * (double)(total - done) / (double)done + 0.5);
    if (left >= 3600) snprintf(out, size, "about %lu h %lu min left", left / 3600, left % 3600 / 60);
    else if (left >= 60) snprintf(out, size, "about %lu min %lu s left", left / 60, left % 60);
    else if (left >= 1) snprintf(out, size, "about %lu s left", left);
    else snprintf(out, size, "under a second left");
}

void tarn_progress_start(tarn_progress *p, const char *label, unsigned long total, int quiet)
{
    snprintf(p->label, sizeof p->label, "%s", label);
    p->total = total;
    p->shown = !quiet && isatty(STDERR_FILENO);
    clock_gettime(CLOCK_MONOTONIC, &p->start);
    p->last = p->start;
    tarn_progress_step(p, 0);
}

void tarn_progress_step(tarn_progress *p, unsigned long done)
{
    if (!p->shown) return;
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    if (done > 0 && done < p->total && seconds_between(&p->last, &now) < REDRAW_SECONDS) return;
    p->last = now;
    char left[64];
    tarn_progress_time_left(seconds_between(&p->start, &now), done, p->total, left, sizeof left);
    /* \r and erase-to-end: the line is redrawn in place */
    fprintf(stderr, "\r%s: %lu/%lu%s%s\033[K", p->label, done, p->total, left[0] ? ", " : "", left);
    fflush(stderr);
}

void tarn_progress_end(tarn_progress *p)
{
    if (!p->shown) return;
    fputs("\r\033[K", stderr);
    fflush(stderr);
}
