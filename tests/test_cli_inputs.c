/* test_cli_inputs.c: `tarn render` and `tarn bake` on inputs that are not files to
 * read: FIFOs, devices, a pipe that never delivers, in place of a scene, a mesh, a
 * texture, a heightfield or a points file; and on scenes over the limits of
 * host/scene/scene_budget.h, which must be refused at once, naming the part that
 * crosses one.
 *
 * Each runs the real binary ($TARN_BIN, set by `make check`) and must end with exit
 * status 2, exactly one stderr line "tarn: FILE: ..." naming the file and what was
 * expected, and nothing left beside the inputs. A run still going after
 * RUN_SECONDS_MAX is killed and reported as hung, so that a regression fails the
 * test instead of stopping it. FIFOs are made with mkfifo in a fresh directory;
 * nothing here writes to /dev. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "bad_scene_cases.h"
#include "cli_run.h"
#include "mesh_gen.h"
#include "scene_budget.h"

/* Far longer than any refusal takes; a run past it is hung. */
#define RUN_SECONDS_MAX 20

/* A name in `dir` other than `inputs` (NULL-terminated): an output or a temporary
 * file left behind. 1 with it in `name`, else 0. */
static int stray_file(const char *dir, const char *const inputs[], char *name, size_t size)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int found = 0;
    for (struct dirent *e; !found && (e = readdir(d)) != NULL;) {
        int expected = strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0;
        for (size_t k = 0; inputs[k]; k++) expected |= strcmp(e->d_name, inputs[k]) == 0;
        if (!expected) {
            snprintf(name, size, "%s", e->d_name);
            found = 1;
        }
    }
    closedir(d);
    return found;
}

/* What is wrong with a refused run, or "" when it is right: exit status 2, stderr
 * exactly `expected` (one line), nothing in `dir` but `inputs`. */
static void check_refusal(const cli_result *r, const char *expected, const char *dir,
                          const char *const inputs[], char *problem, size_t size)
{
    char stray[256];
    problem[0] = '\0';
    if (r->timed_out)
        snprintf(problem, size, "hung: still running after %d s", RUN_SECONDS_MAX);
    else if (r->status != TARN_EXIT_BAD_INPUT)
        snprintf(problem, size, "exit status %d, expected 2", r->status);
    else if (strcmp(r->err, expected) != 0)
        snprintf(problem, size, "stderr is not the expected line");
    else if (stray_file(dir, inputs, stray, sizeof stray))
        snprintf(problem, size, "%s was left behind", stray);
}

/* ---- inputs that are not regular files --------------------------------------- */

#define TEXTURE_SCENE(path) \
    "{" BAD_CAMERA ", \"materials\": {\"m\": {\"texture\": \"" path "\"}}, \"objects\": []}"

typedef struct {
    const char *what;
    const char *scene;   /* bad.json's text; NULL: bad.json is the FIFO */
    const char *fifo;    /* the case's FIFO in the directory, or NULL */
    int bake_points;     /* `tarn bake ... --points DIR/points.txt` instead of render */
    int stdin_pipe;      /* stdin is a pipe that stays open and never delivers */
    const char *file;    /* the file the message names: in the directory, or absolute */
    const char *expect;  /* what follows its path */
} input_case;

static const input_case INPUT_CASES[] = {
    { "scene a FIFO", NULL, "bad.json", 0, 0, "bad.json", ": is a FIFO; a scene file must be a regular file" },
    { "mesh a FIFO", BAD_MESH_SCENE, "leaf.obj", 0, 0, "leaf.obj", ": is a FIFO; an OBJ file must be a regular file" },
    { "texture a FIFO", BAD_TEXTURE_SCENE, "tex.png", 0, 0, "tex.png", ": is a FIFO; a PNG file must be a regular file" },
    { "heightfield a FIFO", BAD_HEIGHTFIELD_SCENE, "pit.png", 0, 0, "pit.png",
      ": is a FIFO; a PNG file must be a regular file" },
    { "points file a FIFO", "", "points.txt", 1, 0, "points.txt", ": is a FIFO; a points file must be a regular file" },
    { "texture /dev/null", TEXTURE_SCENE("/dev/null"), NULL, 0, 0, "/dev/null",
      ": is a character device; a PNG file must be a regular file" },
    { "texture /dev/zero", TEXTURE_SCENE("/dev/zero"), NULL, 0, 0, "/dev/zero",
      ": is a character device; a PNG file must be a regular file" },
    { "texture /dev/stdin, a pipe that never delivers", TEXTURE_SCENE("/dev/stdin"), NULL, 0, 1, "/dev/stdin",
      ": is a FIFO; a PNG file must be a regular file" },
};

