/* texture.c - chapter 10: a texture's colour at texture coordinates (u, v). */
#include "10_interpolation/texture.h"
#include "texture_space.h"

int texel_index(texture_kind kind, long long i, int n)
{
    /* EXERCISE wrap: the index of the texel that index i reads in a row (or column) of n >= 1
     * texels, for either kind of texture, for any i (README, "Texture space"). */
    if (kind == TEXTURE_REPEAT) {
        long long m = i % n;
        return (int)(m < 0 ? m + n : m);
    }
    return i < 0 ? 0 : i >= n ? n - 1 : (int)i;
    /* STUB
    (void)kind, (void)i, (void)n;
    return 0;
    END EXERCISE */
}

color texture_nearest(const scene_texture *tex, mesh_uv uv)
{
    const texture_image *img = &tex->image;
    real x = texel_coordinate(uv.u, img->width);      /* u W */
    real y = texel_coordinate(1 - uv.v, img->height); /* (1 - v) H: v up, rows down */
    /* EXERCISE nearest: the colour of the texel nearest to (x, y), found as the course's solution
     * finds it, wrapped by the texture's kind (README, "Nearest and bilinear"). */
    int column = texel_index(tex->kind, (long long)(x + (real)0.5), img->width);
    int row = texel_index(tex->kind, (long long)(y + (real)0.5), img->height);
    return texture_image_texel(img, column, row);
    /* STUB
    (void)x, (void)y;
    return texture_image_texel(img, 0, 0);
    END EXERCISE */
}

color texture_bilinear(const scene_texture *tex, mesh_uv uv)
{
    const texture_image *img = &tex->image;
    real x = texel_coordinate(uv.u, img->width);
    real y = texel_coordinate(1 - uv.v, img->height);
    /* EXERCISE bilinear: the colour blended from the four texels whose centres surround (x, y),
     * each wrapped by the texture's kind (README, "Nearest and bilinear"). */
    real fx = real_floor(x), fy = real_floor(y);
    real s = x - fx, t = y - fy;
    int x0 = texel_index(tex->kind, (long long)fx, img->width);
    int x1 = texel_index(tex->kind, (long long)fx + 1, img->width);
    int y0 = texel_index(tex->kind, (long long)fy, img->height);
    int y1 = texel_index(tex->kind, (long long)fy + 1, img->height);
    color top = color_add(color_scale(texture_image_texel(img, x0, y0), 1 - s),
                          color_scale(texture_image_texel(img, x1, y0), s));
    color bottom = color_add(color_scale(texture_image_texel(img, x0, y1), 1 - s),
                             color_scale(texture_image_texel(img, x1, y1), s));
    return color_add(color_scale(top, 1 - t), color_scale(bottom, t));
    /* STUB
    (void)x, (void)y;
    return texture_image_texel(img, 0, 0);
    END EXERCISE */
}

color texture_lookup(const scene_texture *tex, mesh_uv uv, texture_filter filter)
{
    return filter == TEXTURE_BILINEAR ? texture_bilinear(tex, uv) : texture_nearest(tex, uv);
}
