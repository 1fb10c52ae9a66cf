/* cli_help.h: what `tarn --help`, `tarn COMMAND --help` and `tarn --version` print
 * (on stdout, exit 0). Every command's own usage lives here but show's and sweep's,
 * which live beside their parsers (show_options.h, sweep.h). */
#ifndef TARN_HOST_CLI_HELP_H
#define TARN_HOST_CLI_HELP_H

#include <stdio.h>

/* Whether the words after the command ask for its help: --help or -h. */
int tarn_cli_wants_help(int argc, char **argv);

/* The tool's overview (command NULL), or one command's usage; -1 for a word that
 * names no command. */
int tarn_cli_print_help(const char *command, FILE *out);

/* The version, the core's link switches as this build has them, and the display
 * backends it found. */
void tarn_cli_print_version(FILE *out);

#endif