/* Runs one case in a fresh directory: 0 when it is refused as it must be. */
static int check_input_case(const char *tarn, const input_case *c)
{
    char dir[] = "/tmp/tarn_cli_inputs_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char scene[1100], fifo[1100], out[1100], points[1100], expected[1400], problem[300];
    snprintf(scene, sizeof scene, "%s/bad.json", dir);
    snprintf(points, sizeof points, "%s/points.txt", dir);
    snprintf(out, sizeof out, "%s/out.%s", dir, c->bake_points ? "c" : "png");
    if (c->bake_points) snprintf(scene, sizeof scene, "scenes/effects/none.json");
    else if (c->scene) assert_int_equal(bad_write_text(scene, c->scene), 0);
    if (c->fifo) {
        snprintf(fifo, sizeof fifo, "%s/%s", dir, c->fifo);
        assert_int_equal(mkfifo(fifo, 0600), 0);
    }
    snprintf(expected, sizeof expected, "tarn: %s%s%s%s\n", c->file[0] == '/' ? "" : dir,
             c->file[0] == '/' ? "" : "/", c->file, c->expect);

    int never_written[2] = { -1, -1 }; /* held open, so a reader waits for ever */
    if (c->stdin_pipe) assert_int_equal(pipe(never_written), 0);
    char *const render[] = { (char *)tarn, "render", scene, "-o", out, NULL };
    char *const bake[] = { (char *)tarn, "bake", scene, "-o", out, "--points", points, NULL };
    cli_result r;
    cli_run(c->bake_points ? bake : render, never_written[0], -1, RUN_SECONDS_MAX, &r);
    if (c->stdin_pipe) {
        close(never_written[0]);
        close(never_written[1]);
    }
    const char *const inputs[] = { "bad.json", c->fifo ? c->fifo : "bad.json", NULL };
    check_refusal(&r, expected, dir, inputs, problem, sizeof problem);
    if (problem[0])
        print_error("case \"%s\": %s\n  stderr   %s  expected %s", c->what, problem,
                    r.err_length ? r.err : "(empty)\n", expected);
    bad_case_remove_dir(dir);
    return problem[0] != '\0';
}

static void test_inputs_that_are_not_files(void **state)
{
    (void)state;
    const char *tarn = cli_tarn();
    int failures = 0; /* every case runs, so one run shows every wrong message */
    for (size_t k = 0; k < sizeof INPUT_CASES / sizeof INPUT_CASES[0]; k++)
        failures += check_input_case(tarn, &INPUT_CASES[k]);
    assert_int_equal(failures, 0);
}

/* A symbolic link to a regular file is that file: a scene and a texture through
 * links render. */
static void test_links_to_files_are_read(void **state)
{
    (void)state;
    const char *tarn = cli_tarn();
    char dir[] = "/tmp/tarn_cli_links_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char cwd[1024], ground[1100], scene[1100], link[1100], texture[1100], out[1100];
    assert_non_null(getcwd(cwd, sizeof cwd));
    snprintf(ground, sizeof ground, "%s/scenes/assets/ground.png", cwd);
    snprintf(scene, sizeof scene, "%s/scene.json", dir);
    snprintf(link, sizeof link, "%s/link.json", dir);
    snprintf(texture, sizeof texture, "%s/tex.png", dir);
    snprintf(out, sizeof out, "%s/out.png", dir);
    assert_int_equal(bad_write_text(scene, BAD_TEXTURE_SCENE), 0);
    assert_int_equal(symlink("scene.json", link), 0);
    assert_int_equal(symlink(ground, texture), 0);
    char *const argv[] = { (char *)tarn, "render", link, "-o", out, "--size", "32x32", NULL };
    cli_result r;
    cli_run(argv, -1, -1, RUN_SECONDS_MAX, &r);
    int written = access(out, F_OK) == 0;
    bad_case_remove_dir(dir); /* first: a failure ends the test */
    if (r.status != 0) fail_msg("status %d, stderr %s", r.status, r.err);
    assert_true(written);
}

