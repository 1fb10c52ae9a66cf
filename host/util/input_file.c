/* input_file.c: regular input files of a bounded size (input_file.h). */
#include "input_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* "a FIFO", "a directory"...: what a file that is not a regular one is. */
static const char *kind_of(mode_t mode)
{
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

/* 0 when `info` is a regular file of at most `max_bytes`, else -1 with the refusal. */
static int check_input(const char *path, const char *what, size_t max_bytes, const struct stat *info,
                       tarn_error *err)
{
    if (!S_ISREG(info->st_mode))
        return tarn_fail(err, "%s: is %s; %s must be a regular file", path, kind_of(info->st_mode), what);
    if ((uintmax_t)info->st_size > (uintmax_t)max_bytes)
        return tarn_fail(err, "%s: is %lld bytes; %s holds at most %zu", path, (long long)info->st_size, what,
                         max_bytes);
    return 0;
}

FILE *tarn_open_input(const char *path, const char *what, size_t max_bytes, tarn_error *err)
{
    /* Checked by name first, so that a device is refused without being opened (opening
     * one can act: a tape rewinds, a watchdog starts), then again on the descriptor,
     * which is the file actually read should the name have changed in between. */
    struct stat info;
    if (stat(path, &info) != 0) return tarn_fail(err, "%s: cannot open: %s", path, strerror(errno)), NULL;
    if (check_input(path, what, max_bytes, &info, err)) return NULL;
    /* O_NONBLOCK: a FIFO swapped in after the stat opens at once instead of waiting for
     * a writer, and is then refused */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) return tarn_fail(err, "%s: cannot open: %s", path, strerror(errno)), NULL;
    int flags = fstat(fd, &info) == 0 ? fcntl(fd, F_GETFL) : -1;
    if (flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) < 0) {
        tarn_fail(err, "%s: cannot open: %s", path, strerror(errno));
    } else if (check_input(path, what, max_bytes, &info, err) == 0) {
        FILE *file = fdopen(fd, "r");
        if (file) return file;
        tarn_fail(err, "%s: cannot open: %s", path, strerror(errno));
    }
    close(fd);
    return NULL;
}
