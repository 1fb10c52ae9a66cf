#include "child_process.h"

#include <errno.h>
#include <fcntl.h>
#include <spawn.h>
#include <string.h>
#include <sys/wait.h>

extern char **environ;

int tarn_child_start(tarn_child *child, char *const argv[], tarn_error *err)
{
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, child->log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&files, 1, 2);
    const int status = posix_spawnp(&child->pid, child->program, &files, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&files);
    if (status == ENOENT)
        return tarn_fail(err, "%s not found; install it: %s", child->program, child->install);
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
