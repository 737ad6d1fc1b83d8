/*
 * frame_out.h — where the host build's swapped frames go: one image file per frame, numbered as
 * the co-simulation numbers its frames. The host BSP (bsp_host.c) scans a frame out of the golden
 * model and hands the pixels here; the file format is the implementation's (frame_out_png.c: PNG,
 * through the co-simulation's writer in libcosim), so the BSP itself names no image library and
 * no other component's header.
 */
#ifndef FRAME_OUT_H
#define FRAME_OUT_H

#include <stdint.h>

/* rgb (width x height, RGB888, rows top down) as frame number `index` in dir. Returns 0, or -1
 * when the file could not be written (the implementation has said why on stderr). */
int frame_out_write(const char *dir, unsigned index, const uint8_t *rgb, unsigned width,
                    unsigned height);

#endif /* FRAME_OUT_H */
