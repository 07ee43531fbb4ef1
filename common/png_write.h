/* png_write.h - write an image as a PNG file, atomically.
 *
 * The PNG is written to a temporary file in the destination's folder and
 * renamed over the destination only when it is complete, so a failure never
 * leaves a truncated PNG and never clobbers an existing one.  The destination
 * is a new path or a regular file: a FIFO, a device or a directory there is
 * left alone and the write refused, saying what is there.
 */
#ifndef RT_PNG_WRITE_H
#define RT_PNG_WRITE_H

#include <stddef.h>
#include <stdint.h>

#include "image.h"

/* Whether `path` may be written: it does not exist, or is a regular file (a
 * symbolic link counts as what it points to).  Returns 0, or -1 with "path:
 * problem" in err.  Renderers ask before rendering, so as to fail at once. */
int png_check_output(const char *path, char *err, size_t err_size);

/* Encodes every pixel with display_encode(L, exposure) and writes `path`.
 * Returns 0, or -1 with a message naming the path and the problem in err
 * (png_check_output's refusal included). */
int png_write(const image *img, real exposure, const char *path, char *err, size_t err_size);

/* Writes RGB bytes (3 a pixel, top row first) as the PNG `path`, as
 * png_write does.  Returns 0, or -1 with the problem in err. */
int png_write_rgb(const uint8_t *bytes, int width, int height, const char *path, char *err, size_t err_size);

#endif
