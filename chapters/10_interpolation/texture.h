/* texture.h - chapter 10: a texture's colour at texture coordinates (u, v), in texels x = u W,
 * y = (1 - v) H (common/texture_space.h), each texel's bytes / 255 as stored (README, "Textures"). */
#ifndef CH10_TEXTURE_H
#define CH10_TEXTURE_H

#include "color.h"
#include "mesh.h"
#include "scene.h"

typedef enum { TEXTURE_NEAREST, TEXTURE_BILINEAR } texture_filter; /* --texture-filter */

/* The column (or row) that index i, any integer, reads in an image n texels
 * wide (or high), n >= 1: i mod n (in [0, n), also for i < 0) for
 * RepeatTexture, i clamped to [0, n - 1] for ClampTexture. */
int texel_index(texture_kind kind, long long i, int n);

/* The texel nearest to (u, v), as the course finds it: column (long long)(u W
 * + 1/2), row (long long)((1 - v) H + 1/2), each wrapped by the texture's kind. */
color texture_nearest(const scene_texture *tex, mesh_uv uv);

/* The bilinear blend of the four texels whose centres surround (u, v), each
 * index wrapped by the texture's kind. */
color texture_bilinear(const scene_texture *tex, mesh_uv uv);

/* The texture's colour at (u, v) with `filter`.  A NaN coordinate counts as
 * 0; one beyond 2^40 texels as 2^40 texels. */
color texture_lookup(const scene_texture *tex, mesh_uv uv, texture_filter filter);

#endif
