/* shade_shadows.h - chapter 06: the shade function of the shadow stage.
 *
 * The lecture's "Image so far" with shadows:
 *
 *     Surface.shade(ray, point, normal, light)
 *         shadRay = (point, light.pos - point)
 *         if (shadRay not blocked)
 *             v = -normalize(ray.direction); l = normalize(light.pos - point)
 *             return the Lambert term (chapter 05)
 *         return black
 *
 * Still the scene's first light only (chapter 07 loops over all of them).  A
 * shadow ray is cast only when it can change the answer: not for RGBNormals,
 * not without a light, not when the light is behind the surface (n . l <= 0,
 * where the Lambert term is 0 anyway: light_blocked says so without a ray).
 */
#ifndef CH06_SHADE_SHADOWS_H
#define CH06_SHADE_SHADOWS_H

#include "06_shadows/spawn.h"

/* True when `light` can light sp's side of the surface: n . (light.pos - point) > 0. */
bool light_in_front(const shading_point *sp, const scene_light *light);

/* A shade_fn: the first light's Lambert term where its shadow ray is not
 * blocked (tr->knobs.spawn: the policy, or the default one). */
color shade_shadows(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays);

#endif
