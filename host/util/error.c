#include "error.h"

#include <stdarg.h>
#include <stdio.h>

int tarn_fail(tarn_error *err, const char *format, ...)
{
    if (err == NULL) return -1;
    va_list args;
    va_start(args, format);
    vsnprintf(err->message, sizeof err->message, format, args);
    va_end(args);
    /* file names, field names and values come from users and may hold any
     * character: control characters become '?', so that an error stays one line */
    for (char *c = err->message; *c != '\0'; c++)
        if ((unsigned char)*c < 0x20 || *c == 0x7f) *c = '?';
    return -1;
}

int tarn_fail_in(tarn_error *err, const char *path)
{
    if (err == NULL) return -1;
    tarn_error inner = *err;
    return tarn_fail(err, "%s: %s", path, inner.message);
}
