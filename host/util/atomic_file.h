/* atomic_file.h: writing an output file all or nothing, and never over anything
 * but a regular file.
 *
 * What the target is decides how it is written:
 * - a regular file, or none yet: the content goes to a temporary file beside it
 *   ("out.png.tmp.XXXXXX", so that the final rename stays on one file system) and is
 *   renamed over it only once complete and closed without error. A failure at any
 *   point leaves neither a partial file nor the temporary behind, and an existing
 *   target intact.
 * - a symlink: the same, for the file its chain of links ends at (which may not
 *   exist yet); the link stays a link.
 * - a device, FIFO or socket (/dev/null, a named pipe): written through, in place,
 *   as `cat > /dev/null` would; it is never renamed over or removed. A FIFO nobody
 *   reads is an error, not a wait.
 * - "-": standard output, written through.
 * - a directory: an error.
 * Errors name the target: "out/pond.c: cannot create out/pond.c.tmp.Xa3f9q: ...". */
#ifndef TARN_HOST_ATOMIC_FILE_H
#define TARN_HOST_ATOMIC_FILE_H

#include <stdio.h>
#include "error.h"

typedef struct {
    const char *path; /* the target as given */
    char *target;     /* owned: the file a temporary replaces, once the links are
                         followed; NULL when written through */
    char *temp_path;  /* owned: the temporary file; NULL when written through */
    FILE *file;       /* open on the temporary file (or the target); write to it freely */
} tarn_atomic_file;

/* The output's file: the temporary one, with the permissions any new file would
 * get, or the target itself when it is written through. */
int tarn_atomic_open(tarn_atomic_file *f, const char *path, tarn_error *err);

/* Closes the temporary file and renames it over the target; on any failure
 * (including an earlier write error on `file`) removes it instead. Either way `f`
 * is finished. */
int tarn_atomic_commit(tarn_atomic_file *f, tarn_error *err);

/* Closes and removes the temporary file; the target is untouched (but for what
 * was already written through). */
void tarn_atomic_abandon(tarn_atomic_file *f);

/* Several files that make one output, all or none: open_all opens every one (or,
 * failing, none stays open); commit_all renames them in order, and if one fails
 * abandons the rest and removes the regular files already in place; abandon_all
 * drops them. */
int tarn_atomic_open_all(tarn_atomic_file *files, const char *const *paths, size_t count, tarn_error *err);
int tarn_atomic_commit_all(tarn_atomic_file *files, size_t count, tarn_error *err);
void tarn_atomic_abandon_all(tarn_atomic_file *files, size_t count);

#endif
