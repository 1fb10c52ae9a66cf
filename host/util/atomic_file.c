#include "atomic_file.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* mkstemp creates files readable by the owner only; an output should get the
 * permissions any other new file would. */
static int set_default_permissions(int fd)
{
    mode_t mask = umask(0);
    umask(mask);
    return fchmod(fd, 0666 & ~mask);
}

int tarn_atomic_open(tarn_atomic_file *f, const char *path, tarn_error *err)
{
    size_t temp_size = strlen(path) + sizeof ".tmp.XXXXXX";
    f->path = path;
    f->file = NULL;
    f->temp_path = malloc(temp_size);
    if (!f->temp_path) return tarn_fail(err, "%s: out of memory", path);
    snprintf(f->temp_path, temp_size, "%s.tmp.XXXXXX", path);
    int fd = mkstemp(f->temp_path);
    if (fd < 0) {
        tarn_fail(err, "%s: cannot create %s: %s", path, f->temp_path, strerror(errno));
        free(f->temp_path);
        f->temp_path = NULL;
        return -1;
    }
    if (set_default_permissions(fd) != 0 || !(f->file = fdopen(fd, "wb"))) {
        tarn_fail(err, "%s: cannot write %s: %s", path, f->temp_path, strerror(errno));
        close(fd);
        tarn_atomic_abandon(f);
        return -1;
    }
    return 0;
}

void tarn_atomic_abandon(tarn_atomic_file *f)
{
    if (f->file) fclose(f->file);
    if (f->temp_path) unlink(f->temp_path);
    free(f->temp_path);
    f->file = NULL;
    f->temp_path = NULL;
}

int tarn_atomic_commit(tarn_atomic_file *f, tarn_error *err)
{
    /* ferror catches a write that failed earlier; fclose one that fails on flush */
    int write_failed = ferror(f->file);
    int close_failed = fclose(f->file) != 0;
    int saved_errno = errno;
    f->file = NULL;
    int result = 0;
    if (write_failed || close_failed) {
        result = tarn_fail(err, "%s: cannot write %s: %s", f->path, f->temp_path,
                           close_failed ? strerror(saved_errno) : "write error");
    } else if (rename(f->temp_path, f->path) != 0) {
        result = tarn_fail(err, "%s: cannot rename %s into place: %s", f->path, f->temp_path,
                           strerror(errno));
    }
    if (result != 0) unlink(f->temp_path);
    free(f->temp_path);
    f->temp_path = NULL;
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
    for (size_t k = 0; k < count; k++) {
        if (tarn_atomic_commit(&files[k], err) == 0) continue;
        tarn_atomic_abandon_all(files + k + 1, count - k - 1);
        while (k > 0) remove(files[--k].path); /* some files alone would be half an output */
        return -1;
    }
    return 0;
}
