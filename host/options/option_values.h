/* option_values.h: a command line's options and their values, read the same way by
 * every command's parser (cli_options.c, show_options.c, quality_options.c,
 * sweep.c), with the same one-line messages:
 *   --send: expected bands, tiles or changed, got 'x'
 *   --tile: expected a whole number 8..64, got 'x'
 *   unknown option '--x' */
#ifndef TARN_HOST_OPTION_VALUES_H
#define TARN_HOST_OPTION_VALUES_H

#include <stddef.h>
#include <stdint.h>
#include "error.h"

/* The animation clock of render --frames and of show: frames per second. */
#define TARN_CLI_FPS_MAX 120u
#define TARN_CLI_FPS_DEFAULT 30u

/* A whole decimal number in [min, max], nothing else in the text (NULL is none):
 * 0 with *out set, or -1. */
int tarn_parse_whole(const char *text, unsigned long min, unsigned long max, unsigned long *out);

/* The same, or -1 with "OPTION: expected a whole number MIN..MAX, got 'text'". */
int tarn_parse_number(const char *option, const char *text, unsigned long min, unsigned long max,
                      unsigned long *out, tarn_error *err);

/* A decimal number of world units in [min, max] (Q16.16 each): 0 with *out_q16 set
 * to it, rounded to Q16.16, or -1 with "OPTION: expected world units MIN..MAX, got
 * 'text'". */
int tarn_parse_units(const char *option, const char *text, uint32_t min_q16, uint32_t max_q16, uint32_t *out_q16,
                     tarn_error *err);

/* A frame size "WxH", each side 1..TARN_FRAME_SIZE_MAX: 0, or -1 with
 * "OPTION: expected WxH with each side 1..1024, got 'text'". */
int tarn_parse_size(const char *option, const char *text, uint16_t *width, uint16_t *height, tarn_error *err);
/* A word an option takes and the value it stands for; `meaning`, when not NULL,
 * follows the word in messages: "on (find each cluster's screen box once a frame)". */
typedef struct {
    const char *name;
    int value;
    const char *meaning;
} tarn_option_choice;

/* A static table and its length, for the functions below. */
#define TARN_CHOICES(table) (table), sizeof(table) / sizeof(table)[0]

/* The value `text` names among `choices`: 0 with *value set, or -1 (NULL names none). */
int tarn_find_choice(const char *text, const tarn_option_choice *choices, size_t count, int *value);

/* The words as a message lists them, "a, b or c", each with its meaning. */
void tarn_list_choices(const tarn_option_choice *choices, size_t count, char *out, size_t size);

/* tarn_find_choice, or -1 with "OPTION: expected a, b or c, got 'text'" in `err`. */
int tarn_parse_choice(const char *option, const char *text, const tarn_option_choice *choices, size_t count,
                      int *value, tarn_error *err);

/* What a command's reader did with one option: took the word after it as its value,
 * did not know it, or took it alone (a flag); -1 with `err` set for a bad value. */
enum { TARN_OPTION_VALUE = 0, TARN_OPTION_UNKNOWN = 1, TARN_OPTION_FLAG = 2 };

/* One option `name` of the command, `value` the word after it (NULL at the end). */
typedef int (*tarn_option_reader)(void *options, const char *name, const char *value, tarn_error *err);

/* The options a command line has given so far: each may stand once, since a
 * second would silently win over the first. */
#define TARN_OPTIONS_SEEN_MAX 64
typedef struct {
    const char *names[TARN_OPTIONS_SEEN_MAX];
    size_t count;
} tarn_options_seen;

/* 0 the first time `name` is seen, or -1 with "NAME: given twice" in `err`. */
int tarn_option_once(tarn_options_seen *seen, const char *name, tarn_error *err);

/* A usage error of `tarn COMMAND` as its one line on stderr,
 * "tarn: MESSAGE; try 'tarn COMMAND --help'"; returns TARN_EXIT_BAD_INPUT. */
int tarn_usage_error(const char *command, const tarn_error *err);

/* The words after the command, argv[2..argc): the one not starting with '-' is the
 * scene (*scene), each option goes to `read`. 0, or -1 with `err` set: a second
 * scene, an unknown option, an option given twice or the reader's message. */
int tarn_parse_arguments(int argc, char **argv, const char **scene, tarn_option_reader read, void *options,
                         tarn_error *err);

#endif
