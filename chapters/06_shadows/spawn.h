/* spawn.h - chapter 06: rays that leave a surface, and the epsilon policy.
 *
 * The lecture's "classic blunder": a shadow ray that starts exactly at the
 * computed hit point may hit the very surface it starts on, at some t just
 * above 0, because the computed point is not exactly on the surface.  The
 * surface then shadows itself in a speckle of dark pixels ("shadow acne").
 * "Solution: shadow rays start a tiny distance from the surface."
 *
 * Every secondary ray (shadow rays here, mirror rays in chapter 08,
 * refracted rays in chapter 09) leaves its surface through spawn_ray or
 * spawn_ray_to, so one knob, --shadow-eps, decides how far from the surface
 * all of them start:
 *
 *   none   start at the computed point: the blunder, kept for the figure.
 *   fixed  start 1e-3 world units along the ray, and (for a segment) stop
 *          1e-3 before its end: what the course's solution does.  Too little
 *          for a scene far from the origin, too much for a small one.
 *   bound  (default) start off the surface along the geometric normal, to
 *          the side the ray goes, by a bound on the rounding error of the
 *          computed point, which grows with the magnitude of its coordinates
 *          (as pbrt does); a segment stops short of its end by the same kind
 *          of bound.  Right at every scale (measured in the README).
 */
#ifndef CH06_SPAWN_H
#define CH06_SPAWN_H

#include "05_lambert/tracer.h"
#include "options.h"

typedef enum { EPS_NONE, EPS_FIXED, EPS_BOUND } eps_policy;

/* The names of the policies, in enum order, NULL-terminated: the choices of --shadow-eps. */
extern const char *const eps_policy_names[];

/* The fixed policy's offset, in world units. */
#define EPS_FIXED_OFFSET ((real)1e-3)

/* The bound policy's offset is EPS_BOUND_ULPS * REAL_EPSILON times the
 * magnitude of the coordinates the point was computed from (eps_bound). */
#define EPS_BOUND_ULPS 32

/* snippet: spawn_knobs */
/* The knobs of chapter 06, a member of every later stage's knobs. */
typedef struct spawn_knobs {
    int eps; /* an eps_policy: --shadow-eps */
} spawn_knobs;
/* end snippet */

/* The defaults, an initializer: the error bound. */
#define SPAWN_KNOBS_DEFAULT {.eps = EPS_BOUND}

/* The policy of a tracer with chapter 06's knobs; the default without. */
eps_policy tracer_eps(const tracer *tr);

/* The bound on how far sp's computed point can be from the true surface, in
 * world units: EPS_BOUND_ULPS REAL_EPSILON times the largest coordinate of
 * the point and of the origin of the ray it was computed from (p + t d). */
real eps_bound(const shading_point *sp);

/* A ray leaving sp's surface in direction d (any length, either side of the
 * surface: towards a light, a mirror direction, a refracted direction), its
 * origin moved off the surface as the policy says.  Trace it from t = 0. */
ray spawn_ray(const shading_point *sp, vec3 d, eps_policy policy);

/* The segment from sp's surface to `target` (a light's position): the ray
 * spawn_ray gives towards it, with d = target - origin so that the target is
 * at t = 1, and in *t_max where to stop so that the target's own position
 * (a light on a surface) is not a blocker: 1 for none, 1e-3 world units
 * before the target for fixed, an error bound before it for bound. */
ray spawn_ray_to(const shading_point *sp, vec3 target, eps_policy policy, real *t_max);

#endif
