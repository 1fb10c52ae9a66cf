/* option_values.c: the values of command-line options (option_values.h). */
#include "option_values.h"

#include <errno.h>
#include <stdlib.h>

int tarn_parse_whole(const char *text, unsigned long min, unsigned long max, unsigned long *out)
{
    if (text == NULL || *text < '0' || *text > '9') return -1;
    errno = 0;
    char *end;
    unsigned long value = strtoul(text, &end, 10);
    if (errno != 0 || *end != '\0' || value < min || value > max) return -1;
    *out = value;
    return 0;
}
