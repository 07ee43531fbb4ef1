/* mirror.h - chapter 08: the mirror direction and the mirror term L_m.
 *
 * The lecture's "Mirror reflection": a perfectly shiny surface shows no
 * highlight but a reflection of other objects; "to find out mirror reflection
 * color, ask what color is seen from surface point in reflection direction".
 * With v the unit vector towards the viewer the lecture writes
 *
 *     r = v + 2((n . v) n - v) = 2 (n . v) n - v
 *
 * and for the ray's own direction d = -v (any length) the same mirror
 * direction is
 *
 *     r = d - 2 (d . n) n
 *
 * (the part of d along n changes sign, the part along the surface stays).
 */
#ifndef CH08_MIRROR_H
#define CH08_MIRROR_H

#include <stdint.h>

#include "05_lambert/tracer.h"

/* The mirror direction of d about the unit normal n: d - 2 (d . n) n.  It has
 * the length of d; either side of n works. */
vec3 reflect(vec3 d, vec3 n);

/* L_m: the radiance seen from sp's point along the mirror direction of its
 * ray about the shading normal sp->n, traced one level deeper than `depth`
 * and counted as RAY_REFLECTED; black when path_next (path.h) stops the path
 * with coefficient k_m.  The ray leaves the surface through chapter 06's
 * spawn_ray with the tracer's --shadow-eps policy, and goes as far as an eye
 * ray: its window is (0, infinity). */
color mirror_radiance(const tracer *tr, const shading_point *sp, color k_m, int depth, uint64_t *rays);

#endif
