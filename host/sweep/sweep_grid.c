#include "sweep_grid.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "quality_options.h"
#include "quality_text.h"

#define VALUES_MAX 16

/* A knob: every value the sweep tries, and those the full grid crosses. */
typedef struct {
    const char *option;
    const char *values[VALUES_MAX]; /* NULL-terminated */
    const char *full[VALUES_MAX];   /* crossed in the full grid; none: balanced only */
    const char *quick[VALUES_MAX];  /* crossed in the quick grid */
    const char *quick_alone[VALUES_MAX]; /* one at a time in the quick grid */
} sweep_knob;

static const sweep_knob knobs[] = {
    {"--perspective", {"affine", "span:2", "span:4", "span:8", "span:16", "span:32", "span:64", "pixel"},
     {"affine", "span:16", "span:4", "pixel"}, {"affine", "pixel"}, {NULL}},
    {"--recip-steps", {"0", "1", "2"}, {"1", "2"}, {NULL}, {NULL}},
    {"--depth", {"16", "32"}, {"16", "32"}, {"16", "32"}, {NULL}},
    {"--apron", {"off", "4", "8", "16", "on"}, {"off", "8", "on"}, {NULL}, {NULL}},
    {"--exp2", {"8:nearest", "16:nearest", "32:nearest", "64:nearest", "128:nearest", "256:nearest",
                "8:linear", "16:linear", "32:linear", "64:linear", "128:linear", "256:linear"},
     {"16:nearest", "64:linear"}, {NULL}, {"8:linear", "32:linear", "256:linear"}},
    {"--fog-bits", {"4", "6", "8", "12", "16"}, {"6", "16"}, {NULL}, {NULL}},
    {"--subpixel", {"1", "2", "3", "4", "5", "6", "7", "8"}, {NULL}, {NULL}, {NULL}},
    {"--tile", {"16", "32", "64"}, {NULL}, {NULL}, {NULL}},
    {"--bins", {"on", "off"}, {NULL}, {NULL}, {NULL}},
    {"--water-block", {"1", "2"}, {NULL}, {NULL}, {NULL}},
    {"--depth-interpolation", {"exact", "plane"}, {NULL}, {NULL}, {NULL}},
    {"--refraction-normal", {"shared", "exact"}, {NULL}, {NULL}, {NULL}},
    {"--lit", {"planes", "line"}, {NULL}, {NULL}, {NULL}},
};

#define KNOB_COUNT (sizeof knobs / sizeof knobs[0])

static size_t value_count(const char *const values[VALUES_MAX])
{
    size_t n = 0;
    while (n < VALUES_MAX && values[n] != NULL) n++;
    return n;
}

/* The table's own values, so a failure is a bug in it: say which. */
static tarn_quality with_option(tarn_quality q, const char *option, const char *value)
{
    tarn_error err;
    if (tarn_cli_parse_quality_option(option, value, &q, &err) != 0) {
        fprintf(stderr, "tarn: sweep grid: %s %s: %s\n", option, value, err.message);
        q.tile_size = 0; /* invalid: tarn__config_check refuses it */
    }
    return q;
}

static int already_listed(const tarn_sweep_point *points, size_t count, const tarn_quality *q)
{
    char text[TARN_SWEEP_OPTIONS_MAX], other[TARN_SWEEP_OPTIONS_MAX];
    tarn_quality_text(q, text, sizeof text);
    for (size_t i = 0; i < count; i++) {
        tarn_quality_text(&points[i].quality, other, sizeof other);
        if (strcmp(text, other) == 0) return 1;
    }
    return 0;
}

static size_t add_point(tarn_sweep_point *points, size_t count, size_t max, const tarn_quality *q,
                        const char *preset)
{
    if (count >= max || already_listed(points, count, q)) return count;
    tarn_sweep_point *p = &points[count];
    memset(p, 0, sizeof *p);
    p->quality = *q;
    p->preset = preset;
    for (size_t s = 0; s < TARN_SWEEP_SOURCES_MAX; s++) p->cost[s] = p->convert[s][0] = p->convert[s][1] = -1.0;
    return count + 1;
}

