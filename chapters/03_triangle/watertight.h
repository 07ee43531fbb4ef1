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

/* The test in two parts.  Its first step depends on the ray alone: the axis
 * permutation and the shear constants S_x, S_y, S_z (three divisions).  A
 * caller that tests one ray against many triangles (chapter 11's lab) makes
 * it once and reuses it; the arithmetic is the same, so are the results. */
typedef struct {
    ray r;
    int kx, ky, kz; /* the axes that become x, y and z in ray space */
    real sx, sy, sz; /* the shear: x' = x - S_x z, y' = y - S_y z, z' = S_z z */
} watertight_ray;

/* Step 1 for r.  False when d has no direction: every triangle is missed. */
bool watertight_ray_make(ray r, watertight_ray *wr);

/* Steps 2-4: triangle_intersect_watertight(tri, wr->r, t_min, t_max, hit)
 * for a wr that watertight_ray_make filled in, bit for bit. */
bool watertight_ray_hit(const watertight_ray *wr, const triangle *tri, real t_min, real t_max, triangle_hit *hit);

#endif
