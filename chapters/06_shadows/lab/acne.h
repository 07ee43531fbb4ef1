/* acne.h - chapter 06's lab: shadow acne and light leaks, measured.
 *
 * Two scenes for each of two shapes, at any scale s and far from the origin
 * (centred at s (3.7, 2.9, -4.3)):
 *   acne: the shape lit from above with nothing in between.  Every point
 *         should be lit: a shadowed one is acne (the shape shadowing itself).
 *   leak: the same shape under a thin occluder 1e-4 s away from it, between
 *         it and the light.  Every point should be in shadow: a lit one is a
 *         leak (the shadow ray started beyond the occluder).
 * The shapes: a square of side s tilted about 20 degrees, under a parallel
 * square; and a sphere of radius s/2, inside a concentric sphere 1e-4 s
 * larger.  The shape is seen from an eye above it through n x n points; each
 * eye ray's hit is computed as a renderer computes it (with the rounding a
 * renderer has), and its shadow ray built by the policy.  Eye rays see the
 * shape only (the occluder is transparent to them), so both scenes shade the
 * same points; points that face away from the light cast no shadow ray and
 * are not counted.
 */
#ifndef CH06_ACNE_H
#define CH06_ACNE_H

#include "06_shadows/spawn.h"

typedef enum { ACNE_SQUARE, ACNE_SPHERE, ACNE_SHAPES } acne_shape;

/* "square", "sphere": the shapes' names, in enum order. */
extern const char *const acne_shape_names[ACNE_SHAPES];

typedef struct {
    long points;  /* shaded points of each scene */
    double acne;  /* % of the acne scene's points in shadow */
    double leak;  /* % of the leak scene's points lit */
} acne_result;

/* The scene scales of the measurement table. */
#define ACNE_SCALES 5
extern const real acne_scales[ACNE_SCALES]; /* 1e-4, 1e-2, 1, 1e2, 1e4 */

/* Both scenes of `shape` at scale s with policy, through n x n points.
 * Returns 0, or -1 when out of memory. */
int acne_measure(acne_shape shape, real s, eps_policy policy, int n, acne_result *result);

#endif
