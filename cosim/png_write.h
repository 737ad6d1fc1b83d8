/* png_write: write an RGB888 image as a PNG file (libpng). */
#ifndef PNG_WRITE_H
#define PNG_WRITE_H

#include <stdint.h>

/* Returns 0 on success; on failure prints why to stderr and returns -1. */
int png_write_rgb(const char *path, const uint8_t *rgb, int width, int height);

#endif
