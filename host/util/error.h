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

/* Room for two paths of PATH_MAX (a target and its temporary file) with their
 * reason, each character escaped: a message is never cut before its reason. */
#define TARN_ERROR_MESSAGE_MAX 16384

typedef struct {
    char message[TARN_ERROR_MESSAGE_MAX];
} tarn_error;

/* printf-style; always returns -1 so loaders can `return tarn_fail(err, ...)`.
 * File names, fields and values come from users and may hold any character:
 * control characters become "\xNN" (so that an error stays one line) and the
 * Unicode bidirectional controls "\u202E" and the like (so that a name cannot
 * reorder the terminal's line around it). */
int tarn_fail(tarn_error *err, const char *format, ...)
    __attribute__((format(printf, 2, 3)));

/* "path: " before the message err holds, for a step that does not know the file
 * it works on; always returns -1. */
int tarn_fail_in(tarn_error *err, const char *path);

/* `text` with the escapes tarn_fail makes, into `out` (always terminated; a text
 * too long for `size` is cut at a whole character). */
void tarn_escape_text(const char *text, char *out, size_t size);

#endif
