/* triangle.h - chapter 03: where a ray meets a triangle.
 *
 * The lecture's "Barycentric ray-triangle intersection": every point of the
 * triangle's plane is a + beta (b - a) + gamma (c - a); on the ray it is also
 * p + t d.  Setting them equal gives three linear equations in beta, gamma
 * and t, solved at once by Cramer's rule.
 *
 * Edges are closed: a point with beta >= 0, gamma >= 0, beta + gamma <= 1 is
 * inside, so a point exactly on an edge that two triangles share belongs to
 * both and a ray through it may report either (the closest-hit search of
 * chapter 04 keeps one, with the same t).  The lecture's strict test
 * (beta > 0 ...) would leave every shared edge a hole; closing the edges
 * removes those holes on paper, but rounding can still let a ray slip
 * between two triangles: see TRIANGLE_WATERTIGHT and the chapter's README.
 */
#ifndef CH03_TRIANGLE_H
#define CH03_TRIANGLE_H

#include <stdbool.h>

#include "ray.h"

/* snippet: triangle */
typedef struct {
    vec3 a, b, c; /* the vertices; (b - a) x (c - a) is the front side's normal */
} triangle;

/* The triangle test knob, --triangle. */
typedef enum {
    TRIANGLE_CRAMER,     /* the lecture's 3x3 system by Cramer's rule (chapter 03's default) */
    TRIANGLE_WATERTIGHT, /* Woop, Benthin and Wald (2013): no ray slips between two triangles;
                          * the default from chapter 04 on */
} triangle_test;

typedef struct {
    real t;           /* the hit point is p + t d */
    real beta, gamma; /* ... and a + beta (b - a) + gamma (c - a); alpha = 1 - beta - gamma */
} triangle_hit;
/* end snippet */

/* The hit of r with tri in the open window (t_min, t_max); false when none.
 * Both sides of the triangle are hit.  A ray parallel to the triangle's
 * plane (or lying in it), a ray that starts in the plane, and a degenerate
 * triangle (collinear or coincident vertices) are misses, also when rounding
 * makes their determinant not quite zero (degenerate.h); no input makes the
 * result NaN.  *hit is written
 * only on a hit. */
bool triangle_intersect(const triangle *tri, ray r, real t_min, real t_max, triangle_test test, triangle_hit *hit);

/* Cramer's rule alone, as the chapter's exercise writes it: the hit in
 * (t_min, t_max), or false for M = 0, a non-finite M, and a t, beta or
 * gamma that is NaN; *hit is written only on a hit.  Without the check of
 * degenerate.h that triangle_intersect adds, so that the tests can look at
 * the exercise on its own (a renderer calls triangle_intersect). */
bool triangle_cramer(const triangle *tri, ray r, real t_min, real t_max, triangle_hit *hit);

/* The unit geometric normal, normalize((b - a) x (c - a)).  A degenerate
 * triangle has none: the result is then the zero vector. */
vec3 triangle_normal(const triangle *tri);

/* snippet: det3 */
/* The determinant of the 3x3 matrix with columns c0, c1, c2, as the scalar
 * triple product det[c0 c1 c2] = c0 . (c1 x c2). */
static inline real det3(vec3 c0, vec3 c1, vec3 c2) { return vec3_dot(c0, vec3_cross(c1, c2)); }
/* end snippet */

#endif
