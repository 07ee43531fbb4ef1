/* shadow.h - chapter 06: is the light blocked?
 *
 * The lecture's shadows: "Surface is only illuminated if nothing blocks the
 * light ... just intersect a ray with the scene!"
 *
 *     shadRay = (point, light.pos - point)
 *     if (shadRay not blocked) ... compute shading
 *
 * The shadow ray is a segment from the point to the light: a surface beyond
 * the light does not block it, nor does the surface the point is on, unless
 * the light is behind that surface.  It
 * asks the tracer's closest-hit query (whatever it is: chapter 04's list,
 * chapter 11's grid) with the t range cut down to the segment.
 */
#ifndef CH06_SHADOW_H
#define CH06_SHADOW_H

#include <stdbool.h>

#include "06_shadows/spawn.h"

/* True when the light at light_pos cannot light sp's point: it is behind the
 * surface (n . (light_pos - point) <= 0 for the shading normal n; no ray is
 * cast), or a surface of tr's scene lies on the segment from sp's surface to
 * light_pos, the segment built by spawn_ray_to with `policy` (one shadow ray,
 * counted in rays[RAY_SHADOW]). */
bool light_blocked(const tracer *tr, const shading_point *sp, vec3 light_pos, eps_policy policy, uint64_t *rays);

#endif
