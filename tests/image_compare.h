/* image_compare.h - a rendered image against a reference PNG, byte by byte.
 *
 * The course's reference images were rendered by the course's own solution;
 * ours match them when (nearly) every byte is within a small tolerance.  The
 * comparison encodes the rendered radiance for display exactly as the PNG
 * writer does (display_encode), reads the reference with stb_image, and
 * counts, per byte (channel), how many are within the tolerance.  It also
 * says where the differences are: how many pixels, their bounding box, and
 * the largest difference with its pixel.
 */
#ifndef RT_TESTS_IMAGE_COMPARE_H
#define RT_TESTS_IMAGE_COMPARE_H

#include <stddef.h>

#include "image.h"

typedef struct {
    long bytes;        /* 3 * width * height */
    long within;       /* bytes whose difference is <= the tolerance */
    int max_diff;      /* the largest |ours - reference| of any byte */
    int max_x, max_y;  /* its pixel, in PNG coordinates (row 0 at the top) */
    long pixels_off;   /* pixels with a byte beyond the tolerance */
    int x0, y0, x1, y1; /* their bounding box (inclusive, PNG coordinates); -1 when none */
} image_diff;

/* Compares img (linear radiance, encoded with `exposure`) with the PNG at
 * png_path.  Returns 0 and fills *diff, or -1 with a message in err when the
 * PNG cannot be read or its size differs from img's. */
int image_compare_png(const image *img, real exposure, const char *png_path, int tolerance, image_diff *diff,
                      char *err, size_t err_size);

/* The share of bytes within the tolerance, in percent. */
double image_diff_percent(const image_diff *diff);

#endif
