/* bake_points.c: the points file of `tarn bake --points` (bake_points.h). */
#include "bake_points.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input_file.h"
#include "quality_options.h"

void tarn_bake_points_free(tarn_bake_points *points)
{
    free(points->qualities);
    free(points->lines);
    points->qualities = NULL;
    points->lines = NULL;
    points->count = 0;
}

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

/* The next word of `*cursor`, NUL-terminated in place, or NULL at the end. */
static char *next_word(char **cursor)
{
    char *c = *cursor;
    while (*c != '\0' && is_space(*c)) c++;
    if (*c == '\0') return NULL;
    char *word = c;
    while (*c != '\0' && !is_space(*c)) c++;
    if (*c != '\0') *c++ = '\0';
    *cursor = c;
    return word;
}

#define LINE_WORDS_MAX 64u

/* One line's options applied to `q`: its --quality preset, if any, as the base
 * (as on the command line), then every knob in order. 1 when the line holds no
 * point, 0 when it does, -1 with `err` set. */
static int parse_line(const char *path, unsigned line_number, char *line, tarn_quality *q, tarn_error *err)
{
    char *words[LINE_WORDS_MAX], *cursor = line;
    int count = 0;
    for (char *word; (word = next_word(&cursor)) != NULL && word[0] != '#';) {
        if ((unsigned)count == LINE_WORDS_MAX)
            return tarn_fail(err, "%s:%u: more than %u words", path, line_number, LINE_WORDS_MAX);
        words[count++] = word;
    }
    if (count == 0) return 1;
    tarn_error option_err;
    if (tarn_cli_apply_preset(count, words, q, &option_err) != 0)
        return tarn_fail(err, "%s:%u: %s", path, line_number, option_err.message);
    for (int i = 0; i < count; i += 2) {
        if (strncmp(words[i], "--", 2) != 0)
            return tarn_fail(err, "%s:%u: expected a quality option such as --tile, got '%s'", path,
                             line_number, words[i]);
        int result = tarn_cli_parse_quality_option(words[i], i + 1 < count ? words[i + 1] : NULL, q, &option_err);
        if (result > 0) return tarn_fail(err, "%s:%u: unknown quality option '%s'", path, line_number, words[i]);
        if (result < 0) return tarn_fail(err, "%s:%u: %s", path, line_number, option_err.message);
    }
    if (tarn_cli_check_quality(q, &option_err) != 0)
        return tarn_fail(err, "%s:%u: %s", path, line_number, option_err.message);
    return 0;
}

static int add_point(tarn_bake_points *points, const tarn_quality *q, unsigned line_number, size_t *capacity)
{
    if (points->count == *capacity) {
        size_t larger = *capacity ? 2 * *capacity : 16;
        tarn_quality *qualities = realloc(points->qualities, larger * sizeof *qualities);
        if (qualities == NULL) return -1;
        points->qualities = qualities;
        unsigned *lines = realloc(points->lines, larger * sizeof *lines);
        if (lines == NULL) return -1;
        points->lines = lines;
        *capacity = larger;
    }
    points->qualities[points->count] = *q;
    points->lines[points->count++] = line_number;
    return 0;
}

int tarn_bake_points_load(const char *path, const tarn_quality *base, tarn_bake_points *points,
                          tarn_error *err)
{
    memset(points, 0, sizeof *points);
    points->path = path;
    FILE *f = tarn_open_input(path, "a points file", TARN_BAKE_POINTS_FILE_BYTES_MAX, err);
    if (f == NULL) return -1;
    char *line = NULL;
    size_t line_capacity = 0, capacity = 0;
    unsigned line_number = 0;
    int failed = 0;
    while (!failed && getline(&line, &line_capacity, f) >= 0) {
        line_number++;
        tarn_quality q = *base;
        int result = parse_line(path, line_number, line, &q, err);
        if (result < 0) failed = 1;
        else if (result == 0 && points->count == TARN_BAKE_POINTS_MAX)
            failed = tarn_fail(err, "%s:%u: more than %u points", path, line_number, TARN_BAKE_POINTS_MAX) != 0;
        else if (result == 0 && add_point(points, &q, line_number, &capacity) != 0)
            failed = tarn_fail(err, "%s:%u: out of memory", path, line_number) != 0;
    }
    if (!failed && ferror(f)) failed = tarn_fail(err, "%s: cannot read it", path) != 0;
    if (!failed && points->count == 0)
        failed = tarn_fail(err, "%s: no points (one line of quality options per point; blank lines and "
                           "# comments are skipped)", path) != 0;
    free(line);
    fclose(f);
    if (failed) tarn_bake_points_free(points);
    return failed ? -1 : 0;
}

int tarn_bake_points_check(const tarn_bake_points *points, const tarn_frame_config *config,
                           const tarn_scene *scene, size_t *memory_bytes, tarn_error *err)
{
    for (size_t i = 0; i < points->count; i++) {
        tarn_frame_config point = *config;
        point.quality = points->qualities[i];
        size_t bytes = tarn_frame_memory_bytes(&point, scene);
        if (bytes == 0)
            return tarn_fail(err, "%s:%u: %ux%u with these quality settings: %s", points->path, points->lines[i],
                             point.width, point.height, tarn_status_text(TARN_ERR_CONFIG));
        if (bytes > *memory_bytes) *memory_bytes = bytes;
    }
    return 0;
}
