/* tarn view in a real display server: Xvfb runs for the suite, tarn view runs
 * scripts in it, and each screenshot must be, pixel for pixel (scaled), what tarn
 * render or tarn compare draws for the same scene, time, camera and quality; the
 * window's title and pixels are read back from the X server itself. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <errno.h>
#include <fcntl.h>
#include <png.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "cli_run.h"

extern char **environ;

static pid_t xvfb;
static char display_name[32];

/* Whether the server answers a client, as a view's SDL will ask it. */
static int wait_for_server(void)
{
    for (int k = 0; k < 200; k++) {
        Display *x = XOpenDisplay(display_name);
        if (x != NULL) {
            XCloseDisplay(x);
            return 0;
        }
        struct timespec pause = {0, 50000000};
        nanosleep(&pause, NULL);
    }
    int status;
    const int ended = waitpid(xvfb, &status, WNOHANG) == xvfb;
    fprintf(stderr, "test_view: Xvfb on %s does not answer after 10 s (%s; its log: /tmp/test_view-xvfb.log)\n",
            display_name, ended ? "it has ended" : "it is running");
    return -1;
}

/* Xvfb on a display number it finds free, which it writes to the pipe. */
static int start_xvfb(void **state)
{
    (void)state;
    int fds[2];
    if (pipe(fds) != 0) return -1;
    char fd_text[16];
    snprintf(fd_text, sizeof fd_text, "%d", fds[1]);
    char *argv[] = {"/usr/bin/Xvfb", "-displayfd", fd_text, "-screen", "0", "1024x768x24", "-nolisten", "tcp", NULL};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/tmp/test_view-xvfb.log", O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    const int spawned = posix_spawn(&xvfb, argv[0], &actions, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    if (spawned != 0) {
        fprintf(stderr, "test_view: cannot start %s: %s (make test installs xvfb)\n", argv[0], strerror(spawned));
        return -1;
    }
    /* the number ends with a newline, which may come in a write of its own: the
     * pipe stays open until it has, or Xvfb fails writing it */
    struct pollfd p = {fds[0], POLLIN, 0};
    char number[16] = "";
    ssize_t got = 0;
    while (strchr(number, '\n') == NULL && got < (ssize_t)sizeof number - 1 && poll(&p, 1, 20000) == 1) {
        const ssize_t more = read(fds[0], number + got, sizeof number - 1 - (size_t)got);
        if (more <= 0) break;
        got += more;
        number[got] = '\0';
    }
    close(fds[0]);
    if (strchr(number, '\n') == NULL) {
        fprintf(stderr, "test_view: Xvfb gave no display number within 20 s (its log: /tmp/test_view-xvfb.log)\n");
        return -1;
    }
    number[strcspn(number, "\n")] = '\0';
    snprintf(display_name, sizeof display_name, ":%s", number);
    return wait_for_server();
}

static int stop_xvfb(void **state)
{
    (void)state;
    if (xvfb > 0) {
        kill(xvfb, SIGTERM);
        waitpid(xvfb, NULL, 0);
    }
    return 0;
}

/* tarn view's environment: the suite's display, and in the sanitizer build the
 * leak check told what SDL's libraries keep to the end (tests/view.lsan). */
static void on_display(void)
{
    setenv("LSAN_OPTIONS", "suppressions=tests/view.lsan:print_suppressions=0", 1);
    setenv("DISPLAY", display_name, 1);
    unsetenv("WAYLAND_DISPLAY");
    unsetenv("SDL_VIDEODRIVER");
}

typedef struct {
    int width, height;
    uint8_t *rgb;
} image;

static image read_png(const char *path)
{
    png_image png;
    memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    image out = {0, 0, NULL};
    if (!png_image_begin_read_from_file(&png, path)) fail_msg("%s: cannot read: %s", path, png.message);
    png.format = PNG_FORMAT_RGB;
    out.width = (int)png.width;
    out.height = (int)png.height;
    out.rgb = malloc(PNG_IMAGE_SIZE(png));
    assert_non_null(out.rgb);
    if (!png_image_finish_read(&png, NULL, out.rgb, 0, NULL)) fail_msg("%s: cannot decode: %s", path, png.message);
    return out;
}

/* The window pixels that are not the frame pixel they scale up, or -1 when the
 * sizes are not a whole scale apart. */
static long scaled_differences(const image *window, const image *frame)
{
    if (frame->width == 0 || window->width % frame->width || window->width / frame->width * frame->height != window->height)
        return -1;
    const int scale = window->width / frame->width;
    long differ = 0;
    for (int y = 0; y < window->height; y++)
        for (int x = 0; x < window->width; x++)
            differ += memcmp(window->rgb + 3 * ((size_t)y * window->width + x),
                             frame->rgb + 3 * ((size_t)(y / scale) * frame->width + x / scale), 3) != 0;
    return differ;
}

