/* pixel.h - chapter 01: the pixel-to-image mapping.
 *
 * The lecture's "Pixel-to-image mapping": pixel (i, j) of an n_x x n_y image
 * is the square [i, i+1] x [j, j+1], pixel (0, 0) at the bottom left, and its
 * ray goes through the square's centre, at the normalized image position
 *     u = (i + 0.5) / n_x,   v = (j + 0.5) / n_y.
 * The render loop (common/render_loop.c) calls it for every sample, with the
 * sample's place (du, dv) inside the pixel: (0.5, 0.5) for one sample.
 */
#ifndef CH01_PIXEL_H
#define CH01_PIXEL_H

#include "real.h"

/* The normalized image position (u, v) in [0,1]^2 of the point (i + du, j + dv)
 * of pixel (i, j): (0, 0) is the bottom-left corner of the image, (1, 1) the
 * top-right.  A pixel_map_fn (common/render_loop.h). */
void pixel_to_image(int i, int j, int nx, int ny, real du, real dv, real *u, real *v);

#endif
