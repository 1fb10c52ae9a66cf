/* atomic_file.h: writing an output file all or nothing.
 *
 * The content goes to a temporary file beside the target ("out.png.tmp.XXXXXX", so
 * that the final rename stays on one file system) and is renamed over the target
 * only once it is complete and closed without error: a failure at any point leaves
 * neither a partial file nor the temporary behind, and an existing target intact.
 * Errors name the target: "out/pond.c: cannot create out/pond.c.tmp.Xa3f9q: ...". */
#ifndef TARN_HOST_ATOMIC_FILE_H
#define TARN_HOST_ATOMIC_FILE_H

#include <stdio.h>
#include "error.h"

typedef struct {
    const char *path; /* the target */
    char *temp_path;  /* owned */
    FILE *file;       /* open on the temporary file; write to it freely */
} tarn_atomic_file;

/* Creates the temporary file, with the permissions any new file would get. */
int tarn_atomic_open(tarn_atomic_file *f, const char *path, tarn_error *err);

/* Closes the temporary file and renames it over the target; on any failure
 * (including an earlier write error on `file`) removes it instead. Either way `f`
 * is finished. */
int tarn_atomic_commit(tarn_atomic_file *f, tarn_error *err);

/* Closes and removes the temporary file; the target is untouched. */
void tarn_atomic_abandon(tarn_atomic_file *f);

/* Several files that make one output, all or none: open_all opens every one (or,
 * failing, none stays open); commit_all renames them in order, and if one fails
 * abandons the rest and removes those already in place; abandon_all drops them. */
int tarn_atomic_open_all(tarn_atomic_file *files, const char *const *paths, size_t count, tarn_error *err);
int tarn_atomic_commit_all(tarn_atomic_file *files, size_t count, tarn_error *err);
void tarn_atomic_abandon_all(tarn_atomic_file *files, size_t count);

#endif