/* Whether the screenshot at `shot` is `reference` (a frame-sized PNG) scaled up. */
static void assert_shows(const char *shot, const char *reference)
{
    image window = read_png(shot), frame = read_png(reference);
    const long differ = scaled_differences(&window, &frame);
    if (differ != 0)
        fail_msg("%s (%dx%d) is not %s (%dx%d) scaled up: %ld window pixels differ", shot, window.width,
                 window.height, reference, frame.width, frame.height, differ);
    free(window.rgb);
    free(frame.rgb);
}

static int same_png(const char *a, const char *b)
{
    image x = read_png(a), y = read_png(b);
    const int same = x.width == y.width && x.height == y.height &&
                     memcmp(x.rgb, y.rgb, 3u * (size_t)x.width * (size_t)x.height) == 0;
    free(x.rgb);
    free(y.rgb);
    return same;
}

/* Runs "tarn WORDS" (split at spaces), which must succeed. */
static void run_tarn(const char *words)
{
    char line[4096], *argv[96];
    int argc = 0;
    snprintf(line, sizeof line, "%s", words);
    argv[argc++] = (char *)cli_tarn();
    for (char *w = strtok(line, " "); w != NULL && argc < 95; w = strtok(NULL, " ")) argv[argc++] = w;
    argv[argc] = NULL;
    cli_result *r = malloc(sizeof *r);
    cli_run(argv, -1, -1, 120, r);
    if (r->status != 0) fail_msg("tarn %s: exit %d: %s", words, r->status, r->err);
    free(r);
}

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

/* The screenshot lines of a view's stdout: "view screenshot=PATH ... command=tarn WORDS". */
typedef struct {
    char shot[256], command[4096];
} screenshot_line;

static size_t screenshot_lines(const char *out, screenshot_line *lines, size_t max)
{
    size_t count = 0;
    for (const char *at = strstr(out, "view screenshot="); at && count < max; at = strstr(at + 1, "view screenshot=")) {
        const char *end = strchr(at, '\n'), *command = strstr(at, " command=tarn ");
        assert_non_null(end);
        assert_true(command != NULL && command < end);
        sscanf(at, "view screenshot=%255s", lines[count].shot);
        snprintf(lines[count].command, sizeof lines[count].command, "%.*s", (int)(end - command - 14), command + 14);
        count++;
    }
    return count;
}

/* The line's command with OUT.png replaced by `output`. */
static void command_to(const screenshot_line *line, const char *output, char *out, size_t size)
{
    const char *at = strstr(line->command, "OUT.png");
    assert_non_null(at);
    snprintf(out, size, "%.*s%s%s", (int)(at - line->command), line->command, output, at + 7);
}

/* Tests run from the checkout's top. */
static const char *scene_path(void)
{
    return "scenes/pond.json";
}

/* Runs argv, which must exit 2 with one line on stderr that holds `says`. */
static void fails_in_one_line(char *const argv[], const char *says)
{
    cli_result *r = malloc(sizeof *r);
    cli_run(argv, -1, -1, 30, r);
    if (r->status != 2 || !cli_one_line(r) || strstr(r->err, says) == NULL)
        fail_msg("exit %d, stderr not one line saying '%s': %s", r->status, says, r->err);
    free(r);
}

static void test_view_without_a_display_is_one_line(void **state)
{
    (void)state;
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    unsetenv("SDL_VIDEODRIVER");
    char *argv[] = {(char *)cli_tarn(), "view", (char *)scene_path(), NULL};
    fails_in_one_line(argv, "no display");
}

static void test_a_display_that_does_not_answer_is_one_line(void **state)
{
    (void)state;
    on_display();
    setenv("DISPLAY", ":9999", 1); /* no server there */
    char *argv[] = {(char *)cli_tarn(), "view", (char *)scene_path(), NULL};
    fails_in_one_line(argv, "cannot open the display :9999");
}

static void test_a_bad_script_line_is_named(void **state)
{
    (void)state;
    on_display();
    write_file(cli_in_folder("bad.txt"), "0 screenshot\n# fine so far\n3 key NoSuchKey\n");
    char *argv[] = {(char *)cli_tarn(), "view", (char *)scene_path(), "--script", (char *)cli_in_folder("bad.txt"),
                    "--screenshot", (char *)cli_in_folder("s.png"), NULL};
    fails_in_one_line(argv, "bad.txt:3: expected a key");
    assert_int_equal(access(cli_in_folder("s-0000.png"), F_OK), -1);
}

