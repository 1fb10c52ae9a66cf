/* commands.h: the `tarn` subcommands. Each returns the process exit status:
 * 0 on success, TARN_EXIT_BAD_INPUT (2) for bad input with one "tarn: ..." line on
 * stderr, and no output file left behind on any failure. */
#ifndef TARN_HOST_COMMANDS_H
#define TARN_HOST_COMMANDS_H

#include "cli_options.h"

int tarn_command_render(const tarn_cli_options *options);
int tarn_command_compare(const tarn_cli_options *options);
int tarn_command_accuracy(const tarn_cli_options *options);
/* Prints the renderer's working memory for the scene at this size and quality:
 *   memory scene=NAME size=WxH tile=N depth_bits=N apron=N bytes=N */
int tarn_command_memory(const tarn_cli_options *options);
/* Writes the scene as const C data (host/bake/bake.h) and prints
 *   bake scene=NAME const_bytes=N memory_bytes=N */
int tarn_command_bake(const tarn_cli_options *options);

#endif
