/* view_script.c: tarn view's scripts (view_script.h). */
#include "view_script.h"

#include <stdlib.h>
#include <string.h>

#include "input_file.h"
#include "option_values.h"
#include "view_state.h"

/* A drag or wheel larger than any window: a typo, not a gesture. */
#define SCRIPT_MOVE_MAX 10000L

static const char *const kinds[] = {"key", "drag", "wheel", "screenshot", "wait-edit", "quit"};

/* A whole number, negative allowed, within SCRIPT_MOVE_MAX. */
static int read_move(const char *word, int *out)
{
    unsigned long magnitude;
    const int negative = word != NULL && word[0] == '-';
    if (word == NULL || tarn_parse_whole(word + negative, 0, SCRIPT_MOVE_MAX, &magnitude) != 0) return -1;
    *out = negative ? -(int)magnitude : (int)magnitude;
    return 0;
}

/* The words after the event's kind. */
static int read_arguments(tarn_script_event *e, char *rest, const char **expected)
{
    const char *first = strtok(rest, " \t"), *second = first ? strtok(NULL, " \t") : NULL;
    const char *extra = second ? strtok(NULL, " \t") : NULL;
    switch (e->kind) {
    case TARN_SCRIPT_KEY:
        *expected = "a key SDL names, one of tarn view's (tarn view --help)";
        if (first == NULL || second != NULL || tarn_view_find_key(first) == NULL) return -1;
        snprintf(e->key, sizeof e->key, "%s", first);
        return 0;
    case TARN_SCRIPT_DRAG:
        *expected = "drag DX DY, whole window pixels -10000..10000";
        return extra == NULL && read_move(first, &e->dx) == 0 && read_move(second, &e->dy) == 0 ? 0 : -1;
    case TARN_SCRIPT_WHEEL:
        *expected = "wheel STEPS, a whole number -10000..10000";
        return second == NULL && read_move(first, &e->dy) == 0 ? 0 : -1;
    default:
        *expected = "nothing after the event";
        return first == NULL ? 0 : -1;
    }
}

/* One line's event (`line` without its comment, not blank). */
static int read_event(char *line, uint32_t last_frame, tarn_script_event *e, const char **expected)
{
    unsigned long frame;
    const char *frame_word = strtok(line, " \t"), *kind = strtok(NULL, " \t");
    char *rest = kind ? strtok(NULL, "") : NULL;
    int k;
    memset(e, 0, sizeof *e);
    *expected = "a frame number 0..999999 no smaller than the line before's";
    if (tarn_parse_whole(frame_word, last_frame, TARN_SCRIPT_FRAME_MAX, &frame) != 0) return -1;
    e->frame = (uint32_t)frame;
    *expected = "an event: key, drag, wheel, screenshot, wait-edit or quit";
    for (k = 0; k < (int)(sizeof kinds / sizeof kinds[0]); k++)
        if (kind != NULL && strcmp(kind, kinds[k]) == 0) break;
    if (k == (int)(sizeof kinds / sizeof kinds[0])) return -1;
    e->kind = (tarn_script_event_kind)k;
    return read_arguments(e, rest ? rest : (char[]){""}, expected);
}

static int read_lines(FILE *f, const char *path, tarn_script *out, tarn_error *err)
{
    char line[256];
    uint32_t last_frame = 0;
    for (unsigned number = 1; fgets(line, sizeof line, f) != NULL; number++) {
        if (strchr(line, '\n') == NULL && !feof(f))
            return tarn_fail(err, "%s:%u: a line longer than %zu characters", path, number, sizeof line - 2);
        line[strcspn(line, "#\r\n")] = '\0';
        if (line[strspn(line, " \t")] == '\0') continue;
        if (out->count == TARN_SCRIPT_EVENTS_MAX)
            return tarn_fail(err, "%s:%u: more than %u events", path, number, TARN_SCRIPT_EVENTS_MAX);
        const char *expected;
        if (read_event(line, last_frame, &out->events[out->count], &expected) != 0)
            return tarn_fail(err, "%s:%u: expected %s", path, number, expected);
        last_frame = out->events[out->count++].frame;
    }
    return ferror(f) ? tarn_fail(err, "%s: cannot read", path) : 0;
}

int tarn_script_load(const char *path, tarn_script *out, tarn_error *err)
{
    memset(out, 0, sizeof *out);
    FILE *f = tarn_open_input(path, "a script", TARN_SCRIPT_FILE_BYTES_MAX, err);
    if (f == NULL) return -1;
    out->events = malloc(TARN_SCRIPT_EVENTS_MAX * sizeof *out->events);
    int failed = out->events == NULL ? tarn_fail(err, "%s: out of memory", path) : read_lines(f, path, out, err);
    fclose(f);
    if (failed) tarn_script_free(out);
    return failed ? -1 : 0;
}

void tarn_script_free(tarn_script *script)
{
    free(script->events);
    memset(script, 0, sizeof *script);
}

const tarn_script_event *tarn_script_take(tarn_script *script, uint32_t frame)
{
    if (script->next == script->count || script->events[script->next].frame > frame) return NULL;
    return &script->events[script->next++];
}

int tarn_script_done(const tarn_script *script)
{
    return script->next == script->count;
}
