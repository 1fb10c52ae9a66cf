#include "child_process.h"

#include <errno.h>
#include <fcntl.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

static int missing(const tarn_child *child, tarn_error *err)
{
    return tarn_fail(err, "%s not found; install it: %s", child->program, child->install);
}

int tarn_child_installed(const tarn_child *child, tarn_error *err)
{
    const char *path = getenv("PATH");
    if (strchr(child->program, '/') != NULL) return access(child->program, X_OK) == 0 ? 0 : missing(child, err);
    for (const char *dir = path ? path : ""; *dir != '\0';) {
        size_t length = strcspn(dir, ":");
        char candidate[4096];
        int written = snprintf(candidate, sizeof candidate, "%.*s/%s", (int)length, dir, child->program);
        if (written > 0 && (size_t)written < sizeof candidate && access(candidate, X_OK) == 0) return 0;
        dir += length + (dir[length] == ':');
    }
    return missing(child, err);
}

int tarn_child_start(tarn_child *child, char *const argv[], tarn_error *err)
{
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, child->log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&files, 1, 2);
    const int status = posix_spawnp(&child->pid, child->program, &files, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&files);
    if (status == ENOENT) return missing(child, err);
    if (status != 0) return tarn_fail(err, "cannot run %s: %s", child->program, strerror(status));
    return 0;
}

int tarn_child_finish(const tarn_child *child, tarn_error *err)
{
    int status;
    if (waitpid(child->pid, &status, 0) < 0)
        return tarn_fail(err, "waiting for %s: %s", child->program, strerror(errno));
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return 0;
    return tarn_fail(err, "%s failed: see %s", child->program, child->log);
}

int tarn_child_run(tarn_child *child, char *const argv[], tarn_error *err)
{
    return tarn_child_start(child, argv, err) || tarn_child_finish(child, err) ? -1 : 0;
}
