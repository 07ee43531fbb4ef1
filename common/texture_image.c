#include "texture_image.h"

#include <limits.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb_image.h>

#include "input_file.h"

static uint32_t big_endian32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | (uint32_t)p[3];
}

/* Walks the PNG's chunks (length, type, data, CRC) up to IEND.  Returns NULL
 * when each fits in the file, else what is wrong.  stb_image 2.27 trusts a
 * chunk's length: a 100-byte file whose IDAT claims 1.6 GB makes it allocate
 * that much, and an empty first IDAT makes it add 0 to a null pointer,
 * undefined behaviour (both found by fuzz/texture.c). */
static const char *png_chunks_problem(const unsigned char *bytes, size_t size, char *problem, size_t problem_size)
{
    size_t offset = 8;
    bool seen_data = false;
    while (size - offset >= 12) {
        uint32_t length = big_endian32(bytes + offset);
        if (length > size - offset - 12) {
            snprintf(problem, problem_size, "the image is broken: its chunk '%.4s' claims %lu bytes, more than the "
                     "file holds", (const char *)bytes + offset + 4, (unsigned long)length);
            return problem;
        }
        if (memcmp(bytes + offset + 4, "IEND", 4) == 0)
            return NULL;
        if (memcmp(bytes + offset + 4, "IDAT", 4) == 0) {
            if (length == 0 && !seen_data) {
                snprintf(problem, problem_size, "the image is broken: its first IDAT chunk is empty");
                return problem;
            }
            seen_data = true;
        }
        offset += 12 + (size_t)length;
    }
    snprintf(problem, problem_size, "the image is broken: it ends before its IEND chunk (cut short?)");
    return problem;
}

int texture_image_decode(const unsigned char *bytes, size_t size, texture_image *t, char *problem,
                         size_t problem_size)
{
    *t = (texture_image){0};
    if (size == 0 || size > (size_t)INT_MAX) {
        snprintf(problem, problem_size, "%s", size ? "the file is too large" : "the file is empty");
        return -1;
    }
    /* PNG only, as docs/scenes.md says: it is the one format whose decoder in
     * stb_image notices a file cut short (the zlib stream ends early).  Its
     * JPEG, BMP and TGA decoders read missing bytes as zeros, its PNM decoder
     * leaves them undefined, and (found by fuzz/texture.c, stb_image 2.27)
     * a 16-bit PNM overflows a buffer. */
    static const unsigned char png_signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (size < sizeof png_signature || memcmp(bytes, png_signature, sizeof png_signature) != 0) {
        snprintf(problem, problem_size, "not a PNG file (a texture image is a PNG)");
        return -1;
    }
    if (png_chunks_problem(bytes, size, problem, problem_size))
        return -1;
    /* The header next: refuse a huge image before allocating for it. */
    int width, height, channels;
    if (!stbi_info_from_memory(bytes, (int)size, &width, &height, &channels)) {
        snprintf(problem, problem_size, "not an image that can be read (%s)", stbi_failure_reason());
        return -1;
    }
    if (width < 1 || height < 1 || width > TEXTURE_MAX_SIDE || height > TEXTURE_MAX_SIDE ||
        (long long)width * height > TEXTURE_MAX_TEXELS) {
        snprintf(problem, problem_size,
                 "the image is %d x %d texels; a texture may have sides up to %d and %lld texels in all", width,
                 height, TEXTURE_MAX_SIDE, TEXTURE_MAX_TEXELS);
        return -1;
    }
    /* Then every texel: a file cut short or corrupt inside fails here. */
    int w, h;
    unsigned char *rgb = stbi_load_from_memory(bytes, (int)size, &w, &h, &channels, 3);
    if (!rgb) {
        snprintf(problem, problem_size, "the image is broken: %s", stbi_failure_reason());
        return -1;
    }
    if (w != width || h != height) { /* the header said otherwise */
        stbi_image_free(rgb);
        snprintf(problem, problem_size, "the image is broken: its size changes while it is decoded");
        return -1;
    }
    t->width = w;
    t->height = h;
    t->rgb = rgb;
    return 0;
}

int texture_image_load(const char *path, texture_image *t, char *err, size_t err_size)
{
    *t = (texture_image){0};
    unsigned char *bytes;
    size_t size;
    if (input_file_read_all(path, "the texture image", TEXTURE_MAX_FILE_BYTES, &bytes, &size, err, err_size) != 0)
        return -1;
    char problem[256];
    int status = texture_image_decode(bytes, size, t, problem, sizeof problem);
    free(bytes);
    if (status != 0)
        snprintf(err, err_size, "%s: %s", path, problem);
    return status;
}

void texture_image_free(texture_image *t)
{
    stbi_image_free(t->rgb);
    *t = (texture_image){0};
}

color texture_image_outside(const texture_image *t, int x, int y)
{
    int cx = x < 0 ? 0 : x >= t->width ? t->width - 1 : x;
    int cy = y < 0 ? 0 : y >= t->height ? t->height - 1 : y;
    static atomic_flag told = ATOMIC_FLAG_INIT;
    if (!atomic_flag_test_and_set(&told))
        fprintf(stderr,
                "texture_image_texel: texel (%d, %d) is outside the %d x %d image (columns 0 to %d, rows 0 to %d): "
                "an index not wrapped into the image; texel (%d, %d) read instead\n",
                x, y, t->width, t->height, t->width - 1, t->height - 1, cx, cy);
    return texture_image_texel(t, cx, cy);
}
