/* sphere.h - chapter 02: where a ray meets a sphere.
 *
 * The lecture's "Ray-sphere intersection": a point x is on the ray when
 * x = p + t d and on the sphere of centre c and radius R when
 * (x - c).(x - c) - R^2 = 0.  Substituting gives a quadratic in t.  Two ways
 * to solve it, the sphere formula knob (docs/design.md, "Knobs"):
 *   SPHERE_TEXTBOOK - the lecture's algebraic quadratic formula, as printed;
 *   SPHERE_ROBUST   - the same roots, computed so that far, small spheres and
 *                     rays that start near the surface keep their digits
 *                     (the default; README.md says why and measures it).
 */
#ifndef CH02_SPHERE_H
#define CH02_SPHERE_H

#include <stdbool.h>

#include "ray.h"

/* snippet: sphere */
typedef struct {
    vec3 center; /* c */
    real radius; /* R > 0 */
} sphere;

typedef enum { SPHERE_ROBUST, SPHERE_TEXTBOOK } sphere_formula;

/* The nearest t in (t_min, t_max) where r meets s; false when there is none. *n: the outward unit normal at the hit. */
bool sphere_intersect(const sphere *s, ray r, real t_min, real t_max, sphere_formula formula, real *t, vec3 *n);
/* end snippet */

/* The parts of sphere_intersect, each an exercise (sphere.c):
 * the two roots of A t^2 + 2 B t + C = 0 by the chosen formula, in either
 * order; false when there is no real root (the ray's line misses). */
bool sphere_roots(const sphere *s, ray r, sphere_formula formula, real *t0, real *t1);

/* The nearest of the roots t0, t1 inside the open window (t_min, t_max), in
 * *t; false when neither is inside. */
bool sphere_nearest_root(real t0, real t1, real t_min, real t_max, real *t);

/* The outward unit normal at a point x of the sphere: (x - c) / |x - c|. */
vec3 sphere_normal(const sphere *s, vec3 x);

#endif