static const char view_script[] =
    "0 screenshot\n"          /* the scene as render draws it at 0 ms */
    "3 screenshot\n"          /* the clock: frame 3 at 100 ms */
    "4 key 3\n4 screenshot\n" /* the exact preset */
    "5 drag 60 -24\n5 screenshot\n"
    "6 wheel 3\n6 screenshot\n"
    "7 key R\n7 key V\n7 screenshot\n" /* the scene's camera again; the float reference */
    "8 key V\n8 screenshot\n"          /* the heat map */
    "9 key V\n9 key P\n9 key B\n9 screenshot\n" /* the core through the panel, --water-block 2 */
    "10 quit\n";

static void test_view_shows_what_render_draws(void **state)
{
    (void)state;
    on_display();
    write_file(cli_in_folder("script.txt"), view_script);
    char *argv[] = {(char *)cli_tarn(), "view", (char *)scene_path(), "--size", "96x80", "--scale", "2",
                    "--script", (char *)cli_in_folder("script.txt"), "--screenshot", (char *)cli_in_folder("v.png"),
                    NULL};
    cli_result *r = malloc(sizeof *r);
    cli_run(argv, -1, -1, 120, r);
    if (r->status != 0) fail_msg("tarn view: exit %d: %s", r->status, r->err);
    screenshot_line lines[16];
    assert_int_equal(screenshot_lines(r->out, lines, 16), 8);
    char command[4200];
    /* frames 0 and 3, and the preset, by commands this test writes itself */
    snprintf(command, sizeof command, "render %s --size 96x80 --time 0 -o %s", scene_path(), cli_in_folder("r.png"));
    run_tarn(command);
    assert_shows(lines[0].shot, cli_in_folder("r.png"));
    snprintf(command, sizeof command, "render %s --size 96x80 --time 100 -o %s", scene_path(), cli_in_folder("r.png"));
    run_tarn(command);
    assert_shows(lines[1].shot, cli_in_folder("r.png"));
    snprintf(command, sizeof command, "render %s --size 96x80 --time 133 --quality exact -o %s", scene_path(),
             cli_in_folder("r.png"));
    run_tarn(command);
    assert_shows(lines[2].shot, cli_in_folder("r.png"));
    /* the dragged camera is another picture, which the printed camera draws */
    image moved = read_png(lines[3].shot), before = read_png(lines[2].shot);
    assert_true(memcmp(moved.rgb, before.rgb, 3u * (size_t)moved.width * (size_t)moved.height) != 0);
    free(moved.rgb);
    free(before.rgb);
    assert_non_null(strstr(lines[3].command, "--camera "));
    assert_non_null(strstr(lines[4].command, "--camera "));
    assert_null(strstr(lines[5].command, "--camera "));
    assert_non_null(strstr(lines[5].command, "--reference"));
    assert_non_null(strstr(lines[6].command, "compare "));
    assert_non_null(strstr(lines[7].command, "--rgb565"));
    assert_non_null(strstr(lines[7].command, "--water-block 2"));
    for (int k = 3; k < 8; k++) {
        const char *output = cli_in_folder(k == 6 ? "heat.png" : "r.png");
        command_to(&lines[k], output, command, sizeof command);
        run_tarn(command);
        assert_shows(lines[k].shot, output);
    }
    free(r);
}

/* The title of the one top-level window with one, as the X server holds it. */
static void window_title(Display *x, char *out, size_t size, Window *found)
{
    Window root, parent, *children = NULL;
    unsigned count = 0;
    out[0] = '\0';
    *found = 0;
    if (!XQueryTree(x, DefaultRootWindow(x), &root, &parent, &children, &count)) return;
    for (unsigned k = 0; k < count; k++) {
        XTextProperty name;
        if (!XGetWMName(x, children[k], &name) || name.value == NULL) continue;
        snprintf(out, size, "%.*s", (int)name.nitems, (const char *)name.value);
        *found = children[k];
        XFree(name.value);
    }
    if (children) XFree(children);
}

