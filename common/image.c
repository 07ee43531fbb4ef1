#include "image.h"

#include <stdlib.h>

int image_init(image *img, int width, int height)
{
    img->width = width;
    img->height = height;
    img->pixels = calloc((size_t)width * (size_t)height, sizeof *img->pixels);
    return img->pixels ? 0 : -1;
}

void image_free(image *img)
{
    free(img->pixels);
    img->pixels = NULL;
}
