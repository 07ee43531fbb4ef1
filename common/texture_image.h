/* texture_image.h - a texture's texels, decoded once when the scene is read.
 *
 * The scene reader decodes the image of every <texture> fully, here, with
 * stb_image, and keeps the texels in the scene description
 * (scene_texture.image).  The image is a PNG file (docs/scenes.md), the one format
 * whose decoder notices a file cut short (texture_image.c says why).  So a broken image (a PNG cut
 * short, say) is refused with the scene's file and line before anything is
 * rendered, and a renderer looks texels up here and never reads a file.
 *
 * Texels are stored as read, 8 bits per channel (a 16-bit PNG keeps its high
 * byte), always three channels (a grey or paletted image is expanded, alpha
 * is dropped).  Texel (x, y): x
 * counts columns from the left, y counts rows from the TOP, as the file
 * stores them; mapping texture coordinates (u, v) to (x, y), and repeating
 * or clamping them, is the texture's business (chapter 10), not this file's.
 */
#ifndef RT_TEXTURE_IMAGE_H
#define RT_TEXTURE_IMAGE_H

#include <stddef.h>

#include "color.h"

/* What one texture may hold, checked from the header before decoding. */
#define TEXTURE_MAX_FILE_BYTES (256LL << 20)
#define TEXTURE_MAX_SIDE 16384
#define TEXTURE_MAX_TEXELS (1LL << 26) /* width * height: 8192 x 8192, 192 MB of texels */

typedef struct {
    int width, height;  /* from 1 to TEXTURE_MAX_SIDE each */
    unsigned char *rgb; /* width * height * 3 bytes, row by row from the top row */
} texture_image;

/* Decodes an image file's bytes.  Returns 0, or -1 with the problem in
 * `problem` (t left empty: nothing to free). */
int texture_image_decode(const unsigned char *bytes, size_t size, texture_image *t, char *problem,
                         size_t problem_size);

/* Reads and decodes `path`, which must be a regular file.  Returns 0, or -1
 * with "path: problem" in err (t left empty). */
int texture_image_load(const char *path, texture_image *t, char *err, size_t err_size);

void texture_image_free(texture_image *t);

/* The edge texel nearest to (x, y), an index outside the image; the first
 * such read of the process says on stderr which index, in which image. */
color texture_image_outside(const texture_image *t, int x, int y);

/* The texel at column x, row y from the top (0 <= x < width, 0 <= y <
 * height), each channel byte / 255: the stored value, with no gamma taken off.
 * An index outside the image (a column or row not wrapped into it) is never
 * read: texture_image_outside clamps it and says so. */
static inline color texture_image_texel(const texture_image *t, int x, int y)
{
    if (x < 0 || x >= t->width || y < 0 || y >= t->height)
        return texture_image_outside(t, x, y);
    const unsigned char *p = t->rgb + ((size_t)y * (size_t)t->width + (size_t)x) * 3;
    return color_make((real)p[0] / 255, (real)p[1] / 255, (real)p[2] / 255);
}

#endif
