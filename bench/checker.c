/* checker.c - the checkerboard texture of the bench's scene.
 *
 *     checker N SQUARES OUT.png
 *
 * writes an N x N PNG of SQUARES x SQUARES squares in two colours, with a
 * thin darker line around each square, so that texture filtering and
 * texture coordinates show in the renders (bench/scenes/checker.png).
 */
#include <stdio.h>
#include <stdlib.h>

#include <stb_image_write.h>

int main(int argc, char **argv)
{
    int n = argc == 4 ? atoi(argv[1]) : 0, squares = argc == 4 ? atoi(argv[2]) : 0;
    if (n < 2 || n > 4096 || squares < 1 || squares > n) {
        fprintf(stderr, "usage: checker N SQUARES OUT.png (2 <= N <= 4096, 1 <= SQUARES <= N)\n");
        return 2;
    }
    unsigned char *px = malloc((size_t)n * (size_t)n * 3);
    if (!px)
        return 1;
    static const unsigned char light[3] = {235, 225, 200}, dark[3] = {60, 90, 140}, line[3] = {30, 30, 30};
    for (int y = 0; y < n; y++) {
        for (int x = 0; x < n; x++) {
            int sx = x * squares / n, sy = y * squares / n;
            int edge = (x * squares) % n < squares || (y * squares) % n < squares;
            const unsigned char *c = edge ? line : (sx + sy) % 2 ? dark : light;
            for (int k = 0; k < 3; k++)
                px[3 * ((size_t)y * (size_t)n + (size_t)x) + (size_t)k] = c[k];
        }
    }
    int ok = stbi_write_png(argv[3], n, n, 3, px, n * 3);
    free(px);
    if (!ok) {
        fprintf(stderr, "checker: cannot write %s\n", argv[3]);
        return 1;
    }
    return 0;
}
