/* degenerate.h - chapter 03: is the crossing of a ray and a triangle's plane
 * decided by the data, or only by rounding?
 *
 * M = det[a - b   a - c   d] is zero when the triangle is degenerate
 * (collinear or coincident vertices) or the ray is parallel to its plane.
 * With coordinates that are not small integers it is rarely exactly zero
 * there: rounding leaves a tiny M of either sign, and dividing by it gives a
 * meaningless beta, gamma and t that may pass the inside test.  This check
 * compares |M|, and the numerator of t, with a bound on the error that
 * rounding can put into them (the derivation is in degenerate.c), so that a
 * hit counts only when both signs are certain and its point is placed to
 * within an eighth of the triangle.  It uses no absolute epsilon: the bound scales with
 * the data, so a triangle of any size at any place is treated alike.
 */
#ifndef CH03_DEGENERATE_H
#define CH03_DEGENERATE_H

#include <stdbool.h>

#include "03_triangle/triangle.h"

/* The share of a triangle's size (its largest edge component) within which
 * Cramer's rule in real arithmetic must be certain to place a hit point for
 * triangle_crossing_certain to accept it. */
#define TRIANGLE_POINT_SLACK 0x1p-3

/* Whether r crosses the plane of tri at a t that the data decide: false
 * when M = det[a - b   a - c   d] or the numerator of t,
 * det[a - b   a - c   a - p], is not larger than the rounding error it may
 * carry, that is for a degenerate triangle (collinear or coincident
 * vertices, or so nearly so that rounding cannot tell), for a direction in
 * or parallel to the triangle's plane, for an origin in the plane, and for
 * non-finite data; and false when rounding may put the hit point further
 * than TRIANGLE_POINT_SLACK of the triangle's size from where the data put
 * it (a triangle so thin that beta and gamma are noise).  The data are
 * taken as they are stored: a crossing that the arithmetic decides counts
 * at any distance from the origin. */
bool triangle_crossing_certain(const triangle *tri, ray r);

/* The same answer, always computed in full: triangle_crossing_certain first
 * tries a cheaper sufficient test and calls this one only where that test
 * cannot decide.  (The tests compare the two.) */
bool triangle_crossing_certain_exact(const triangle *tri, ray r);

#endif
