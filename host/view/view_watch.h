/* view_watch.h: the files a view reads again when they change on disk: the scene
 * file and the textures it names. A change is any difference in the file's inode,
 * size or modification time (to the nanosecond), so an editor that writes in
 * place and one that renames a new file over the old are both seen. */
#ifndef TARN_HOST_VIEW_WATCH_H
#define TARN_HOST_VIEW_WATCH_H

#include <stddef.h>
#include <sys/stat.h>
#include "scene_load.h"

typedef struct {
    char *path;
    int exists;
    dev_t device;
    ino_t inode;
    off_t size;
    struct timespec modified;
} tarn_watched_file;

typedef struct {
    tarn_watched_file *files;
    size_t count;
} tarn_view_watch;

/* Watches `scene_path` and, if `scene` is not NULL, its textures, as they are now.
 * 0, or -1 when out of memory (the watch is then empty). */
int tarn_view_watch_set(tarn_view_watch *watch, const char *scene_path, const tarn_loaded_scene *scene);

/* Whether any watched file changed since it was last looked at; each is looked
 * at now. */
int tarn_view_watch_changed(tarn_view_watch *watch);

void tarn_view_watch_free(tarn_view_watch *watch);

#endif
