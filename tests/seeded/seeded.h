/* seeded.h - what the checks of inputs drawn at grading time share
 * (tests/answers.h; one file tests/seeded/NN_name.c a suite).
 *
 * The inputs are drawn in double from the grader's seed (suite_uniform) and
 * rounded to real once, so the reference's run and the student's see the
 * same ones in either build.  Header only, in static functions.
 */
#ifndef RT_TESTS_SEEDED_H
#define RT_TESTS_SEEDED_H

#include <math.h>

#include "color.h"
#include "suite.h"

/* A number uniform in [lo, hi). */
static inline double seeded_between(unsigned long *rng, double lo, double hi)
{
    return lo + (hi - lo) * suite_uniform(rng);
}

/* A point uniform in the cube [-size, size]^3. */
static inline vec3 seeded_point(unsigned long *rng, double size)
{
    double x = seeded_between(rng, -size, size), y = seeded_between(rng, -size, size);
    double z = seeded_between(rng, -size, size);
    return vec3_make((real)x, (real)y, (real)z);
}

/* A colour, each channel uniform in [lo, hi). */
static inline color seeded_color(unsigned long *rng, double lo, double hi)
{
    double r = seeded_between(rng, lo, hi), g = seeded_between(rng, lo, hi), b = seeded_between(rng, lo, hi);
    return color_make((real)r, (real)g, (real)b);
}

/* A unit vector at angle theta from the unit n, about a random axis. */
static inline vec3 seeded_at_angle(unsigned long *rng, vec3 n, double theta)
{
    vec3 side;
    do /* a random direction not along n, made perpendicular to it */
        side = suite_random_unit(rng);
    while (real_abs(vec3_dot(side, n)) > (real)0.9);
    side = vec3_normalize(vec3_sub(side, vec3_scale(n, vec3_dot(side, n))));
    return vec3_normalize(vec3_add(vec3_scale(n, (real)cos(theta)), vec3_scale(side, (real)sin(theta))));
}

/* A colour's channels as a vec3, for suite_answer_vec3. */

#endif