/* ---- scenes over the limits ------------------------------------------------------ */

/* A refusal of the budget is a matter of weighing, not building: far under this. */
#define BUDGET_SECONDS_MAX 5.0

/* The spheres that fill the scenes below: 64 segments and 64 rings (SPHERE_JSON and
 * the messages spell them out), as the scene of 5,000 of them that took 18 s and a
 * gigabyte before it was refused. */
#define SPHERE_SEGMENTS 64u
#define SPHERE_JSON                                                                         \
    "{\"type\": \"sphere\", \"material\": \"m0\", \"radius\": 0.1, \"segments\": 64, " \
    "\"rings\": 64}"

/* A directory for a budget case; its scene is written with the helpers below. */
typedef struct {
    char dir[32];
    char scene[1100];
    FILE *file;
} budget_scene;

/* Opens DIR/bad.json with the camera and `materials` materials m0, m1... (each with
 * its texture tNN.png when `textured`), up to the "objects" array. */
static void budget_scene_begin(budget_scene *b, unsigned materials, int textured)
{
    snprintf(b->dir, sizeof b->dir, "/tmp/tarn_cli_budget_XXXXXX");
    assert_non_null(mkdtemp(b->dir));
    snprintf(b->scene, sizeof b->scene, "%s/bad.json", b->dir);
    b->file = fopen(b->scene, "w");
    assert_non_null(b->file);
    fprintf(b->file, "{" BAD_CAMERA ", \"materials\": {");
    for (unsigned k = 0; k < materials; k++) {
        if (textured)
            fprintf(b->file, "%s\"m%u\": {\"texture\": \"t%02u.png\"}", k ? ", " : "", k, k);
        else
            fprintf(b->file, "%s\"m%u\": {}", k ? ", " : "", k);
    }
    fprintf(b->file, "}, \"objects\": [");
}

/* `count` spheres, after `first` objects already written. */
static void budget_scene_spheres(budget_scene *b, size_t first, size_t count)
{
    for (size_t k = 0; k < count; k++) fprintf(b->file, "%s" SPHERE_JSON, first + k ? ", " : "");
}

/* Closes the scene, renders it and requires the refusal "DIR/FILE: WHY" within
 * BUDGET_SECONDS_MAX; `file` is "bad.json: objects[3] (...)" or "leaf.obj:7". */
static void budget_scene_refused(budget_scene *b, const char *file, const char *why,
                                 const char *const inputs[])
{
    fprintf(b->file, "]}\n");
    assert_int_equal(fclose(b->file), 0);
    char out[1100], expected[1600], problem[300];
    snprintf(out, sizeof out, "%s/out.png", b->dir);
    snprintf(expected, sizeof expected, "tarn: %s/%s: %s\n", b->dir, file, why);
    char *const argv[] = { (char *)cli_tarn(), "render", b->scene, "-o", out, NULL };
    cli_result r;
    cli_run(argv, -1, -1, RUN_SECONDS_MAX, &r);
    check_refusal(&r, expected, b->dir, inputs, problem, sizeof problem);
    if (!problem[0] && r.seconds > BUDGET_SECONDS_MAX)
        snprintf(problem, sizeof problem, "took %.1f s, more than %.0f", r.seconds, BUDGET_SECONDS_MAX);
    bad_case_remove_dir(b->dir); /* first: a failure ends the test */
    if (problem[0])
        fail_msg("%s\n  stderr   %s  expected %s", problem, r.err_length ? r.err : "(empty)\n",
                 expected);
}

/* "4,000,000" */
static const char *with_commas(uint64_t v, char out[32])
{
    char digits[24];
    int n = snprintf(digits, sizeof digits, "%llu", (unsigned long long)v), o = 0;
    for (int k = 0; k < n; k++) {
        if (k > 0 && (n - k) % 3 == 0) out[o++] = ',';
        out[o++] = digits[k];
    }
    out[o] = '\0';
    return out;
}

/* "the scene would hold 4,007,808 triangles; the limit is 4,000,000" */
static void would_hold(char *out, size_t size, uint64_t would, const char *noun, uint64_t limit)
{
    char a[32], b[32];
    snprintf(out, size, "the scene would hold %s %s; the limit is %s", with_commas(would, a), noun,
             with_commas(limit, b));
}

