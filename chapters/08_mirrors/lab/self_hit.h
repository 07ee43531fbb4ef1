/* self_hit.h - chapter 08's lab: does a convex mirror see itself?  Measured.
 *
 * A mirror sphere of radius s centred at s (3.7, 2.9, -4.3), for scales s
 * from 1e-4 to 1e8, hit by parallel eye rays that start 3 s away, at chosen
 * angles of incidence theta_i up to grazing (an eye ray at distance
 * s sin(theta_i) from the centre meets the sphere at theta_i), n in each
 * angle band.  Each eye ray's hit is computed as the renderer computes it,
 * its mirror ray is built by reflect() and leaves the surface through
 * chapter 06's spawn_ray with a policy; a convex mirror must never see
 * itself, so every mirror ray that hits the sphere again is a failure.  The
 * failures are counted by the angle of incidence theta_i (between the eye ray
 * and the normal): grazing rays are where the reflected ray leaves the
 * surface at the smallest angle.
 */
#ifndef CH08_SELF_HIT_H
#define CH08_SELF_HIT_H

#include "06_shadows/spawn.h"

/* The angle bands, in degrees: [0, 60), [60, 85), [85, 89), [89, 89.9), [89.9, 89.99), [89.99, 90). */
#define SELF_HIT_BANDS 6
extern const double self_hit_band_start[SELF_HIT_BANDS + 1]; /* the last is 90 */

/* The scales of the table: 1e-4, 1e-2, 1, 1e2, 1e4, 1e6, 1e8. */
#define SELF_HIT_SCALES 7
extern const real self_hit_scales[SELF_HIT_SCALES];

typedef struct {
    long rays[SELF_HIT_BANDS]; /* mirror rays cast in each band */
    long hits[SELF_HIT_BANDS]; /* of those, the ones that hit the sphere again */
} self_hit_result;

/* The sphere at scale s with `policy`, through n eye rays in each band. */
void self_hit_measure(real s, eps_policy policy, int n, self_hit_result *result);

#endif
