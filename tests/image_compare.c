#include "image_compare.h"

#include <stdio.h>
#include <stdlib.h>

#include <stb_image.h>

#include "display.h"

int image_compare_png(const image *img, real exposure, const char *png_path, int tolerance, image_diff *diff,
                      char *err, size_t err_size)
{
    int width, height, channels;
    unsigned char *ref = stbi_load(png_path, &width, &height, &channels, 3);
    if (!ref) {
        snprintf(err, err_size, "%s: cannot read the PNG (%s)", png_path, stbi_failure_reason());
        return -1;
    }
    if (width != img->width || height != img->height) {
        snprintf(err, err_size, "%s: %dx%d, but the rendered image is %dx%d", png_path, width, height, img->width,
                 img->height);
        stbi_image_free(ref);
        return -1;
    }
    *diff = (image_diff){.bytes = 3L * width * height, .max_x = -1, .max_y = -1, .x0 = -1, .y0 = -1, .x1 = -1,
                         .y1 = -1};
    for (int y = 0; y < height; y++) {
        int j = height - 1 - y; /* PNG rows go down, the image's j goes up (image.h) */
        for (int x = 0; x < width; x++) {
            color c = *image_at(img, x, j);
            const unsigned char ours[3] = {display_encode(c.r, exposure), display_encode(c.g, exposure),
                                           display_encode(c.b, exposure)};
            const unsigned char *theirs = ref + 3 * ((long)y * width + x);
            int off = 0;
            for (int k = 0; k < 3; k++) {
                int d = abs((int)ours[k] - (int)theirs[k]);
                if (d <= tolerance)
                    diff->within++;
                else
                    off = 1;
                if (d > diff->max_diff) {
                    diff->max_diff = d;
                    diff->max_x = x;
                    diff->max_y = y;
                }
            }
            if (off) {
                diff->pixels_off++;
                if (diff->x0 < 0 || x < diff->x0)
                    diff->x0 = x;
                if (x > diff->x1)
                    diff->x1 = x;
                if (diff->y0 < 0)
                    diff->y0 = y;
                diff->y1 = y;
            }
        }
    }
    stbi_image_free(ref);
    return 0;
}

double image_diff_percent(const image_diff *diff)
{
    return diff->bytes ? 100.0 * (double)diff->within / (double)diff->bytes : 100.0;
}
