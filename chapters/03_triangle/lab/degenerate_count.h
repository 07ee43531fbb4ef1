/* degenerate_count.h - chapter 03's lab: measuring false hits on degenerate
 * triangles and in-plane rays, and lost hits on proper triangles.
 *
 * The data are random (a fixed seed: the same on every run), rotated,
 * scaled from 1e-3 to 1e3 and, for half of the cases, translated up to 1e4
 * times the triangle's size from the origin, so that no arithmetic is exact.
 * lab --degenerate=N prints the counts (lab/README.md has them).
 */
#ifndef CH03_DEGENERATE_COUNT_H
#define CH03_DEGENERATE_COUNT_H

#include "03_triangle/triangle.h"

typedef struct {
    long degenerate_rays, degenerate_hits; /* at collinear (rounded) or coincident vertices */
    double degenerate_worst;               /* largest |p + t d - x| of such a hit, in edge lengths */
    long plane_rays, plane_hits;           /* rays in the plane x + y + z = 0 */
    double plane_worst;
    long clear_hits, lost_hits; /* proper triangles: points 1 % inside by a long-double reference */
} degenerate_count;

/* n cases of each kind, with the chosen test. */
degenerate_count degenerate_counts(long n, triangle_test test);

#endif
