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
    long degenerate_false;                 /* of those hits, the ones the data do not have */
    double degenerate_worst;               /* largest |p + t d - x| of such a hit, in edge lengths */
    long plane_rays, plane_hits, plane_false; /* rays in the plane x + y + z = 0 */
    double plane_worst;
    double worst_off; /* the largest distance of any of those hits from the triangle, in edge lengths */
    long clear_hits, lost_hits; /* proper triangles: points 1 % inside by a long-double reference,
                                 * found by Cramer's rule in real arithmetic without the check */
} degenerate_count;

/* n cases of each kind, with the chosen test.  The false hits are those of
 * crossing_agrees (crossing_reference.h) with a slack of 1 %: the data as
 * stored put the crossing elsewhere, or have none.  A triangle whose third
 * vertex was rounded off the line of the other two is a thin one for the
 * data, and a ray may well cross it. */
degenerate_count degenerate_counts(long n, triangle_test test);

/* The same with every triangle of size 1 (edges up to 2.6) at `distance`
 * from the origin, in a random direction; distance < 0: as
 * degenerate_counts. */
degenerate_count degenerate_counts_at(long n, triangle_test test, double distance);

#endif
