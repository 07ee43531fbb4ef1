/* closeup-png.c - writes the texture of chapter 10's close-up figure (scenes/closeup.xml).
 *
 *     closeup-png FILE.png
 *
 * `make closeup-texture` writes chapters/10_interpolation/scenes/closeup.png
 * with it: 16 x 16 texels, a red disc of radius 5.5 texels on a blue ground
 * and a white stripe at 30 degrees across it.  Its edges run across the texel
 * grid, not along it, so that magnified, the nearest texel shows them as
 * staircases of blocks and the bilinear lookup as smooth ramps.  The colours
 * are linear values times 255, as every texture here.
 */
#include <math.h>
#include <stdio.h>

#include <stb_image_write.h>

enum { SIDE = 16 };

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: closeup-png FILE.png\n");
        return 2;
    }
    static unsigned char rgb[SIDE * SIDE * 3];
    const double s = sin(30 * 3.14159265358979323846 / 180), c = cos(30 * 3.14159265358979323846 / 180);
    for (int y = 0; y < SIDE; y++)
        for (int x = 0; x < SIDE; x++) {
            double px = x + 0.5 - SIDE / 2.0, py = y + 0.5 - SIDE / 2.0; /* the texel's centre */
            unsigned char colour[3] = {60, 120, 200};                   /* the ground */
            if (px * px + py * py < 5.5 * 5.5) {                         /* the disc */
                colour[0] = 210, colour[1] = 60, colour[2] = 40;
            }
            if (fabs(-s * px + c * py - 3) < 1.2) { /* the stripe: 2.4 texels wide, 3 below the centre */
                colour[0] = colour[1] = colour[2] = 235;
            }
            for (int k = 0; k < 3; k++)
                rgb[(y * SIDE + x) * 3 + k] = colour[k];
        }
    if (!stbi_write_png(argv[1], SIDE, SIDE, 3, rgb, SIDE * 3)) {
        fprintf(stderr, "closeup-png: %s: cannot write it\n", argv[1]);
        return 1;
    }
    return 0;
}
