/* pixel.c - chapter 01: from a pixel to a position on the image. */
#include "01_camera_rays/pixel.h"
#include "exercise.h"

void pixel_to_image(int i, int j, int nx, int ny, real du, real dv, real *u, real *v)
{
    /* TODO pixel: the image position (u, v) in [0, 1]^2 of the sample at (du, dv) inside pixel (i, j)
     * (README, "From pixels to the image rectangle"). */
    EXERCISE_STUB("01_camera_rays", "pixel.c", "pixel"); /* delete this line when done */
    (void)i, (void)j, (void)nx, (void)ny, (void)du, (void)dv;
    *u = *v = (real)0.5;
}
