/* crossing_reference.h - chapter 03: where a ray crosses a triangle, for the
 * data exactly as they are stored, as a yardstick for the tests and the
 * measurements of false and lost hits.
 *
 * Cramer's rule in long double: the coordinates of the float build are
 * exact there, so are their differences, and the determinants carry an
 * error 2^11 times smaller than double's (on x86-64, whose long double has
 * 64 significant bits).
 */
#ifndef CH03_CROSSING_REFERENCE_H
#define CH03_CROSSING_REFERENCE_H

#include <stdbool.h>

#include "03_triangle/triangle.h"

typedef struct {
    long double t;     /* the crossing with the plane is at p + t d */
    long double beta, gamma; /* ... and a + beta (b - a) + gamma (c - a) */
    long double least;       /* the smallest of alpha, beta, gamma there: negative outside */
} crossing;

/* The crossing of r with the plane of tri; false when there is none that
 * long double can tell: M = det[a - b  a - c  d] not larger than its own
 * rounding error (a degenerate triangle, a ray along the plane). */
bool crossing_reference(const triangle *tri, ray r, crossing *x);

/* How far the hit h puts its point from the crossing x, in units of the
 * triangle's longest edge: |t - x.t| |d| + |beta - x.beta| |b - a| +
 * |gamma - x.gamma| |c - a|, each coordinate's part of the error. */
long double hit_error(const triangle *tri, ray r, triangle_hit h, const crossing *x);

/* The distance from the point p + t d to the triangle (the closed point set
 * of the data as stored), in units of the triangle's longest edge: 0 on it.
 * A degenerate triangle is the segment (or point) its vertices span. */
long double hit_distance(const triangle *tri, ray r, long double t);

#endif
