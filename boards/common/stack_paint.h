/* stack_paint.h: the word startup paints the whole stack with before main
 * (cortex_m_startup.c, qemu-rv32/startup.S), so that board_stack_peak (stack_peak.c)
 * can find the deepest word a run overwrote. Assembly includes it too, so the value
 * is a plain number (it fits an int, and compares equal to the uint32_t words). */
#ifndef TARN_STACK_PAINT_H
#define TARN_STACK_PAINT_H

#define STACK_PAINT 0x5AA5C33C

#endif
