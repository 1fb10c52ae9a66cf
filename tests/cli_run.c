#include "cli_run.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

static void fail_setup(const char *what)
{
    fprintf(stderr, "cli_run: %s: %s\n", what, strerror(errno));
    exit(1);
}

/* Appends what `fd` has to the buffer; 0 at its end. */
static int drain(int fd, char *buffer, size_t *length)
{
    char scratch[4096];
    ssize_t got = read(fd, scratch, sizeof scratch);
    if (got < 0) return errno == EINTR || errno == EAGAIN ? 1 : 0;
    size_t room = CLI_OUTPUT_MAX - 1 - *length;
    size_t kept = (size_t)got < room ? (size_t)got : room;
    memcpy(buffer + *length, scratch, kept);
    *length += kept;
    buffer[*length] = '\0';
    return got > 0;
}

static double now_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static pid_t spawn(char *const argv[], int stdin_fd, int out_pipe, int err_pipe, int stderr_fd)
{
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (stdin_fd >= 0) posix_spawn_file_actions_adddup2(&actions, stdin_fd, STDIN_FILENO);
    else posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, out_pipe, STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, stderr_fd >= 0 ? stderr_fd : err_pipe, STDERR_FILENO);
    /* the test's own ends of the pipes stay out of the child, so that its exit closes them */
    posix_spawn_file_actions_addclose(&actions, out_pipe);
    posix_spawn_file_actions_addclose(&actions, err_pipe);
    pid_t pid;
    int spawned = posix_spawn(&pid, argv[0], &actions, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) {
        errno = spawned;
        fail_setup(argv[0]);
    }
    return pid;
}

void cli_run(char *const argv[], int stdin_fd, int stderr_fd, unsigned timeout_s, cli_result *r)
{
    int out_fds[2], err_fds[2];
    if (pipe(out_fds) != 0 || pipe(err_fds) != 0) fail_setup("pipe");
    /* the read ends never reach the child */
    if (fcntl(out_fds[0], F_SETFD, FD_CLOEXEC) != 0 || fcntl(err_fds[0], F_SETFD, FD_CLOEXEC) != 0)
        fail_setup("fcntl");
    const double start = now_seconds();
    pid_t pid = spawn(argv, stdin_fd, out_fds[1], err_fds[1], stderr_fd);
    close(out_fds[1]);
    close(err_fds[1]);
    memset(r, 0, sizeof *r);
    struct pollfd fds[2] = {{out_fds[0], POLLIN, 0}, {err_fds[0], POLLIN, 0}};
    const double deadline = start + (double)timeout_s;
    while (fds[0].fd >= 0 || fds[1].fd >= 0) {
        if (now_seconds() >= deadline) {
            r->timed_out = 1;
            kill(pid, SIGKILL);
            break;
        }
        if (poll(fds, 2, 200) <= 0) continue;
        for (int k = 0; k < 2; k++) {
            if (fds[k].fd < 0 || !(fds[k].revents & (POLLIN | POLLHUP))) continue;
            if (!drain(fds[k].fd, k == 0 ? r->out : r->err, k == 0 ? &r->out_length : &r->err_length)) {
                close(fds[k].fd);
                fds[k].fd = -1;
            }
        }
    }
    for (int k = 0; k < 2; k++)
        if (fds[k].fd >= 0) close(fds[k].fd);
    int wait_status;
    while (waitpid(pid, &wait_status, 0) < 0)
        if (errno != EINTR) fail_setup("waitpid");
    r->seconds = now_seconds() - start;
    r->status = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1;
}

int cli_one_line(const cli_result *r)
{
    const char *newline = strchr(r->err, '\n');
    return newline != NULL && newline[1] == '\0';
}

const char *cli_tarn(void)
{
    const char *tarn = getenv("TARN_BIN");
    if (tarn == NULL || access(tarn, X_OK) != 0) fail_msg("TARN_BIN is not set to a tarn binary (make check sets it)");
    return tarn;
}

static char folder[64];

int cli_make_folder(void **state)
{
    (void)state;
    snprintf(folder, sizeof folder, "/tmp/tarn-cli-XXXXXX");
    return mkdtemp(folder) == NULL ? -1 : 0;
}

int cli_remove_folder(void **state)
{
    (void)state;
    char command[128];
    snprintf(command, sizeof command, "rm -rf '%s'", folder);
    return system(command) == 0 ? 0 : -1;
}

const char *cli_in_folder(const char *name)
{
    static char paths[4][256];
    static int next;
    char *path = paths[next++ % 4];
    snprintf(path, sizeof paths[0], "%s/%s", folder, name);
    return path;
}
