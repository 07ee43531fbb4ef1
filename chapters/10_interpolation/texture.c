/* texture.c - chapter 10: a texture's colour at texture coordinates (u, v). */
#include "10_interpolation/texture.h"
#include "exercise.h"

#include <math.h>

const char *const texture_filter_names[] = {"nearest", "bilinear", NULL};

/* snippet: texel_index */
int texel_index(texture_kind kind, long long i, int n)
{
    /* TODO wrap: the index of the texel that i reads, n >= 1 texels:
     *     RepeatTexture: i mod n, in [0, n) also for negative i
     *         (C's % keeps the sign of i: -1 % 4 is -1, which must become 3);
     *     ClampTexture: i clamped to [0, n - 1]. */
    EXERCISE_STUB("10_interpolation", "texture.c", "wrap"); /* delete this line when done */
    (void)kind;
    (void)i;
    (void)n;
    return 0;
}
/* end snippet */

/* The continuous texel coordinates of (u, v): x = u W across from the left
 * edge, y = (1 - v) H down from the top (v counts up from the bottom), in
 * texel widths; texel (x, y)'s centre is at (x, y).  Beyond +-2^40 texels
 * (no index means anything there) a coordinate is held at +-2^40, so that
 * it converts to an integer; NaN reads 0. */
#define TEXEL_COORDINATE_LIMIT ((real)1099511627776.0) /* 2^40 */

static real texel_coordinate(real s, int n)
{
    real x = s * (real)n;
    if (!(x == x))
        return 0;
    return real_fmin(real_fmax(x, -TEXEL_COORDINATE_LIMIT), TEXEL_COORDINATE_LIMIT);
}

/* snippet: texture_nearest */
color texture_nearest(const scene_texture *tex, mesh_uv uv)
{
    const texture_image *img = &tex->image;
    real x = texel_coordinate(uv.u, img->width);      /* u W */
    real y = texel_coordinate(1 - uv.v, img->height); /* (1 - v) H: v up, rows down */
    /* TODO nearest: the texel nearest to (x, y), as the course's solution
     *     finds it: add 1/2 and drop the fraction (a conversion to an integer,
     *     which rounds towards zero: (long long)(x + 0.5)); wrap the column and
     *     the row by texel_index (the texture's kind tex->kind; the image's
     *     width and height); and read the texel: texture_image_texel(img,
     *     column, row).  (For x < -1/2 dropping the fraction rounds up, not
     *     down: texel 0 is read from x = -3/2 to 1/2, a whole texel more
     *     than the others.  The course's images show it, so it stays.) */
    EXERCISE_STUB("10_interpolation", "texture.c", "nearest"); /* delete this line when done */
    (void)x;
    (void)y;
    return texture_image_texel(img, 0, 0);
}
/* end snippet */

/* snippet: texture_bilinear */
color texture_bilinear(const scene_texture *tex, mesh_uv uv)
{
    const texture_image *img = &tex->image;
    real x = texel_coordinate(uv.u, img->width);
    real y = texel_coordinate(1 - uv.v, img->height);
    /* TODO bilinear: the four texels whose centres surround (x, y):
     *     columns x0 = floor(x) and x0 + 1, rows y0 = floor(y) and y0 + 1,
     *     each wrapped by texel_index; with the fractions s = x - x0 and
     *     t = y - y0, blend along x, then along y:
     *         top    = (1 - s) T(x0, y0)     + s T(x0 + 1, y0)
     *         bottom = (1 - s) T(x0, y0 + 1) + s T(x0 + 1, y0 + 1)
     *         result = (1 - t) top + t bottom */
    EXERCISE_STUB("10_interpolation", "texture.c", "bilinear"); /* delete this line when done */
    (void)x;
    (void)y;
    return texture_image_texel(img, 0, 0);
}
/* end snippet */

color texture_lookup(const scene_texture *tex, mesh_uv uv, texture_filter filter)
{
    return filter == TEXTURE_BILINEAR ? texture_bilinear(tex, uv) : texture_nearest(tex, uv);
}
