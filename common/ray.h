/* ray.h - the lecture's ray, a half line r(t) = p + t d.
 *
 * d is not assumed to be a unit vector ("we won't assume this in practice"):
 * replacing d by alpha d (alpha > 0) gives the same ray with t divided by alpha.
 */
#ifndef RT_RAY_H
#define RT_RAY_H

#include "vec3.h"

typedef struct {
    vec3 p; /* origin */
    vec3 d; /* direction, any non-zero length */
} ray;

/* r(t) = p + t d */
static inline vec3 ray_at(ray r, real t) { return vec3_add(r.p, vec3_scale(r.d, t)); }

#endif
