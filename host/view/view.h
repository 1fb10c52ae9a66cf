/* view.h: `tarn view`: a scene drawn live by the integer core in a window, with
 * the clock, the camera, the quality and the picture (core, reference, heat map,
 * panel) under the keys and the mouse, and the scene read again as it is edited.
 * docs/view.md is its manual; view_options.h its command line. */
#ifndef TARN_HOST_VIEW_H
#define TARN_HOST_VIEW_H

/* The whole command; argv[1] is "view". Returns the exit status: 0, or 2 for bad
 * input, no display or a window that cannot open (one "tarn: ..." line). */
int tarn_command_view(int argc, char **argv);

#endif
