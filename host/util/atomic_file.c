#include "atomic_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* As many links as the kernel follows before it says ELOOP. */
#define LINK_HOPS_MAX 40

/* mkstemp creates files readable by the owner only; an output should get the
 * permissions any other new file would. */
static int set_default_permissions(int fd)
{
    mode_t mask = umask(0);
    umask(mask);
    return fchmod(fd, 0666 & ~mask);
}

/* `link`, read from the symlink `at`, as a path from here: relative links are
 * relative to the link's own folder. Owned by the caller, or NULL. */
static char *link_destination(const char *at, const char *link)
{
    const char *slash = strrchr(at, '/');
    size_t folder = link[0] == '/' || slash == NULL ? 0 : (size_t)(slash - at) + 1;
    char *joined = malloc(folder + strlen(link) + 1);
    if (joined == NULL) return NULL;
    memcpy(joined, at, folder);
    strcpy(joined + folder, link);
    return joined;
}

/* The file the chain of symlinks from `path` ends at (it may not exist yet: a
 * dangling link names the file to create). Owned by the caller, or NULL. */
static char *follow_links(const char *path, tarn_error *err)
{
    char *at = strdup(path);
    for (int hop = 0; at != NULL && hop <= LINK_HOPS_MAX; hop++) {
        struct stat info;
        if (lstat(at, &info) != 0 || !S_ISLNK(info.st_mode)) return at;
        char link[4096];
        ssize_t length = readlink(at, link, sizeof link - 1);
        if (length < 0) {
            tarn_fail(err, "%s: cannot read the link %s: %s", path, at, strerror(errno));
            free(at);
            return NULL;
        }
        link[length] = '\0';
        char *next = link_destination(at, link);
        free(at);
        at = next;
    }
    if (at == NULL) tarn_fail(err, "%s: out of memory", path);
    else tarn_fail(err, "%s: too many levels of symbolic links", path);
    free(at);
    return NULL;
}

/* Standard output, or a target that is no regular file, written in place through
 * the path as given (so that /dev/stdout and /proc/self/fd/N reach the pipe they
 * stand for). A FIFO is opened without waiting: with no reader that is an error
 * (ENXIO). */
static int open_through(tarn_atomic_file *f, tarn_error *err)
{
    int fd = strcmp(f->path, "-") == 0 ? dup(STDOUT_FILENO)
                                      : open(f->path, O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        return tarn_fail(err, "%s: cannot write: %s", f->path,
                         errno == ENXIO ? "no process reads this FIFO" : strerror(errno));
    }
    int flags = fcntl(fd, F_GETFL);
    if (flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0 || !(f->file = fdopen(fd, "wb"))) {
        close(fd);
        return tarn_fail(err, "%s: cannot write: %s", f->path, strerror(errno));
    }
    return 0;
}

static int open_temporary(tarn_atomic_file *f, tarn_error *err)
{
    size_t temp_size = strlen(f->target) + sizeof ".tmp.XXXXXX";
    f->temp_path = malloc(temp_size);
    if (!f->temp_path) return tarn_fail(err, "%s: out of memory", f->path);
    snprintf(f->temp_path, temp_size, "%s.tmp.XXXXXX", f->target);
    int fd = mkstemp(f->temp_path);
    if (fd < 0) {
        tarn_fail(err, "%s: cannot create %s: %s", f->path, f->temp_path, strerror(errno));
        free(f->temp_path);
        f->temp_path = NULL;
        return -1;
    }
    if (set_default_permissions(fd) != 0 || !(f->file = fdopen(fd, "wb"))) {
        tarn_fail(err, "%s: cannot write %s: %s", f->path, f->temp_path, strerror(errno));
        close(fd);
        return -1;
    }
    return 0;
}

/* How the output is written: through (1), by a temporary file renamed over the
 * end of its links (0), or not at all (-1: a directory). stat follows every link,
 * /proc's too, to what a write would reach. */
static int written_through(const char *path, tarn_error *err)
{
    struct stat info;
    if (strcmp(path, "-") == 0) return 1;
    if (stat(path, &info) != 0) return 0;
    if (S_ISDIR(info.st_mode)) return tarn_fail(err, "%s: is a directory, expected a file name", path);
    return !S_ISREG(info.st_mode);
}

int tarn_atomic_open(tarn_atomic_file *f, const char *path, tarn_error *err)
{
    f->path = path;
    f->file = NULL;
    f->temp_path = NULL;
    f->target = NULL;
    const int through = written_through(path, err);
    if (through < 0) return -1;
    if (through) return open_through(f, err); /* in place: no target to rename over */
    f->target = follow_links(path, err);
    if (f->target == NULL) return -1;
    if (open_temporary(f, err) == 0) return 0;
    tarn_atomic_abandon(f);
    return -1;
}

void tarn_atomic_abandon(tarn_atomic_file *f)
{
    if (f->file) fclose(f->file);
    if (f->temp_path) unlink(f->temp_path);
    free(f->temp_path);
    free(f->target);
    f->file = NULL;
    f->temp_path = NULL;
    f->target = NULL;
}

/* Whether everything written reached the file: ferror catches a write that failed
 * earlier, fclose one that fails on flush (a full disk, /dev/full). */
static int close_output(tarn_atomic_file *f, tarn_error *err)
{
    int write_failed = ferror(f->file);
    int close_failed = fclose(f->file) != 0;
    int saved_errno = errno;
    f->file = NULL;
    if (!write_failed && !close_failed) return 0;
    const char *reason = close_failed ? strerror(saved_errno) : "write error";
    if (f->temp_path == NULL) return tarn_fail(err, "%s: cannot write: %s", f->path, reason);
    return tarn_fail(err, "%s: cannot write %s: %s", f->path, f->temp_path, reason);
}

int tarn_atomic_commit(tarn_atomic_file *f, tarn_error *err)
{
    int result = close_output(f, err);
    if (result == 0 && f->temp_path != NULL && rename(f->temp_path, f->target) != 0) {
        result = tarn_fail(err, "%s: cannot rename %s into place: %s", f->path, f->temp_path,
                           strerror(errno));
    }
    if (result != 0 && f->temp_path != NULL) unlink(f->temp_path);
    tarn_atomic_abandon(f);
    return result;
}

int tarn_atomic_open_all(tarn_atomic_file *files, const char *const *paths, size_t count, tarn_error *err)
{
    for (size_t opened = 0; opened < count; opened++) {
        if (tarn_atomic_open(&files[opened], paths[opened], err) == 0) continue;
        tarn_atomic_abandon_all(files, opened);
        return -1;
    }
    return 0;
}

void tarn_atomic_abandon_all(tarn_atomic_file *files, size_t count)
{
    while (count > 0) tarn_atomic_abandon(&files[--count]);
}

int tarn_atomic_commit_all(tarn_atomic_file *files, size_t count, tarn_error *err)
{
    char *placed[count > 0 ? count : 1]; /* the regular files renamed into place */
    size_t placed_count = 0;
    int result = 0;
    for (size_t k = 0; k < count && result == 0; k++) {
        char *target = files[k].temp_path != NULL ? strdup(files[k].target) : NULL;
        result = tarn_atomic_commit(&files[k], err);
        if (result == 0 && target != NULL) placed[placed_count++] = target;
        else free(target);
        if (result != 0) tarn_atomic_abandon_all(files + k + 1, count - k - 1);
    }
    while (placed_count > 0) {
        char *target = placed[--placed_count];
        if (result != 0) remove(target); /* some files alone would be half an output */
        free(target);
    }
    return result;
}
