/* option_values.h: the values of command-line options, read the same way by every
 * command's parser (cli_options.c, show_options.c, quality_options.c). */
#ifndef TARN_HOST_OPTION_VALUES_H
#define TARN_HOST_OPTION_VALUES_H

/* The animation clock of render --frames and of show: frames per second. */
#define TARN_CLI_FPS_MAX 120u
#define TARN_CLI_FPS_DEFAULT 30u

/* A whole decimal number in [min, max], nothing else in the text (NULL is none):
 * 0 with *out set, or -1. */
int tarn_parse_whole(const char *text, unsigned long min, unsigned long max, unsigned long *out);

#endif