/* How many spheres fit the triangle limit; each sphere's size in `sphere`. */
static size_t spheres_that_fit(tarn_mesh_size *sphere)
{
    *sphere = tarn_mesh_sphere_size(SPHERE_SEGMENTS, SPHERE_SEGMENTS);
    size_t fit = TARN_SCENE_TRIANGLES_MAX / sphere->triangles;
    /* the cases below need the triangles to be the limit these spheres reach first */
    assert_true(fit * sphere->vertices <= TARN_SCENE_VERTICES_MAX);
    const tarn_scene_cost spheres = { fit + 1, fit * sphere->vertices, fit * sphere->triangles, 0 };
    assert_true(tarn_scene_cost_bytes(&spheres) <= TARN_SCENE_MEMORY_MAX);
    return fit;
}

static const char *const SCENE_ONLY[] = { "bad.json", NULL };

/* The scene: 5,000 spheres of 64 x 64, refused at the first that crosses the
 * triangle limit, before any is built. */
static void test_many_spheres_are_refused_at_once(void **state)
{
    (void)state;
    tarn_mesh_size sphere;
    size_t fit = spheres_that_fit(&sphere);
    budget_scene b;
    budget_scene_begin(&b, 1, 0);
    budget_scene_spheres(&b, 0, 5000);
    char file[64], why[200];
    snprintf(file, sizeof file, "bad.json: objects[%zu] (sphere, segments 64, rings 64)", fit);
    would_hold(why, sizeof why, (uint64_t)(fit + 1) * sphere.triangles, "triangles", TARN_SCENE_TRIANGLES_MAX);
    budget_scene_refused(&b, file, why, SCENE_ONLY);
}

/* An OBJ file first, then spheres that leave it too little room: the file stops at
 * the face that crosses the triangle limit. */
