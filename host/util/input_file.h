/* input_file.h: the files tarn reads (scenes, OBJ meshes, PNG images, points files)
 * opened so that only a regular file of a bounded size is ever read.
 *
 * A FIFO, a device, a socket or a directory named where a file belongs would block
 * the open (a FIFO without a writer), never end (/dev/zero, a pipe fed slowly) or not
 * be a file at all; a huge regular file (a sparse one costs no disk) would be read
 * whole. Each is refused with one line before its first byte is read:
 *   scenes/bad.json: is a FIFO; a scene file must be a regular file
 *   scenes/bad.json: is 5242880 bytes; a scene file holds at most 4194304
 * A symbolic link is followed: a link to a regular file is that file. */
#ifndef TARN_HOST_INPUT_FILE_H
#define TARN_HOST_INPUT_FILE_H

#include <stddef.h>
#include <stdio.h>
#include "error.h"

/* `path` open for reading, or NULL with `err` set ("PATH: cannot open: REASON", or one
 * of the refusals above). `what` names the kind of file the caller reads, with its
 * article: "a scene file", "an OBJ file". */
FILE *tarn_open_input(const char *path, const char *what, size_t max_bytes, tarn_error *err);

#endif
