/*
 * png_diff — pixel error of one PNG against a reference PNG, for `make bench-error`.
 *
 *     png_diff [--block N] [--box K] REFERENCE IMAGE
 *
 * Both images are read as 8-bit RGB and must have the same size. With --block N (default 1) only
 * the top-left pixel of each N x N block is compared: the co-simulation's frames show each
 * framebuffer pixel as a 2 x 2 block of the 640 x 480 monitor image, so --block 2 measures in
 * framebuffer pixels. Prints one line:
 *
 *     pixels P differing D abs_sum S max_abs M
 *
 * P pixels compared, D of them with any channel different, S the sum over the compared pixels and
 * their three channels of |image - reference| (0..255 each), M the largest such channel difference.
 * With --box K (the compared pixels' grid a whole number of K x K boxes), the line goes on with
 *
 *     box_abs_sum B
 *
 * B the sum over the aligned K x K boxes of compared pixels and their three channels of
 * |sum over the box of image - sum over the box of reference|: the error of the frames as seen
 * from afar, after averaging each box, where an ordered dither of that period averages to the
 * intensity it stands for. B / (P * 3) is the mean, per pixel and channel, of the box means'
 * difference (S / (P * 3) the same without averaging).
 * Exit status 0 when compared (equal or not), 2 on a usage, read or size error.
 */
#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint8_t *png_diff_read(const char *path, png_uint_32 *w, png_uint_32 *h)
{
    png_image img;
    uint8_t *rgb;

    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path)) {
        fprintf(stderr, "png_diff: %s: %s\n", path, img.message);
        return NULL;
    }
    img.format = PNG_FORMAT_RGB;
    rgb = malloc(PNG_IMAGE_SIZE(img));
    if (rgb == NULL || !png_image_finish_read(&img, NULL, rgb, 0, NULL)) {
        fprintf(stderr, "png_diff: %s: %s\n", path, rgb ? img.message : "out of memory");
        free(rgb);
        png_image_free(&img);
        return NULL;
    }
    *w = img.width;
    *h = img.height;
    return rgb;
}

int main(int argc, char **argv)
{
    png_uint_32 block = 1;
    png_uint_32 box = 0;
    png_uint_32 rw, rh, iw, ih;
    uint8_t *ref;
    uint8_t *img;
    int64_t *box_sums = NULL;  /* per box of the compared grid and channel: sum image - sum reference */
    png_uint_32 boxes_x = 0;
    uint64_t pixels = 0, differing = 0, abs_sum = 0, box_abs_sum = 0;
    unsigned max_abs = 0;
    int a = 1;

    while (argc - a > 2 && argv[a][0] == '-') {
        if (strcmp(argv[a], "--block") == 0) {
            block = (png_uint_32)strtoul(argv[a + 1], NULL, 10);
        } else if (strcmp(argv[a], "--box") == 0) {
            box = (png_uint_32)strtoul(argv[a + 1], NULL, 10);
            if (box == 0) {
                block = 0;  /* a usage error below */
            }
        } else {
            break;
        }
        a += 2;
    }
    if (argc - a != 2 || block == 0) {
        fprintf(stderr, "usage: png_diff [--block N] [--box K] REFERENCE IMAGE\n");
        return 2;
    }
    ref = png_diff_read(argv[a], &rw, &rh);
    img = ref ? png_diff_read(argv[a + 1], &iw, &ih) : NULL;
    if (ref == NULL || img == NULL) {
        free(ref);
        return 2;
    }
    if (rw != iw || rh != ih) {
        fprintf(stderr, "png_diff: sizes differ: %ux%u and %ux%u\n", (unsigned)rw, (unsigned)rh,
                (unsigned)iw, (unsigned)ih);
        free(ref);
        free(img);
        return 2;
    }
    if (box != 0) {
        const png_uint_32 gw = (rw + block - 1) / block, gh = (rh + block - 1) / block;

        if (gw % box != 0 || gh % box != 0) {
            fprintf(stderr, "png_diff: --box %u does not tile the %ux%u compared pixels\n", (unsigned)box,
                    (unsigned)gw, (unsigned)gh);
            free(ref);
            free(img);
            return 2;
        }
        boxes_x = gw / box;
        box_sums = calloc((size_t)boxes_x * (gh / box) * 3u, sizeof *box_sums);
        if (box_sums == NULL) {
            fprintf(stderr, "png_diff: out of memory\n");
            free(ref);
            free(img);
            return 2;
        }
    }
    for (png_uint_32 y = 0; y < rh; y += block) {
        for (png_uint_32 x = 0; x < rw; x += block) {
            const size_t o = ((size_t)y * rw + x) * 3u;
            unsigned diff = 0;

            for (int c = 0; c < 3; c++) {
                const unsigned d = (unsigned)abs((int)img[o + c] - (int)ref[o + c]);

                abs_sum += d;
                diff |= d;
                max_abs = (d > max_abs) ? d : max_abs;
                if (box_sums != NULL) {
                    box_sums[(((size_t)(y / block / box) * boxes_x + x / block / box) * 3u) + (size_t)c] +=
                        (int)img[o + c] - (int)ref[o + c];
                }
            }
            pixels++;
            differing += (diff != 0u);
        }
    }
    printf("pixels %llu differing %llu abs_sum %llu max_abs %u", (unsigned long long)pixels,
           (unsigned long long)differing, (unsigned long long)abs_sum, max_abs);
    if (box_sums != NULL) {
        const size_t n = (size_t)boxes_x * (((rh + block - 1) / block) / box) * 3u;

        for (size_t i = 0; i < n; i++) {
            box_abs_sum += (uint64_t)(box_sums[i] < 0 ? -box_sums[i] : box_sums[i]);
        }
        printf(" box_abs_sum %llu", (unsigned long long)box_abs_sum);
        free(box_sums);
    }
    printf("\n");
    free(ref);
    free(img);
    return 0;
}
