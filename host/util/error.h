/* error.h: one-line user-facing errors for the host tool.
 *
 * Every loader reports bad input by filling a tarn_error with a single line that
 * names the file, the line or field, and what was expected, e.g.
 *   "scenes/pond.json: objects[2].radius: expected a number > 0, got -1"
 * The CLI prints it after "tarn: " and exits with status 2. */
#ifndef TARN_HOST_ERROR_H
#define TARN_HOST_ERROR_H

#include <stddef.h>

#define TARN_EXIT_BAD_INPUT 2

typedef struct {
    char message[512];
} tarn_error;

/* printf-style; always returns -1 so loaders can `return tarn_fail(err, ...)`.
 * Control characters in the result (from file names or values) become '?'. */
int tarn_fail(tarn_error *err, const char *format, ...)
    __attribute__((format(printf, 2, 3)));

/* "path: " before the message err holds, for a step that does not know the file
 * it works on; always returns -1. */
int tarn_fail_in(tarn_error *err, const char *path);

#endif
