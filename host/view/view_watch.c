/* view_watch.c: files looked at for changes (view_watch.h). */
#include "view_watch.h"

#include <stdlib.h>
#include <string.h>

/* Looks at the file now: whether it differs from when it was last looked at. */
static int look(tarn_watched_file *f)
{
    struct stat s;
    const int exists = stat(f->path, &s) == 0;
    const int changed = exists != f->exists ||
                        (exists && (s.st_dev != f->device || s.st_ino != f->inode || s.st_size != f->size ||
                                    s.st_mtim.tv_sec != f->modified.tv_sec ||
                                    s.st_mtim.tv_nsec != f->modified.tv_nsec));
    f->exists = exists;
    if (exists) {
        f->device = s.st_dev;
        f->inode = s.st_ino;
        f->size = s.st_size;
        f->modified = s.st_mtim;
    }
    return changed;
}

static int add(tarn_view_watch *watch, const char *path)
{
    tarn_watched_file *f = &watch->files[watch->count];
    memset(f, 0, sizeof *f);
    f->path = strdup(path);
    if (f->path == NULL) return -1;
    watch->count++;
    look(f);
    return 0;
}

int tarn_view_watch_set(tarn_view_watch *watch, const char *scene_path, const tarn_loaded_scene *scene)
{
    tarn_view_watch_free(watch);
    const size_t textures = scene ? scene->texture_count : 0;
    watch->files = calloc(1 + textures, sizeof *watch->files);
    int failed = watch->files == NULL || add(watch, scene_path) != 0;
    for (size_t k = 0; k < textures && !failed; k++) failed = add(watch, scene->texture_paths[k]) != 0;
    if (failed) tarn_view_watch_free(watch);
    return failed ? -1 : 0;
}

int tarn_view_watch_changed(tarn_view_watch *watch)
{
    int changed = 0;
    for (size_t k = 0; k < watch->count; k++) changed |= look(&watch->files[k]);
    return changed;
}

void tarn_view_watch_free(tarn_view_watch *watch)
{
    for (size_t k = 0; k < watch->count; k++) free(watch->files[k].path);
    free(watch->files);
    watch->files = NULL;
    watch->count = 0;
}