/* Whether the window's pixels in the X server are the screenshot's. */
static int window_shows(Display *x, Window w, const char *shot)
{
    image expected = read_png(shot);
    XImage *got = XGetImage(x, w, 0, 0, (unsigned)expected.width, (unsigned)expected.height, AllPlanes, ZPixmap);
    long differ = got == NULL ? -1 : 0;
    for (int y = 0; got != NULL && y < expected.height; y++)
        for (int i = 0; i < expected.width; i++) {
            const unsigned long p = XGetPixel(got, i, y);
            const uint8_t *e = expected.rgb + 3 * ((size_t)y * expected.width + i);
            differ += ((p >> 16) & 255) != e[0] || ((p >> 8) & 255) != e[1] || (p & 255) != e[2];
        }
    if (got) XDestroyImage(got);
    free(expected.rgb);
    return differ == 0;
}

static int wait_for_file(const char *path)
{
    for (int k = 0; k < 600; k++) {
        if (access(path, F_OK) == 0) return 1;
        struct timespec pause = {0, 50000000};
        nanosleep(&pause, NULL);
    }
    return 0;
}

static const char *small_scene(const char *colour)
{
    static char text[512];
    snprintf(text, sizeof text,
             "{\"frame\": {\"width\": 64, \"height\": 48},\n"
             " \"camera\": {\"position\": [0, 2, 6], \"target\": [0, 0, 0], \"fov\": 60},\n"
             " \"materials\": {\"m\": {\"colour\": \"%s\"}},\n"
             " \"objects\": [{\"type\": \"box\", \"material\": \"m\", \"size\": [2, 2, 2]}]}\n", colour);
    return text;
}

static void test_a_bad_edit_keeps_the_last_picture(void **state)
{
    (void)state;
    on_display();
    char scene[256];
    snprintf(scene, sizeof scene, "%s", cli_in_folder("edit.json"));
    write_file(scene, small_scene("#d0452f"));
    write_file(cli_in_folder("edit.txt"), "0 screenshot\n1 wait-edit\n1 screenshot\n2 wait-edit\n2 screenshot\n3 quit\n");
    char out_path[256], err_path[256], script[256], shots[256];
    snprintf(out_path, sizeof out_path, "%s", cli_in_folder("view.out"));
    snprintf(err_path, sizeof err_path, "%s", cli_in_folder("view.err"));
    snprintf(script, sizeof script, "%s", cli_in_folder("edit.txt"));
    snprintf(shots, sizeof shots, "%s", cli_in_folder("e.png"));
    char *argv[] = {(char *)cli_tarn(), "view", scene, "--scale", "3", "--script", script, "--screenshot",
                    shots, NULL};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t view;
    assert_int_equal(posix_spawn(&view, argv[0], &actions, NULL, argv, environ), 0);
    posix_spawn_file_actions_destroy(&actions);

    assert_true(wait_for_file(cli_in_folder("e-0000.png")));
    write_file(scene, "{\"frame\": {\"width\": 64, \"height\": 48},\n \"camera\": {\"position\": [0, 2, 6]");
    assert_true(wait_for_file(cli_in_folder("e-0001.png")));
    /* now at frame 2's wait: the window shows the last good picture, and the error */
    Display *x = XOpenDisplay(display_name);
    assert_non_null(x);
    char title[2048];
    Window window;
    window_title(x, title, sizeof title, &window);
    if (strstr(title, "edit.json") == NULL || strstr(title, "last good picture") == NULL)
        fail_msg("the window's title does not show the scene's error: '%s'", title);
    assert_true(window_shows(x, window, cli_in_folder("e-0000.png")));
    XCloseDisplay(x);
    write_file(scene, small_scene("#2f6f9f"));

    int status = -1;
    for (int k = 0; k < 600 && waitpid(view, &status, WNOHANG) == 0; k++) {
        struct timespec pause = {0, 50000000};
        nanosleep(&pause, NULL);
    }
    if (!WIFEXITED(status)) kill(view, SIGKILL);
    assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    assert_true(same_png(cli_in_folder("e-0000.png"), cli_in_folder("e-0001.png")));
    char command[1024];
    snprintf(command, sizeof command, "render %s -o %s", scene, cli_in_folder("blue.png"));
    run_tarn(command);
    assert_shows(cli_in_folder("e-0002.png"), cli_in_folder("blue.png"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_view_without_a_display_is_one_line, cli_make_folder, cli_remove_folder),
        cmocka_unit_test(test_a_display_that_does_not_answer_is_one_line),
        cmocka_unit_test_setup_teardown(test_a_bad_script_line_is_named, cli_make_folder, cli_remove_folder),
        cmocka_unit_test_setup_teardown(test_view_shows_what_render_draws, cli_make_folder, cli_remove_folder),
        cmocka_unit_test_setup_teardown(test_a_bad_edit_keeps_the_last_picture, cli_make_folder, cli_remove_folder),
    };
    return cmocka_run_group_tests(tests, start_xvfb, stop_xvfb);
}
