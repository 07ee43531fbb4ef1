/* crossing.h - is the crossing of a ray and a triangle's plane decided by the
 * data, or only by rounding?
 *
 * Cramer's rule for the ray p + t d and the triangle a, b, c divides by
 * M = det[a - b   a - c   d], which is zero for a degenerate triangle
 * (collinear or coincident vertices) and a ray parallel to its plane.  With
 * coordinates that are not small integers rounding leaves a tiny M of either
 * sign there, and the quotients are noise that may pass the inside test.
 * This check compares |M| and the numerator of t, N = det[a - b   a - c   a - p],
 * with bounds on the rounding error they may carry (the derivation is in
 * crossing.c); the bounds scale with the data, so there is no absolute
 * epsilon.  Chapter 03's two triangle tests apply it to their hits.
 */
#ifndef RT_CROSSING_H
#define RT_CROSSING_H

#include <stdbool.h>

#include "ray.h"

/* The share of a triangle's size (its largest edge component) within which
 * Cramer's rule in real arithmetic must be certain to place a hit point. */
#define TRIANGLE_POINT_SLACK 0x1p-3

/* The first of the tests below, on the data as they are stored (no scaling
 * by powers of two): true only where triangle_crossing_certain_exact is
 * true, for any input (crossing.c proves it), and true for a clear crossing
 * (a triangle that is not a sliver, a ray not nearly in its plane, an origin
 * not nearly in it) whose coordinates' magnitudes sum below 2^100 and whose
 * determinants are far above 2^-250 (its suite counts those it takes).
 * Where it is false the scaled test decides.  Inline, in crossing_clear.h:
 *     bool triangle_crossing_clear(const vec3 *a, const vec3 *b, const vec3 *c, ray r); */
#include "crossing_clear.h"

/* Where the quick test cannot decide: the data scaled by powers of two, then
 * a quick test and the full check on them. */
bool triangle_crossing_scaled(const vec3 *a, const vec3 *b, const vec3 *c, ray r);

/* The same answer as triangle_crossing_certain, always computed in full.
 * (The tests compare the two.) */
bool triangle_crossing_certain_exact(const vec3 *a, const vec3 *b, const vec3 *c, ray r);

/* Whether r crosses the plane of the triangle *a, *b, *c at a t that the data
 * decide: false when |M| or |N| is not larger than the rounding error it may
 * carry (a degenerate or nearly degenerate triangle, a direction in or
 * parallel to the plane, an origin in the plane), for non-finite data, and
 * when rounding may put the hit point further than TRIANGLE_POINT_SLACK of
 * the triangle's size from where the data put it.  The data are taken as
 * they are stored: a crossing that the arithmetic decides counts at any
 * distance from the origin.  The quick test first, inline: it settles every
 * clear hit without a call (a triangle test ends with this check on a hit). */
static inline bool triangle_crossing_certain(const vec3 *a, const vec3 *b, const vec3 *c, ray r)
{
    return triangle_crossing_clear(a, b, c, r) || triangle_crossing_scaled(a, b, c, r);
}

#endif
