/* test_frame_parts.c: a frame drawn in parts (tarn_render_frame_part), each part in a
 * thread of its own with memory of its own, all at once, is the frame
 * tarn_render_frame draws, byte for byte, with every pixel delivered once: on every
 * scene that two ways of drawing are tested on and the moving ones, at each preset,
 * in tiles and in strips of 16 and 48 rows, for two, three and seven parts (seven
 * is more than 48-row strips make of the frame: some parts draw nothing).
 *
 * So is a frame drawn by a strip pipeline (tarn_strip_pipeline_begin): its two
 * workers in two threads over one memory, each taking steps and waiting only as the
 * header says; in one thread, every opaque pass as early as the order allows, the
 * order that would show a ring too shallow, the workers taking a strip each in
 * turn; and one worker taking every step. */
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "frame_render.h"
#include "scene_load.h"

#define WIDTH 160
#define HEIGHT 120
#define PARTS_MAX 7u

static const char *const moving_scenes[] = {"scenes/pond-orbit.json", "scenes/lake-drift.json"};
static const tarn_preset presets[] = {TARN_PRESET_EXACT, TARN_PRESET_BALANCED, TARN_PRESET_FAST};
static const char *const preset_names[] = {"exact", "balanced", "fast"};
/* Under ThreadSanitizer (make test's third run of this file, whose work is to find
 * races; the other two check the pixels of every way) the frame is drawn only the
 * ways that share memory between threads: three parts share what two and seven do,
 * and a pipeline in one thread races with nothing. The run is then minutes shorter. */
#if defined(__SANITIZE_THREAD__)
#define ONE_THREAD_ORDERS 0
static const uint16_t part_counts[] = {2u, PARTS_MAX};
#else
#define ONE_THREAD_ORDERS 1
static const uint16_t part_counts[] = {2u, 3u, PARTS_MAX};
#endif

/* The frame the parts draw together: its pixels, and how often each was delivered.
 * The parts' tiles do not overlap, so the threads write apart. */
typedef struct {
    uint8_t rgb[3u * WIDTH * HEIGHT];
    uint8_t deliveries[WIDTH * HEIGHT];
} shared_frame;

/* One part, run in its own thread. */
typedef struct {
    const tarn_scene *scene;
    const tarn_frame_config *config;
    tarn_frame_part part;
    shared_frame *frame;
    tarn_status status;
} part_job;

static int keep_tile(void *user, const tarn_tile *tile)
{
    shared_frame *frame = user;
    for (uint16_t y = 0; y < tile->height; y++)
        for (uint16_t x = 0; x < tile->width; x++) {
            const uint32_t rgb = tile->rgb[(size_t)y * tile->stride + x];
            const size_t k = (size_t)(tile->y + y) * WIDTH + (tile->x + x);
            frame->rgb[3u * k] = (uint8_t)(rgb >> 16);
            frame->rgb[3u * k + 1u] = (uint8_t)(rgb >> 8);
            frame->rgb[3u * k + 2u] = (uint8_t)rgb;
            frame->deliveries[k]++;
        }
    return 0;
}

static void *run_part(void *arg)
{
    part_job *job = arg;
    const size_t bytes = tarn_frame_memory_bytes(job->config, job->scene);
    void *memory = malloc(bytes);
    job->status = memory == NULL ? TARN_ERR_MEMORY
                                 : tarn_render_frame_part(job->scene, job->config, memory, bytes, job->part,
                                                          keep_tile, job->frame);
    free(memory);
    return NULL;
}

/* The frame drawn by `parts` threads at once; fails the test if a part fails. */
static void render_in_parts(const tarn_scene *scene, const tarn_frame_config *config, uint16_t parts,
                            shared_frame *frame, const char *what)
{
    memset(frame, 0, sizeof *frame);
    part_job jobs[PARTS_MAX];
    pthread_t threads[PARTS_MAX];
    for (uint16_t p = 0; p < parts; p++) {
        const part_job job = {scene, config, {p, parts}, frame, TARN_OK};
        jobs[p] = job;
        if (pthread_create(&threads[p], NULL, run_part, &jobs[p]) != 0) fail_msg("%s: cannot start a thread", what);
    }
    for (uint16_t p = 0; p < parts; p++) pthread_join(threads[p], NULL);
    for (uint16_t p = 0; p < parts; p++)
        if (jobs[p].status != TARN_OK)
            fail_msg("%s: part %u of %u returned %s", what, (unsigned)p, (unsigned)parts,
                     tarn_status_text(jobs[p].status));
}

/* A strip pipeline's run: its memory, and the steps taken and done, which the
 * workers wait on. */
