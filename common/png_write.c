#include "png_write.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stb_image_write.h>

#include "display.h"
#include "output_file.h"

typedef struct {
    FILE *file;
    int failed;
} png_sink;

static void sink_write(void *context, void *data, int size)
{
    png_sink *sink = context;
    if (!sink->failed && fwrite(data, 1, (size_t)size, sink->file) != (size_t)size)
        sink->failed = 1;
}

/* Display bytes, top row first, as PNG wants them. */
static uint8_t *encode_rows(const image *img, real exposure)
{
    uint8_t *bytes = malloc((size_t)img->width * (size_t)img->height * 3);
    if (!bytes)
        return NULL;
    for (int j = 0; j < img->height; j++) {
        uint8_t *row = bytes + (size_t)(img->height - 1 - j) * (size_t)img->width * 3;
        for (int i = 0; i < img->width; i++) {
            color c = *image_at(img, i, j);
            row[3 * i + 0] = display_encode(c.r, exposure);
            row[3 * i + 1] = display_encode(c.g, exposure);
            row[3 * i + 2] = display_encode(c.b, exposure);
        }
    }
    return bytes;
}

int png_check_output(const char *path, char *err, size_t err_size)
{
    struct stat st;
    if (stat(path, &st) != 0)
        return 0; /* a new path (or one that mkstemp will name the problem of) */
    if (S_ISREG(st.st_mode))
        return 0;
    const char *kind = S_ISDIR(st.st_mode)    ? "a directory"
                       : S_ISFIFO(st.st_mode) ? "a FIFO"
                       : S_ISCHR(st.st_mode)  ? "a character device"
                       : S_ISBLK(st.st_mode)  ? "a block device"
                       : S_ISSOCK(st.st_mode) ? "a socket"
                                              : "not a plain file";
    snprintf(err, err_size, "%s: not written: it is %s, and the image goes only to a regular file or a new path",
             path, kind);
    return -1;
}

int png_write_rgb(const uint8_t *bytes, int width, int height, const char *path, char *err, size_t err_size)
{
    output_file f;
    if (output_open(&f, path, err, err_size) != 0)
        return -1;
    png_sink sink = {f.file, 0};
    int encoded = stbi_write_png_to_func(sink_write, &sink, width, height, 3, bytes, width * 3);
    return output_close(&f, !encoded || sink.failed, "the PNG", err, err_size);
}

int png_write(const image *img, real exposure, const char *path, char *err, size_t err_size)
{
    if (png_check_output(path, err, err_size) != 0)
        return -1;
    uint8_t *bytes = encode_rows(img, exposure);
    if (!bytes) {
        snprintf(err, err_size, "%s: out of memory", path);
        return -1;
    }
    int status = png_write_rgb(bytes, img->width, img->height, path, err, err_size);
    free(bytes);
    return status;
}
