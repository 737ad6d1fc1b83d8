/*
 * frame_out_png.c — frame_out.h as PNG files DIR/NNNN.png (the names gpusim cosim gives its
 * frames, so the scene tests compare the two folders file by file). The one file of the host
 * build that sees the co-simulation's PNG writer (firmware.mk gives only this object -Icosim).
 */
#include <stdio.h>

#include "frame_out.h"
#include "png_write.h"

int frame_out_write(const char *dir, unsigned index, const uint8_t *rgb, unsigned width,
                    unsigned height)
{
    char path[1024];

    snprintf(path, sizeof path, "%s/%04u.png", dir, index);
    if (png_write_rgb(path, rgb, (int)width, (int)height) != 0) {
        fprintf(stderr, "host bsp: cannot write %s\n", path);
        return -1;
    }
    return 0;
}