#define STRIPS_MAX 64
typedef struct {
    void *memory;
    tarn_strip_pipeline pipeline;
    shared_frame *frame;
    pthread_mutex_t lock;
    pthread_cond_t moved;
    /* under lock: the next strip whose opaque pass, and whose water, no worker has
       taken, and each strip's steps done */
    int32_t next_opaque, next_water;
    uint8_t drawn[STRIPS_MAX], sent[STRIPS_MAX];
    tarn_status status; /* the first step that failed */
} pipeline_run;

/* Whether the first `count` flags are set; under lock. */
static int all_set(const uint8_t *flags, int32_t count)
{
    for (int32_t d = 0; d < count; d++)
        if (!flags[d]) return 0;
    return 1;
}

/* The step a worker takes next, as tarn_render.h orders them: the next water strip
 * if the opaque passes it reads are drawn, or else the next opaque strip if the
 * water over its slot is done; *water says which. -1: none now; under lock. */
static int32_t next_step(pipeline_run *r, int *water)
{
    const tarn_strip_pipeline *p = &r->pipeline;
    *water = r->next_water < p->strips && all_set(r->drawn, tarn_strip_pipeline_drawn_before_water(p, r->next_water));
    if (*water) return r->next_water++;
    if (r->next_opaque < p->strips && all_set(r->sent, tarn_strip_pipeline_sent_before_opaque(p, r->next_opaque)))
        return r->next_opaque++;
    return -1;
}

typedef struct {
    pipeline_run *run;
    unsigned worker;
} worker_job;

/* One worker: the steps it takes, until every step is taken or a step fails. */
static void *pipeline_worker(void *arg)
{
    const worker_job *job = arg;
    pipeline_run *r = job->run;
    pthread_mutex_lock(&r->lock);
    while (r->status == TARN_OK && (r->next_water < r->pipeline.strips || r->next_opaque < r->pipeline.strips)) {
        int water;
        const int32_t step = next_step(r, &water);
        if (step < 0) {
            pthread_cond_wait(&r->moved, &r->lock);
            continue;
        }
        pthread_mutex_unlock(&r->lock);
        tarn_status status = TARN_OK;
        if (water)
            status = tarn_strip_pipeline_water(r->memory, job->worker, step, keep_tile, r->frame);
        else
            tarn_strip_pipeline_opaque(r->memory, job->worker, step);
        pthread_mutex_lock(&r->lock);
        (water ? r->sent : r->drawn)[step] = 1u;
        if (status != TARN_OK) r->status = status;
        pthread_cond_broadcast(&r->moved);
    }
    pthread_mutex_unlock(&r->lock);
    return NULL;
}

/* The steps in one thread: every opaque pass as soon as the order allows, so that
 * the ring holds as much below each water strip as it can, each step by worker k
 * modulo 2 (its strip's); or each step by worker 0 just before it is needed. */
static tarn_status run_in_one_thread(pipeline_run *r, int opaque_first)
{
    const tarn_strip_pipeline *p = &r->pipeline;
    int32_t drawn = 0;
    for (int32_t k = 0; k < p->strips; k++) {
        const int32_t last = opaque_first ? p->strips : tarn_strip_pipeline_drawn_before_water(p, k);
        for (; drawn < last && tarn_strip_pipeline_sent_before_opaque(p, drawn) <= k; drawn++)
            tarn_strip_pipeline_opaque(r->memory, opaque_first ? (unsigned)drawn % 2u : 0u, drawn);
        const tarn_status status =
            tarn_strip_pipeline_water(r->memory, opaque_first ? (unsigned)k % 2u : 0u, k, keep_tile, r->frame);
        if (status != TARN_OK) return status;
    }
    return TARN_OK;
}

/* How a test runs the pipeline's workers. */
typedef enum { IN_TWO_THREADS, OPAQUE_FIRST, ONE_WORKER } pipeline_schedule;

