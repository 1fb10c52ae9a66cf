/* tarn: render scenes to PNG, measure the integer core against the float reference,
 * sweep the quality knobs, bake scenes into C for firmware, drive a panel. */
#include <stdio.h>

#include <string.h>

#include "cli_options.h"
#include "commands.h"
#include "show.h"
#include "sweep.h"

int main(int argc, char **argv)
{
    tarn_cli_options options;
    tarn_error err;
    if (argc >= 2 && strcmp(argv[1], "show") == 0) return tarn_command_show(argc, argv);
    if (argc >= 2 && strcmp(argv[1], "sweep") == 0) return tarn_command_sweep(argc, argv);
    if (argc >= 2 && strcmp(argv[1], "sweep-cost-worker") == 0) return tarn_command_sweep_cost_worker(argc, argv);
    if (tarn_cli_parse(argc, argv, &options, &err) != 0) {
        fprintf(stderr, "tarn: %s\n%s", err.message, tarn_cli_usage);
        return TARN_EXIT_BAD_INPUT;
    }
    switch (options.command) {
    case TARN_CMD_RENDER: return tarn_command_render(&options);
    case TARN_CMD_COMPARE: return tarn_command_compare(&options);
    case TARN_CMD_ACCURACY: return tarn_command_accuracy(&options);
    case TARN_CMD_MEMORY: return tarn_command_memory(&options);
    case TARN_CMD_BAKE: return tarn_command_bake(&options);
    }
    return TARN_EXIT_BAD_INPUT;
}
