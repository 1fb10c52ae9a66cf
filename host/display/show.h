/* show.h: `tarn show`: a scene animated on a panel.
 *
 * Frames render continuously (or --frames N) at the panel's size and go out by the
 * send path the options pick; while one frame is sent, a second thread renders the
 * next. The run ends with one line of figures:
 *   show panel=MODEL rotation=R display=... link=... send=... frames=N
 *        bytes_per_frame=B spi_bytes=T transfers=X busy=Y tiles_sent=S tiles_skipped=K
 *        link_ms=L link_bytes_per_s=... link_fps=... ceiling_fps=... wall_s=W wall_fps=...
 * link_* come from the link's counted bits and transfers (display.h), the same on
 * every machine; ceiling_fps is what the SPI clock allows a whole frame sent in
 * bands; wall_* is measured and says how fast this machine and link really were. */
#ifndef TARN_HOST_SHOW_H
#define TARN_HOST_SHOW_H

/* The whole command; argv[1] is "show". Returns the exit status: 0, 2 for bad input
 * or a device that cannot be used (one "tarn: ..." line), 1 when the link failed
 * during the run. */
int tarn_command_show(int argc, char **argv);

#endif
