/* tarn: render scenes to PNG, measure the integer core against the float reference,
 * sweep the quality knobs, bake scenes into C for firmware, drive a panel. */
#include <stdio.h>

#include <string.h>

#include "cli_help.h"
#include "cli_options.h"
#include "commands.h"
#include "option_values.h"
#include "show.h"
#include "sweep.h"
#include "view.h"

/* tarn, tarn --help, tarn -h, tarn help [COMMAND], tarn COMMAND --help: exit 0.
 * -1 when the line asks for no help. */
static int help(int argc, char **argv)
{
    const char *word = argc >= 2 ? argv[1] : NULL;
    if (word != NULL && strcmp(word, "--version") == 0 && argc == 2) {
        tarn_cli_print_version(stdout);
        return 0;
    }
    int overview = word != NULL && (strcmp(word, "--help") == 0 || strcmp(word, "-h") == 0);
    if (overview && argc == 2) return tarn_cli_print_help(NULL, stdout) == 0 ? 0 : 1;
    if (word != NULL && strcmp(word, "help") == 0) {
        tarn_error err;
        if (argc > 3) tarn_fail(&err, "help: unexpected argument '%s'", argv[3]);
        else if (tarn_cli_print_help(argc == 3 ? argv[2] : NULL, stdout) == 0) return 0;
        else tarn_fail(&err, "help: no command '%s'", argv[2]);
        return tarn_usage_error(NULL, &err);
    }
    if (word != NULL && word[0] != '-' && tarn_cli_wants_help(argc, argv) &&
        tarn_cli_print_help(word, stdout) == 0)
        return 0;
    return -1;
}

int main(int argc, char **argv)
{
    tarn_cli_options options;
    tarn_error err;
    int helped = help(argc, argv);
    if (helped >= 0) return helped;
    if (argc >= 2 && strcmp(argv[1], "show") == 0) return tarn_command_show(argc, argv);
    if (argc >= 2 && strcmp(argv[1], "sweep") == 0) return tarn_command_sweep(argc, argv);
    if (argc >= 2 && strcmp(argv[1], "view") == 0) return tarn_command_view(argc, argv);
    if (argc >= 2 && strcmp(argv[1], "sweep-cost-worker") == 0) return tarn_command_sweep_cost_worker(argc, argv);
    if (tarn_cli_parse(argc, argv, &options, &err) != 0)
        return tarn_usage_error(tarn_cli_known_command(argc, argv), &err);
    switch (options.command) {
    case TARN_CMD_RENDER: return tarn_command_render(&options);
    case TARN_CMD_COMPARE: return tarn_command_compare(&options);
    case TARN_CMD_ACCURACY: return tarn_command_accuracy(&options);
    case TARN_CMD_MEMORY: return tarn_command_memory(&options);
    case TARN_CMD_BAKE: return tarn_command_bake(&options);
    }
    return TARN_EXIT_BAD_INPUT;
}