static void test_obj_stops_at_the_face_over_the_limit(void **state)
{
    (void)state;
    tarn_mesh_size sphere;
    size_t fit = spheres_that_fit(&sphere);
    const uint64_t room = TARN_SCENE_TRIANGLES_MAX - (uint64_t)fit * sphere.triangles;
    budget_scene b;
    budget_scene_begin(&b, 1, 0);
    fprintf(b.file, "{\"type\": \"mesh\", \"material\": \"m0\", \"file\": \"leaf.obj\"}");
    budget_scene_spheres(&b, 1, fit);
    char path[1100];
    snprintf(path, sizeof path, "%s/leaf.obj", b.dir);
    FILE *obj = fopen(path, "w");
    assert_non_null(obj);
    fprintf(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    for (uint64_t k = 0; k < room + 10; k++) fprintf(obj, "f 1 2 3\n");
    assert_int_equal(fclose(obj), 0);
    char file[64], why[200];
    snprintf(file, sizeof file, "leaf.obj:%llu", (unsigned long long)(3 + room + 1));
    would_hold(why, sizeof why, TARN_SCENE_TRIANGLES_MAX + 1ull, "triangles", TARN_SCENE_TRIANGLES_MAX);
    const char *const inputs[] = { "bad.json", "leaf.obj", NULL };
    budget_scene_refused(&b, file, why, inputs);
}

/* Writes a `side` x `side` PNG of one grey to DIR/NAME (a texture or a heightfield). */
static void write_grey_png(const char *dir, const char *name, uint32_t side)
{
    char path[1100];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    uint8_t *rgb = malloc((size_t)side * side * 3);
    assert_non_null(rgb);
    memset(rgb, 0x80, (size_t)side * side * 3);
    tarn_error err;
    int written = tarn_png_write_rgb(path, rgb, side, side, &err);
    free(rgb);
    if (written != 0) fail_msg("%s", err.message);
}

/* A heightfield first, then spheres: refused from its image's size, before its mesh
 * is built. */
static void test_heightfield_is_weighed_from_its_image(void **state)
{
    (void)state;
    tarn_mesh_size sphere;
    size_t fit = spheres_that_fit(&sphere);
    budget_scene b;
    budget_scene_begin(&b, 1, 0);
    fprintf(b.file, "{\"type\": \"heightfield\", \"material\": \"m0\", \"image\": \"hill.png\", "
                    "\"size\": [4, 4], \"height\": 1}");
    budget_scene_spheres(&b, 1, fit);
    write_grey_png(b.dir, "hill.png", 181);
    const tarn_mesh_size hill = tarn_mesh_heightfield_size(181, 181);
    char why[200];
    would_hold(why, sizeof why, (uint64_t)fit * sphere.triangles + hill.triangles, "triangles",
               TARN_SCENE_TRIANGLES_MAX);
    const char *const inputs[] = { "bad.json", "hill.png", NULL };
    budget_scene_refused(&b, "bad.json: objects[0] (heightfield, image 181x181)", why, inputs);
}

/* The textures t00.png... of materials m0... (budget_scene_begin), each of the
 * largest size; returns the case's inputs, for the check that nothing else is left. */
#define BIG_TEXTURE_SIDE TARN_TEXTURE_SIZE_MAX
#define BIG_TEXTURES_MAX 32
static const char *const *write_big_textures(budget_scene *b, unsigned count)
{
    static char names[BIG_TEXTURES_MAX][16];
    static const char *inputs[BIG_TEXTURES_MAX + 2];
    assert_true(count <= BIG_TEXTURES_MAX);
    inputs[0] = "bad.json";
    for (unsigned k = 0; k < count; k++) {
        snprintf(names[k], sizeof names[k], "t%02u.png", k);
        write_grey_png(b->dir, names[k], BIG_TEXTURE_SIDE);
        inputs[k + 1] = names[k];
    }
    inputs[count + 1] = NULL;
    return inputs;
}

/* One texture of the largest size past the texel limit: the field that names it. */
static void test_textures_over_the_texel_limit(void **state)
{
    (void)state;
    const uint64_t texels = (uint64_t)BIG_TEXTURE_SIDE * BIG_TEXTURE_SIDE;
    const unsigned count = (unsigned)(TARN_SCENE_TEXELS_MAX / texels) + 1;
    budget_scene b;
    budget_scene_begin(&b, count, 1);
    const char *const *inputs = write_big_textures(&b, count);
    char file[96], why[200];
    snprintf(file, sizeof file, "bad.json: materials.m%u.texture (image %ux%u)", count - 1, BIG_TEXTURE_SIDE,
             BIG_TEXTURE_SIDE);
    would_hold(why, sizeof why, count * texels, "texels of textures and water maps", TARN_SCENE_TEXELS_MAX);
    budget_scene_refused(&b, file, why, inputs);
}

/* Textures up to their limit, then spheres under theirs: together they need more
 * memory than a scene may, and the sphere that tips it is named. */
static void test_memory_over_the_limit(void **state)
{
    (void)state;
    const uint64_t texels = (uint64_t)BIG_TEXTURE_SIDE * BIG_TEXTURE_SIDE;
    const unsigned textures = (unsigned)(TARN_SCENE_TEXELS_MAX / texels);
    tarn_mesh_size sphere;
    size_t fit = spheres_that_fit(&sphere), spheres = fit;
    tarn_scene_cost cost = { spheres, 0, 0, textures * texels };
    size_t tipping = 0;
    while (tarn_scene_cost_bytes(&cost) <= TARN_SCENE_MEMORY_MAX) {
        cost.vertices += sphere.vertices;
        cost.triangles += sphere.triangles;
        tipping++;
    }
    assert_true(tipping <= fit); /* memory, not triangles, is the limit crossed */
    budget_scene b;
    budget_scene_begin(&b, textures, 1);
    const char *const *inputs = write_big_textures(&b, textures);
    budget_scene_spheres(&b, 0, spheres);
    char file[64], why[200], bytes[32], limit[32];
    snprintf(file, sizeof file, "bad.json: objects[%zu] (sphere, segments 64, rings 64)", tipping - 1);
    snprintf(why, sizeof why, "the scene would need some %s bytes of memory; the limit is %s",
             with_commas(tarn_scene_cost_bytes(&cost), bytes), with_commas(TARN_SCENE_MEMORY_MAX, limit));
    budget_scene_refused(&b, file, why, inputs);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_inputs_that_are_not_files),
        cmocka_unit_test(test_links_to_files_are_read),
        cmocka_unit_test(test_many_spheres_are_refused_at_once),
        cmocka_unit_test(test_obj_stops_at_the_face_over_the_limit),
        cmocka_unit_test(test_heightfield_is_weighed_from_its_image),
        cmocka_unit_test(test_textures_over_the_texel_limit),
        cmocka_unit_test(test_memory_over_the_limit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
