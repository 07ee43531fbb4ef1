/* texture.h - chapter 10: a texture's colour at texture coordinates (u, v).
 *
 * A shader's <texture ref> replaces its diffuse colour k_d by the texture's
 * colour at the point's texture coordinates (docs/scenes.md): interpolated from
 * the mesh's vt (interpolate.h), or the sphere's own (sphere_uv.h).  The
 * texels were decoded once, when the scene was read (common/texture_image.h):
 * here they are only looked up.
 *
 * Texture space: u runs along the image from its left edge (u = 0) to its
 * right edge (u = 1), v from its BOTTOM edge (v = 0) to its top (v = 1).  In
 * texel units, x = u W across from the left and y = (1 - v) H down from the
 * top, and texel (i, j) (column i from the left, row j from the top) is
 * centred on (x, y) = (i, j): the texel nearest to (x, y) is (x + 1/2, y +
 * 1/2) with the fractions dropped.  This is how the course's solution reads
 * its textures (measured against its reference images: the README says how),
 * down to one quirk: dropping a fraction rounds towards zero, so for x < -1/2
 * the index is one more than the nearest texel's (texel 0 is read from x =
 * -3/2 to 1/2, the texels before it one column late).
 *
 * Outside the image the texture's type decides:
 *     RepeatTexture  the image repeats: column i is column i mod W (also for
 *                    negative i), so u and u + 1 look the same;
 *     ClampTexture   the edge texels stretch outwards: i < 0 reads column 0,
 *                    i >= W reads column W - 1.
 *
 * --texture-filter chooses how a colour is read between texel centres:
 *     nearest   the nearest texel: blocky where a texel covers many pixels
 *               (the course's images; the default);
 *     bilinear  the four texels whose centres surround (x, y), weighted by
 *               how close each is: smooth, and four texels to read.
 * Texels are used as stored, each byte / 255, as the course's solution did.
 */
#ifndef CH10_TEXTURE_H
#define CH10_TEXTURE_H

#include "color.h"
#include "mesh.h"
#include "scene.h"

typedef enum { TEXTURE_NEAREST, TEXTURE_BILINEAR } texture_filter;

/* The names of the filters, in enum order, NULL-terminated: the choices of --texture-filter. */
extern const char *const texture_filter_names[];

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
