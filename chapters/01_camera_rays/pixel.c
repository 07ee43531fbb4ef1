/* pixel.c - chapter 01: from a pixel to a position on the image. */
#include "01_camera_rays/pixel.h"
#include "exercise.h"

/* snippet: pixel_to_image */
void pixel_to_image(int i, int j, int nx, int ny, real du, real dv, real *u, real *v)
{
    /* TODO pixel: the pixel-to-image mapping (lecture, "Pixel-to-image mapping"):
     *     u = (i + du) / n_x,   v = (j + dv) / n_y
     * (du, dv) is the sample's place inside the pixel; one sample per pixel takes its centre,
     * du = dv = 0.5, which is the lecture's u = (i + 0.5)/n_x, v = (j + 0.5)/n_y.
     * i counts columns (along u, to the right), j rows (along v, upwards: j = 0 is the bottom row). */
    EXERCISE_STUB("01_camera_rays", "pixel.c", "pixel"); /* delete this line when done */
    (void)i;
    (void)j;
    (void)nx;
    (void)ny;
    (void)du;
    (void)dv;
    *u = *v = (real)0.5;
}
/* end snippet */
