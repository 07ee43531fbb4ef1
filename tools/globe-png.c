/* globe-png.c - writes chapter 10's globe map (globe_texture, sphere_mesh.h) as a PNG.
 *
 *     globe-png FILE.png
 *
 * `make globe-texture` writes chapters/10_interpolation/scenes/globe.png with
 * it: 128 x 64 texels, a graticule every 8.  Chapter 10's suite checks that
 * the file and the map agree texel for texel.
 */
#include <stdio.h>

#include <stb_image_write.h>

#include "10_interpolation/scenes/sphere_mesh.h"

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: globe-png FILE.png\n");
        return 2;
    }
    texture_image t;
    if (globe_texture(&t, 128, 64, 8) != 0) {
        fprintf(stderr, "globe-png: out of memory\n");
        return 1;
    }
    int ok = stbi_write_png(argv[1], t.width, t.height, 3, t.rgb, t.width * 3);
    texture_image_free(&t);
    if (!ok) {
        fprintf(stderr, "globe-png: %s: cannot write it\n", argv[1]);
        return 1;
    }
    return 0;
}
