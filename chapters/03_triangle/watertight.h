/* watertight.h - chapter 03: the watertight ray/triangle test.
 *
 * Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", Journal of
 * Computer Graphics Techniques 2(1), 2013.  The ray is made the z axis of a
 * sheared coordinate system; there the test is three 2D edge functions whose
 * values depend only on the ray and the edge's two vertices, so two
 * triangles that share an edge compute the same number for it, with opposite
 * signs, and a ray cannot slip between them.
 */
#ifndef CH03_WATERTIGHT_H
#define CH03_WATERTIGHT_H

#include "03_triangle/triangle.h"

/* triangle_intersect(..., TRIANGLE_WATERTIGHT, ...): the same contract. */
bool triangle_intersect_watertight(const triangle *tri, ray r, real t_min, real t_max, triangle_hit *hit);

#endif
