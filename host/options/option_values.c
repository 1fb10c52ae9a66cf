/* option_values.c: the values of command-line options (option_values.h). */
#include "option_values.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tarn/tarn_render.h"

/* Room for the longest list of words with their meanings. */
#define CHOICE_LIST_MAX 320

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

int tarn_parse_number(const char *option, const char *text, unsigned long min, unsigned long max,
                      unsigned long *out, tarn_error *err)
{
    if (tarn_parse_whole(text, min, max, out) == 0) return 0;
    return tarn_fail(err, "%s: expected a whole number %lu..%lu, got '%s'", option, min, max, text ? text : "");
}

int tarn_parse_units(const char *option, const char *text, uint32_t min_q16, uint32_t max_q16, uint32_t *out_q16,
                     tarn_error *err)
{
    char *end = NULL;
    const double v = text != NULL && *text != '\0' ? strtod(text, &end) : -1.0;
    const double q16 = v * 65536.0;
    if (end == NULL || *end != '\0' || !(q16 >= min_q16 && q16 <= max_q16)) /* and not a number fails */
        return tarn_fail(err, "%s: expected world units %g..%g, got '%s'", option, min_q16 / 65536.0,
                         max_q16 / 65536.0, text ? text : "");
    *out_q16 = (uint32_t)(q16 + 0.5);
    return 0;
}

int tarn_find_choice(const char *text, const tarn_option_choice *choices, size_t count, int *value)
{
    for (size_t k = 0; text != NULL && k < count; k++) {
        if (strcmp(text, choices[k].name) == 0) {
            *value = choices[k].value;
            return 0;
        }
    }
    return -1;
}

void tarn_list_choices(const tarn_option_choice *choices, size_t count, char *out, size_t size)
{
    size_t used = 0;
    out[0] = '\0';
    for (size_t k = 0; k < count && used < size; k++) {
        const char *separator = k == 0 ? "" : k + 1 < count ? ", " : " or ";
        int n = choices[k].meaning != NULL
                    ? snprintf(out + used, size - used, "%s%s (%s)", separator, choices[k].name, choices[k].meaning)
                    : snprintf(out + used, size - used, "%s%s", separator, choices[k].name);
        used += n > 0 ? (size_t)n : 0u;
    }
}

int tarn_parse_choice(const char *option, const char *text, const tarn_option_choice *choices, size_t count,
                      int *value, tarn_error *err)
{
    if (tarn_find_choice(text, choices, count, value) == 0) return 0;
    char expected[CHOICE_LIST_MAX];
    tarn_list_choices(choices, count, expected, sizeof expected);
    return tarn_fail(err, "%s: expected %s, got '%s'", option, expected, text ? text : "");
}

int tarn_option_once(tarn_options_seen *seen, const char *name, tarn_error *err)
{
    for (size_t k = 0; k < seen->count; k++)
        if (strcmp(seen->names[k], name) == 0) return tarn_fail(err, "%s: given twice (give it once)", name);
    if (seen->count < TARN_OPTIONS_SEEN_MAX) seen->names[seen->count++] = name;
    return 0;
}

int tarn_usage_error(const char *command, const tarn_error *err)
{
    fprintf(stderr, "tarn: %s; try 'tarn %s%s--help'\n", err->message, command ? command : "", command ? " " : "");
    return TARN_EXIT_BAD_INPUT;
}

int tarn_parse_arguments(int argc, char **argv, const char **scene, tarn_option_reader read, void *options,
                         tarn_error *err)
{
    tarn_options_seen seen = {.count = 0};
    for (int i = 2; i < argc; i++) {
        const char *arg = argv[i];
        if (arg[0] != '-' || strcmp(arg, "-") == 0) {
            if (*scene != NULL) return tarn_fail(err, "unexpected argument '%s'", arg);
            *scene = arg;
            continue;
        }
        if (tarn_option_once(&seen, arg, err) != 0) return -1;
        int taken = read(options, arg, i + 1 < argc ? argv[i + 1] : NULL, err);
        if (taken < 0) return -1;
        if (taken == TARN_OPTION_UNKNOWN) return tarn_fail(err, "unknown option '%s'", arg);
        if (taken == TARN_OPTION_VALUE) i++;
    }
    return 0;
}

int tarn_parse_size(const char *option, const char *text, uint16_t *width, uint16_t *height, tarn_error *err)
{
    const char *x = text ? strchr(text, 'x') : NULL;
    unsigned long w, h;
    char width_text[16];
    if (x != NULL && (size_t)(x - text) < sizeof width_text) {
        memcpy(width_text, text, (size_t)(x - text));
        width_text[x - text] = '\0';
        if (tarn_parse_whole(width_text, 1, TARN_FRAME_SIZE_MAX, &w) == 0 &&
            tarn_parse_whole(x + 1, 1, TARN_FRAME_SIZE_MAX, &h) == 0) {
            *width = (uint16_t)w;
            *height = (uint16_t)h;
            return 0;
        }
    }
    return tarn_fail(err, "%s: expected WxH with each side 1..%u, got '%s'", option, TARN_FRAME_SIZE_MAX,
                     text ? text : "");
}
