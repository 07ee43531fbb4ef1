/* png_write.h - write an image as a PNG file, atomically.
 *
 * The PNG is written to a temporary file in the destination's folder and
 * renamed over the destination only when it is complete, so a failure never
 * leaves a truncated PNG and never clobbers an existing one.
 */
#ifndef RT_PNG_WRITE_H
#define RT_PNG_WRITE_H

#include <stddef.h>

#include "image.h"

/* Encodes every pixel with display_encode(L, exposure) and writes `path`.
 * Returns 0, or -1 with a message naming the path and the problem in err. */
int png_write(const image *img, real exposure, const char *path, char *err, size_t err_size);

#endif