/* The frame drawn by a strip pipeline; fails the test if the pipeline fails. */
static void render_in_pipeline(const tarn_scene *scene, const tarn_frame_config *config, pipeline_schedule how,
                               shared_frame *frame, const char *what)
{
    memset(frame, 0, sizeof *frame);
    const size_t bytes = tarn_strip_pipeline_memory_bytes(config, scene);
    pipeline_run r = {malloc(bytes), {0, 0}, frame, PTHREAD_MUTEX_INITIALIZER, PTHREAD_COND_INITIALIZER, 0, 0, {0}, {0},
                      TARN_OK};
    assert_non_null(r.memory);
    r.status = tarn_strip_pipeline_begin(scene, config, r.memory, bytes, &r.pipeline);
    if (r.pipeline.strips > STRIPS_MAX) fail_msg("%s: %d strips, more than the test's %d", what, r.pipeline.strips, STRIPS_MAX);
    if (r.status == TARN_OK && r.pipeline.strips == 0) /* not in strips: the frame as it is */
        r.status = tarn_render_frame(scene, config, r.memory, bytes, keep_tile, frame);
    else if (r.status == TARN_OK && how != IN_TWO_THREADS)
        r.status = run_in_one_thread(&r, how == OPAQUE_FIRST);
    else if (r.status == TARN_OK) {
        worker_job jobs[TARN_STRIP_PIPELINE_WORKERS];
        pthread_t threads[TARN_STRIP_PIPELINE_WORKERS];
        for (unsigned w = 0; w < TARN_STRIP_PIPELINE_WORKERS; w++) {
            jobs[w].run = &r;
            jobs[w].worker = w;
            if (pthread_create(&threads[w], NULL, pipeline_worker, &jobs[w]) != 0)
                fail_msg("%s: cannot start a thread", what);
        }
        for (unsigned w = 0; w < TARN_STRIP_PIPELINE_WORKERS; w++) pthread_join(threads[w], NULL);
    }
    free(r.memory);
    if (r.status != TARN_OK) fail_msg("%s: the strip pipeline returned %s", what, tarn_status_text(r.status));
}

/* Every pixel of `frame` delivered once, and the pixels `whole`'s. */
static void assert_frame_is(const uint8_t *whole, const shared_frame *frame, const char *what, const char *how)
{
    for (size_t k = 0; k < (size_t)WIDTH * HEIGHT; k++)
        if (frame->deliveries[k] != 1u)
            fail_msg("%s %s: pixel (%zu, %zu) delivered %u times", what, how, k % WIDTH, k / WIDTH,
                     (unsigned)frame->deliveries[k]);
    for (size_t k = 0; k < (size_t)WIDTH * HEIGHT; k++)
        if (memcmp(whole + 3u * k, frame->rgb + 3u * k, 3u) != 0)
            fail_msg("%s %s: pixel (%zu, %zu) is #%02x%02x%02x, drawn whole #%02x%02x%02x", what, how, k % WIDTH,
                     k / WIDTH, frame->rgb[3u * k], frame->rgb[3u * k + 1u], frame->rgb[3u * k + 2u], whole[3u * k],
                     whole[3u * k + 1u], whole[3u * k + 2u]);
}

static void assert_parts_draw_the_frame(const tarn_scene *scene, const tarn_frame_config *config, const char *what)
{
    uint8_t *whole = test_render_rgb(scene, config, what);
    shared_frame *frame = malloc(sizeof *frame);
    assert_non_null(frame);
    for (size_t n = 0; n < sizeof part_counts / sizeof part_counts[0]; n++) {
        render_in_parts(scene, config, part_counts[n], frame, what);
        char how[48];
        snprintf(how, sizeof how, "in %u parts", (unsigned)part_counts[n]);
        assert_frame_is(whole, frame, what, how);
    }
    if (config->quality.frame_shape == TARN_FRAME_STRIPS) {
        render_in_pipeline(scene, config, IN_TWO_THREADS, frame, what);
        assert_frame_is(whole, frame, what, "in a strip pipeline of two threads");
    }
    if (ONE_THREAD_ORDERS && config->quality.frame_shape == TARN_FRAME_STRIPS) {
        render_in_pipeline(scene, config, OPAQUE_FIRST, frame, what);
        assert_frame_is(whole, frame, what, "in a strip pipeline, its opaque strips drawn first");
        render_in_pipeline(scene, config, ONE_WORKER, frame, what);
        assert_frame_is(whole, frame, what, "in a strip pipeline, one worker taking every step");
    }
    free(frame);
    free(whole);
}

static void assert_scene_in_parts(const char *path)
{
    tarn_loaded_scene *loaded = malloc(sizeof *loaded);
    assert_non_null(loaded);
    tarn_error err;
    if (tarn_scene_load(path, loaded, &err) != 0) fail_msg("%s", err.message);
    for (size_t p = 0; p < sizeof presets / sizeof presets[0]; p++) {
        tarn_frame_config config = {WIDTH, HEIGHT, tarn_quality_preset(presets[p]), 1234u};
        char what[160];
        snprintf(what, sizeof what, "%s (%s, tiles)", path, preset_names[p]);
        assert_parts_draw_the_frame(&loaded->scene, &config, what);
        static const uint8_t rows[] = {16, 48};
        config.quality.frame_shape = TARN_FRAME_STRIPS;
        for (size_t r = 0; r < sizeof rows; r++) {
            config.quality.tile_size = rows[r];
            snprintf(what, sizeof what, "%s (%s, strips of %u rows)", path, preset_names[p], (unsigned)rows[r]);
            assert_parts_draw_the_frame(&loaded->scene, &config, what);
        }
    }
    tarn_scene_free(loaded);
    free(loaded);
}

