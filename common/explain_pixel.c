/* explain_pixel.c - --explain X,Y: the pixel computed again, with the recorder on. */
#include <stdlib.h>
#include <string.h>

#include "display.h"
#include "explain_tree.h"

/* "(R, G, B)" bytes of linear radiance L at `exposure`, by the PNG's own encoding. */
static void encode(color L, real exposure, uint8_t bytes[3])
{
    bytes[0] = display_encode(L.r, exposure);
    bytes[1] = display_encode(L.g, exposure);
    bytes[2] = display_encode(L.b, exposure);
}

static bool same(color a, color b)
{
    return memcmp(&a.r, &b.r, sizeof a.r) == 0 && memcmp(&a.g, &b.g, sizeof a.g) == 0 &&
           memcmp(&a.b, &b.b, sizeof a.b) == 0;
}

int explain_pixel(sample_fn sample, const void *prepared, const render_options *opt, pixel_map_fn map,
                  const image *img, const scene *desc, FILE *out, char *err, size_t err_size)
{
    const int nx = img->width, ny = img->height;
    const int i = opt->explain_x, j = ny - 1 - opt->explain_y; /* the lecture counts rows from the bottom */
    char root[400];
    snprintf(root, sizeof root, "pixel (%d, %d) of the %dx%d image, from its top-left corner: the lecture's pixel (i, j) = "
             "(%d, %d), rows counted from the bottom", opt->explain_x, opt->explain_y, nx, ny, i, j);
    explainer e;
    explain_init(&e, desc, root);
    explain_now = &e;
    uint64_t rays[RAY_KINDS] = {0}, nonfinite = 0;
    color L = render_pixel(sample, prepared, opt, map, i, j, nx, ny, rays, &nonfinite);
    explain_now = NULL;

    uint8_t bytes[3], held[3];
    color in_image = *image_at(img, i, j);
    encode(L, desc->exposure, bytes);
    encode(in_image, desc->exposure, held);
    explain_write_text(&e, out);
    char c[96];
    int n = opt->samples > 0 ? opt->samples : 1;
    fprintf(out, "pixel value L = %s, the mean of %d sample%s%s\n", explain_color(c, sizeof c, L), n, n == 1 ? "" : "s",
            nonfinite ? " (non-finite samples left out: see --nonfinite)" : "");
    fprintf(out, "display: byte = round(255 clamp((exposure L)^(1/2.2), 0, 1)) with exposure %.6g: (%d, %d, %d)\n",
            (double)desc->exposure, bytes[0], bytes[1], bytes[2]);
    if (same(L, in_image) && memcmp(bytes, held, 3) == 0)
        fprintf(out, "the image holds (%d, %d, %d) at (%d, %d): the same\n", held[0], held[1], held[2], opt->explain_x,
                opt->explain_y);
    else
        fprintf(out, "the image holds (%d, %d, %d) at (%d, %d), from L = %s: NOT the same\n", held[0], held[1], held[2],
                opt->explain_x, opt->explain_y, explain_color(c, sizeof c, in_image));

    int status = 0;
    if (opt->explain_json) {
        char pixel[600];
        snprintf(pixel, sizeof pixel,
                 "{\"x\": %d, \"y\": %d, \"i\": %d, \"j\": %d, \"width\": %d, \"height\": %d, \"samples\": %d, "
                 "\"L\": [%.17g, %.17g, %.17g], \"exposure\": %.17g, \"bytes\": [%d, %d, %d], \"image_bytes\": [%d, %d, %d]}",
                 opt->explain_x, opt->explain_y, i, j, nx, ny, n, (double)L.r, (double)L.g, (double)L.b,
                 (double)desc->exposure, bytes[0], bytes[1], bytes[2], held[0], held[1], held[2]);
        status = explain_write_json(&e, opt->explain_json, pixel, err, err_size);
    }
    if (status == 0 && opt->explain_picture)
        status = explain_write_picture(&e, img, desc->exposure, opt->explain_x, opt->explain_y, opt->explain_picture,
                                       err, err_size);
    free(e.nodes);
    return status;
}
