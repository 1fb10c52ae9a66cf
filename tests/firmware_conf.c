#include "firmware_conf.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "cli_options.h"

#define FLAGS_MAX 32

char *firmware_read_file(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) return NULL;
    size_t capacity = 4096, n = 0;
    char *bytes = malloc(capacity + 1);
    for (size_t got; bytes != NULL && (got = fread(bytes + n, 1, capacity - n, f)) > 0;) {
        n += got;
        if (n == capacity) {
            char *grown = realloc(bytes, 2 * capacity + 1);
            if (grown == NULL) free(bytes);
            bytes = grown;
            capacity *= 2;
        }
    }
    fclose(f);
    if (bytes != NULL) bytes[n] = '\0';
    if (size != NULL) *size = n;
    return bytes;
}

void firmware_conf_value(char *out, size_t size, const char *text, const char *key)
{
    size_t key_length = strlen(key);
    out[0] = '\0';
    for (const char *line = text; line != NULL && *line != '\0';) {
        const char *end = strchr(line, '\n');
        size_t length = end ? (size_t)(end - line) : strlen(line);
        if (length > key_length && strncmp(line, key, key_length) == 0 && line[key_length] == '=') {
            size_t n = length - key_length - 1;
            if (n >= size) n = size - 1;
            memcpy(out, line + key_length + 1, n);
            out[n] = '\0';
            return;
        }
        line = end ? end + 1 : NULL;
    }
}

tarn_frame_config firmware_bake_config(const char *scene_path, const char *bake_flags,
                                       const tarn_loaded_scene *scene, uint32_t time_ms,
                                       tarn_backdrop_request *backdrop)
{
    char flags[512];
    /* parsed as the bake's command line, which is what they were; nothing is written */
    char *argv[FLAGS_MAX + 5] = {"tarn", "bake", (char *)scene_path, "-o", "parsed-only.c"};
    int argc = 5;
    snprintf(flags, sizeof flags, "%s", bake_flags);
    for (char *word = strtok(flags, " "); word != NULL; word = strtok(NULL, " ")) {
        if (argc == FLAGS_MAX + 5) fail_msg("too many bake flags: %s", bake_flags);
        argv[argc++] = word;
    }
    tarn_cli_options options;
    tarn_error err;
    if (tarn_cli_parse(argc, argv, &options, &err) != 0) fail_msg("bake flags '%s': %s", bake_flags, err.message);
    tarn_frame_config config = {options.width ? options.width : scene->width,
                                options.height ? options.height : scene->height, options.quality, time_ms};
    if (backdrop != NULL) *backdrop = tarn_cli_backdrop(&options);
    return config;
}

void firmware_sort_board_names(char names[][64], size_t n)
{
    for (size_t i = 1; i < n; i++)
        for (size_t j = i; j > 0 && strcmp(names[j - 1], names[j]) > 0; j--) {
            char t[64];
            memcpy(t, names[j], 64);
            memcpy(names[j], names[j - 1], 64);
            memcpy(names[j - 1], t, 64);
        }
}
