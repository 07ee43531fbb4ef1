/* texture.c - chapter 10: a texture's colour at texture coordinates (u, v). */
#include "10_interpolation/texture.h"
#include "exercise.h"

#include <math.h>

const char *const texture_filter_names[] = {"nearest", "bilinear", NULL};

/* snippet: texel_index */
int texel_index(texture_kind kind, long long i, int n)
{
    /* TODO wrap: the index of the texel that index i reads in a row (or column) of n >= 1
     * texels, for either kind of texture, for any i (README, "Texture space"). */
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
    /* TODO nearest: the colour of the texel nearest to (x, y), found as the course's solution
     * finds it, wrapped by the texture's kind (README, "Nearest and bilinear"). */
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
    /* TODO bilinear: the colour blended from the four texels whose centres surround (x, y),
     * each wrapped by the texture's kind (README, "Nearest and bilinear"). */
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
