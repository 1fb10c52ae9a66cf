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
    return -1;
}