static size_t add_tile_variant(tarn_sweep_point *points, size_t count, size_t max, const tarn_quality *q)
{
    const size_t added = add_point(points, count, max, q, NULL);
    if (added > count) points[count].host_tile_only = 1;
    return added;
}

static const char *const *crossed_values(const sweep_knob *k, tarn_sweep_grid grid)
{
    return grid == TARN_SWEEP_GRID_FULL ? k->full : k->quick;
}

/* Every combination of the crossed values, by counting through them like an
 * odometer: digit k indexes knob k's values. */
static size_t add_product(tarn_sweep_grid grid, tarn_sweep_point *points, size_t count, size_t max)
{
    size_t digit[KNOB_COUNT] = {0};
    for (;;) {
        tarn_quality q = tarn_quality_default();
        for (size_t k = 0; k < KNOB_COUNT; k++) {
            const char *const *values = crossed_values(&knobs[k], grid);
            if (value_count(values) > 0) q = with_option(q, knobs[k].option, values[digit[k]]);
        }
        count = add_point(points, count, max, &q, NULL);
        size_t k = 0;
        for (; k < KNOB_COUNT; k++) {
            size_t n = value_count(crossed_values(&knobs[k], grid));
            if (n > 0 && ++digit[k] < n) break;
            digit[k] = 0;
        }
        if (k == KNOB_COUNT) return count;
    }
}

static size_t add_alone(tarn_sweep_grid grid, tarn_sweep_point *points, size_t count, size_t max)
{
    for (size_t k = 0; k < KNOB_COUNT; k++) {
        const char *const *values = grid == TARN_SWEEP_GRID_FULL ? knobs[k].values : knobs[k].quick_alone;
        for (size_t v = 0; v < value_count(values); v++) {
            const tarn_quality q = with_option(tarn_quality_default(), knobs[k].option, values[v]);
            count = strcmp(knobs[k].option, "--tile") == 0 ? add_tile_variant(points, count, max, &q)
                                                           : add_point(points, count, max, &q, NULL);
        }
    }
    return count;
}

size_t tarn_sweep_grid_points(tarn_sweep_grid grid, tarn_sweep_point *points, size_t max)
{
    size_t count = 0;
    for (int p = 0; p < TARN_PRESET_COUNT; p++) {
        const tarn_quality q = tarn_quality_preset((tarn_preset)p);
        count = add_point(points, count, max, &q, tarn_preset_name((tarn_preset)p));
    }
    if (grid == TARN_SWEEP_GRID_PRESETS) return count;
    count = add_product(grid, points, count, max);
    return add_alone(grid, points, count, max);
}

size_t tarn_sweep_variants(tarn_sweep_variant *variants, size_t max)
{
    size_t count = 0;
    for (size_t k = 0; k < KNOB_COUNT; k++) {
        for (size_t v = 0; v < value_count(knobs[k].values) && count < max; v++) {
            variants[count].option = knobs[k].option;
            variants[count].value = knobs[k].values[v];
            variants[count].quality = with_option(tarn_quality_default(), knobs[k].option, knobs[k].values[v]);
            count++;
        }
    }
    return count;
}

int tarn_sweep_write_points(const char *path, const tarn_quality *qualities, size_t count, tarn_error *err)
{
    FILE *f = fopen(path, "w");
    if (f == NULL) return tarn_fail(err, "%s: cannot write: %s", path, strerror(errno));
    for (size_t i = 0; i < count; i++) {
        char text[TARN_SWEEP_OPTIONS_MAX];
        tarn_quality_text(&qualities[i], text, sizeof text);
        fprintf(f, "%s\n", text);
    }
    const int failed = ferror(f);
    return fclose(f) == 0 && !failed ? 0 : tarn_fail(err, "%s: cannot write: %s", path, strerror(errno));
}
