/* texture_space.h - texture coordinates in texel units.
 *
 * u runs across an image W texels wide from its left edge, v up from its
 * bottom edge; in texels x = u W and y = (1 - v) H (rows stored from the
 * top), and texel (i, j) is centred on (x, y) = (i, j) (chapter 10's README,
 * "Texture space").
 */
#ifndef TEXTURE_SPACE_H
#define TEXTURE_SPACE_H

#include "real.h"

/* s n, in texel widths of an image n texels across: held within +-2^40 (no
 * index means anything beyond, and so it converts to an integer); 0 for NaN. */
real texel_coordinate(real s, int n);

#endif
