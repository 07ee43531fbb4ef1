/* texture.c - chapter 10: a texture's colour at texture coordinates (u, v). */
#include "10_interpolation/texture.h"
#include "exercise.h"
#include "texture_space.h"

int texel_index(texture_kind kind, long long i, int n)
{
    /* TODO wrap: the index of the texel that index i reads in a row (or column) of n >= 1
     * texels, for either kind of texture, for any i (README, "Texture space"). */
    EXERCISE_STUB("10_interpolation", "texture.c", "wrap"); /* delete this line when done */
    (void)kind, (void)i, (void)n;
    return 0;
}

color texture_nearest(const scene_texture *tex, mesh_uv uv)
{
    const texture_image *img = &tex->image;
    real x = texel_coordinate(uv.u, img->width);      /* u W */
    real y = texel_coordinate(1 - uv.v, img->height); /* (1 - v) H: v up, rows down */
    /* TODO nearest: the colour of the texel nearest to (x, y), found as the course's solution
     * finds it, wrapped by the texture's kind (README, "Nearest and bilinear"). */
    EXERCISE_STUB("10_interpolation", "texture.c", "nearest"); /* delete this line when done */
    (void)x, (void)y;
    return texture_image_texel(img, 0, 0);
}

color texture_bilinear(const scene_texture *tex, mesh_uv uv)
{
    const texture_image *img = &tex->image;
    real x = texel_coordinate(uv.u, img->width);
    real y = texel_coordinate(1 - uv.v, img->height);
    /* TODO bilinear: the colour blended from the four texels whose centres surround (x, y),
     * each wrapped by the texture's kind (README, "Nearest and bilinear"). */
    EXERCISE_STUB("10_interpolation", "texture.c", "bilinear"); /* delete this line when done */
    (void)x, (void)y;
    return texture_image_texel(img, 0, 0);
}

color texture_lookup(const scene_texture *tex, mesh_uv uv, texture_filter filter)
{
    return filter == TEXTURE_BILINEAR ? texture_bilinear(tex, uv) : texture_nearest(tex, uv);
}
