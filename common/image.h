/* image.h - an image buffer of linear radiance.
 *
 * Pixel (i, j) follows the lecture: i counts columns from the left, j counts
 * rows from the BOTTOM (v = (j + 0.5) / n_y grows upwards).  Only the PNG
 * writer flips rows, because PNG files store the top row first.
 */
#ifndef RT_IMAGE_H
#define RT_IMAGE_H

#include "color.h"

typedef struct {
    int width;  /* n_x */
    int height; /* n_y */
    color *pixels; /* width * height, row j at pixels + j * width */
} image;

/* Allocates a black image; returns 0, or -1 when out of memory. */
int image_init(image *img, int width, int height);
void image_free(image *img);

static inline color *image_at(const image *img, int i, int j) { return &img->pixels[(long)j * img->width + i]; }

#endif
