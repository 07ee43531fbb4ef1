/* tessellate.c - a sphere as a triangle mesh, for the bench.
 *
 *     tessellate N OUT.obj [CX CY CZ R]
 *
 * writes a sphere (the unit sphere at the origin unless centre and radius are
 * given) as a latitude-longitude mesh of about N
 * triangles (S stacks and 2S slices: 4S(S - 1) triangles, S chosen nearest to
 * N), with per-vertex normals and texture coordinates, and prints the number
 * of triangles written.  The growth measurement renders these from 100 to a
 * million triangles; the one-scene-through-all-stages scene uses a small one.
 */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    char *end;
    long n = argc == 3 || argc == 7 ? strtol(argv[1], &end, 10) : 0;
    double centre[3] = {0, 0, 0}, radius = 1;
    bool ok = (argc == 3 || argc == 7) && !*end && n >= 8 && n <= 100000000;
    for (int k = 0; ok && argc == 7 && k < 4; k++) {
        double value = strtod(argv[3 + k], &end);
        ok = *end == '\0' && end != argv[3 + k] && isfinite(value);
        if (k < 3)
            centre[k] = value;
        else
            radius = value;
    }
    if (!ok || !(radius > 0)) {
        fprintf(stderr, "usage: tessellate N OUT.obj [CX CY CZ R] (N triangles, 8 to 1e8; R > 0)\n");
        return 2;
    }
    long stacks = 2;
    while (4 * (stacks + 1) * stacks < n)
        stacks++;
    if (llabs(4 * (stacks + 1) * stacks - n) < llabs(4 * stacks * (stacks - 1) - n))
        stacks++;
    long slices = 2 * stacks;
    FILE *f = fopen(argv[2], "w");
    if (!f) {
        perror(argv[2]);
        return 1;
    }
    const double pi = 3.14159265358979323846;
    /* Vertices: the two poles, then (stacks - 1) rings of (slices + 1): the seam is duplicated so that
     * texture coordinates run from 0 to 1. */
    fprintf(f, "# sphere (centre %g %g %g, radius %g), %ld stacks, %ld slices\n", centre[0], centre[1], centre[2],
            radius, stacks, slices);
    fprintf(f, "v %.9g %.9g %.9g\nvn 0 1 0\nvt 0.5 1\n", centre[0], centre[1] + radius, centre[2]);
    fprintf(f, "v %.9g %.9g %.9g\nvn 0 -1 0\nvt 0.5 0\n", centre[0], centre[1] - radius, centre[2]);
    for (long i = 1; i < stacks; i++) {
        double theta = pi * (double)i / (double)stacks;
        for (long k = 0; k <= slices; k++) {
            double phi = 2 * pi * (double)k / (double)slices;
            double x = sin(theta) * cos(phi), y = cos(theta), z = -sin(theta) * sin(phi);
            fprintf(f, "v %.9g %.9g %.9g\nvn %.9g %.9g %.9g\nvt %.9g %.9g\n", centre[0] + radius * x,
                    centre[1] + radius * y, centre[2] + radius * z, x, y, z,
                    (double)k / (double)slices, 1 - (double)i / (double)stacks);
        }
    }
    /* OBJ indices from 1: north pole 1, south pole 2, ring i (1-based) vertex k at 3 + (i-1)(slices+1) + k. */
#define RING(i, k) (3 + ((i) - 1) * (slices + 1) + (k))
    long triangles = 0;
    for (long k = 0; k < slices; k++) {
        fprintf(f, "f 1/1/1 %ld/%ld/%ld %ld/%ld/%ld\n", RING(1, k), RING(1, k), RING(1, k), RING(1, k + 1),
                RING(1, k + 1), RING(1, k + 1));
        long a = RING(stacks - 1, k), b = RING(stacks - 1, k + 1);
        fprintf(f, "f 2/2/2 %ld/%ld/%ld %ld/%ld/%ld\n", b, b, b, a, a, a);
        triangles += 2;
    }
    for (long i = 1; i + 1 < stacks; i++) {
        for (long k = 0; k < slices; k++) {
            long a = RING(i, k), b = RING(i, k + 1), c = RING(i + 1, k), d = RING(i + 1, k + 1);
            fprintf(f, "f %ld/%ld/%ld %ld/%ld/%ld %ld/%ld/%ld\n", a, a, a, c, c, c, d, d, d);
            fprintf(f, "f %ld/%ld/%ld %ld/%ld/%ld %ld/%ld/%ld\n", a, a, a, d, d, d, b, b, b);
            triangles += 2;
        }
    }
    if (fclose(f) != 0) {
        perror(argv[2]);
        return 1;
    }
    printf("%ld\n", triangles);
    return 0;
}