static void test_parts_draw_the_frame_together(void **state)
{
    (void)state;
    for (size_t i = 0; i < TEST_FRAME_SCENE_COUNT; i++) assert_scene_in_parts(test_frame_scenes[i]);
    for (size_t i = 0; i < sizeof moving_scenes / sizeof moving_scenes[0]; i++) assert_scene_in_parts(moving_scenes[i]);
}

/* No part 0 of 0, and no part past the last. */
static void test_a_part_outside_the_parts_is_refused(void **state)
{
    (void)state;
    tarn_loaded_scene loaded;
    tarn_error err;
    if (tarn_scene_load("scenes/pond.json", &loaded, &err) != 0) fail_msg("%s", err.message);
    const tarn_frame_config config = {WIDTH, HEIGHT, tarn_quality_default(), 0u};
    const size_t bytes = tarn_frame_memory_bytes(&config, &loaded.scene);
    void *memory = malloc(bytes);
    assert_non_null(memory);
    const tarn_frame_part none = {0u, 0u}, past = {2u, 2u}, second = {1u, 2u};
    assert_int_equal(tarn_render_frame_part(&loaded.scene, &config, memory, bytes, none, NULL, NULL), TARN_ERR_CONFIG);
    assert_int_equal(tarn_render_frame_part(&loaded.scene, &config, memory, bytes, past, NULL, NULL), TARN_ERR_CONFIG);
    assert_int_equal(tarn_render_frame_part(&loaded.scene, &config, memory, bytes, second, NULL, NULL), TARN_OK);
    free(memory);
    tarn_scene_free(&loaded);
}

/* A pipeline takes the frame's memory, a strip of ring and a second worker's water
 * buffers more; a frame in tiles, too little memory, or a worker or strip past the
 * last is refused. */
static void test_a_strip_pipeline_takes_one_strip_more(void **state)
{
    (void)state;
    tarn_loaded_scene loaded;
    tarn_error err;
    if (tarn_scene_load("scenes/pond.json", &loaded, &err) != 0) fail_msg("%s", err.message);
    tarn_frame_config config = {WIDTH, HEIGHT, tarn_quality_default(), 0u};
    config.quality.frame_shape = TARN_FRAME_STRIPS;
    config.quality.tile_size = 16;
    const size_t bytes = tarn_strip_pipeline_memory_bytes(&config, &loaded.scene);
    const size_t strip = (size_t)WIDTH * 16u * (4u + config.quality.depth_bits / 8u);
    const size_t frame = tarn_frame_memory_bytes(&config, &loaded.scene);
    if (bytes < frame + 2u * strip || bytes > frame + 2u * strip + 8192u)
        fail_msg("a strip pipeline takes %zu bytes, the frame %zu and a strip %zu", bytes, frame, strip);
    void *memory = malloc(bytes);
    assert_non_null(memory);
    tarn_strip_pipeline p;
    assert_int_equal(tarn_strip_pipeline_begin(&loaded.scene, &config, memory, bytes - 1u, &p), TARN_ERR_MEMORY);
    assert_int_equal(tarn_strip_pipeline_begin(&loaded.scene, &config, memory, bytes, &p), TARN_OK);
    assert_int_equal(p.strips, (HEIGHT + 15) / 16);
    assert_int_equal(tarn_strip_pipeline_water(memory, 0, p.strips, NULL, NULL), TARN_ERR_CONFIG);
    assert_int_equal(tarn_strip_pipeline_water(memory, 1, -1, NULL, NULL), TARN_ERR_CONFIG);
    assert_int_equal(tarn_strip_pipeline_water(memory, TARN_STRIP_PIPELINE_WORKERS, 0, NULL, NULL), TARN_ERR_CONFIG);
    config.quality.frame_shape = TARN_FRAME_TILES;
    assert_int_equal(tarn_strip_pipeline_begin(&loaded.scene, &config, memory, bytes, &p), TARN_ERR_CONFIG);
    assert_int_equal(p.strips, 0);
    free(memory);
    tarn_scene_free(&loaded);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parts_draw_the_frame_together),
        cmocka_unit_test(test_a_part_outside_the_parts_is_refused),
        cmocka_unit_test(test_a_strip_pipeline_takes_one_strip_more),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
