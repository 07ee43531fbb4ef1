/* acne.h - chapter 06: shadow acne and light leaks, measured.
 *
 * Two scenes, at any scale s and far from the origin (centred at
 * s (3.7, 2.9, -4.3)):
 *   acne: a square of side s, tilted about 20 degrees, lit from above with
 *         nothing in between.  Every point should be lit: a shadowed one is
 *         acne (the square shadowing itself).
 *   leak: the same square under a thin parallel occluder 1e-4 s above it,
 *         between it and the light.  Every point should be in shadow: a lit
 *         one is a leak (the shadow ray started beyond the occluder).
 * The square is seen from an eye above it through n x n points spread over
 * it; each eye ray's hit is computed as a renderer computes it (with the
 * rounding a renderer has), and its shadow ray is built by the policy.  Eye
 * rays see the square only (the occluder is transparent to them), so both
 * scenes shade the same points.
 */
#ifndef CH06_ACNE_H
#define CH06_ACNE_H

#include "06_shadows/spawn.h"

typedef struct {
    long points;  /* shaded points of each scene */
    double acne;  /* % of the acne scene's points in shadow */
    double leak;  /* % of the leak scene's points lit */
} acne_result;

/* The scene scales of the measurement table. */
#define ACNE_SCALES 5
extern const real acne_scales[ACNE_SCALES]; /* 1e-4, 1e-2, 1, 1e2, 1e4 */

/* Both scenes at scale s with policy, through n x n points.  Returns 0, or -1
 * when out of memory. */
int acne_measure(real s, eps_policy policy, int n, acne_result *result);

#endif
