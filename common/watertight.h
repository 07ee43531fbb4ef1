/* watertight.h - the watertight ray/triangle test.
 *
 * Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", Journal of
 * Computer Graphics Techniques 2(1), 2013.  The ray is made the z axis of a
 * sheared coordinate system; there the test is three 2D edge functions, each
 * a function of the ray and its edge's two vertices alone, so two triangles
 * that share an edge compute the same number for it, with opposite signs, and
 * no ray slips between them.  Edges are closed; both sides are hit.
 */
#ifndef RT_WATERTIGHT_H
#define RT_WATERTIGHT_H

#include <stdbool.h>

#include "ray.h"

/* The test's first step, which depends on the ray alone: the axis
 * permutation and the shear (three divisions).  A caller that tests one ray
 * against many triangles makes it once. */
typedef struct {
    ray r;
    int kx, ky, kz;  /* the axes that become x, y and z in ray space */
    real sx, sy, sz; /* the shear: x' = x - S_x z, y' = y - S_y z, z' = S_z z */
    real p[3];       /* r.p's coordinates along kx, ky and kz */
} watertight_ray;

/* Step 1 for r.  False when d has no direction: every triangle is missed. */
bool watertight_ray_make(ray r, watertight_ray *wr);

/* Steps 2-4 for the triangle *a, *b, *c: whether the ray meets it at
 * r.p + t r.d = a + beta (b - a) + gamma (c - a) with t in (t_min, t_max)
 * and a crossing that the data decide (crossing.h).  A degenerate triangle
 * and a ray in or parallel to its plane are misses.  out = (t, beta, gamma)
 * is written only on a hit.  (Addresses, not copies: the test runs for
 * every triangle a ray meets, and each argument beyond six registers costs.) */
bool watertight_hit(const watertight_ray *wr, const vec3 *a, const vec3 *b, const vec3 *c, real t_min, real t_max,
                    real out[3]);

#endif
