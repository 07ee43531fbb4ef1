/* crossing_clear.h - the quick sufficient test of crossing.h's certainty
 * check, inline: it runs on every hit of a triangle test.  crossing.c's
 * full check (decided) and this test share crossing_det, so that both see the
 * same rounded determinants; the full check's derivation is there. */
#ifndef RT_CROSSING_CLEAR_H
#define RT_CROSSING_CLEAR_H

#include <math.h>
#include <stdbool.h>

#include "ray.h"

/* fmax of two values that are not NaN (the data were checked finite). */
static inline double crossing_larger(double x, double y) { return x > y ? x : y; }

/* e1 . (e2 x w), in one fixed order of operations: the quick test below and
 * decided must see the same rounded value. */
static inline double crossing_det(const double e1[3], const double e2[3], const double w[3])
{
    return e1[0] * (e2[1] * w[2] - e2[2] * w[1]) + e1[1] * (e2[2] * w[0] - e2[0] * w[2]) +
           e1[2] * (e2[0] * w[1] - e2[1] * w[0]);
}

static inline double crossing_biggest(const double v[3])
{
    return crossing_larger(fabs(v[0]), crossing_larger(fabs(v[1]), fabs(v[2])));
}

/* A quick sufficient test for decided, which the common case (a clear hit)
 * passes at a fraction of the cost: |N| > k E1 E2 F + tiny and
 * 2 k E1 E2 W (2 F + L) + tiny < TRIANGLE_POINT_SLACK L |M| (bounded_by_largest,
 * which triangle_crossing_clear also calls with its own k and tiny).  Each of the six terms of a P is at
 * most the product of the three largest |components|: P_M <= 6 E1 E2 W,
 * P_N <= 6 E1 E2 F, P_beta <= 6 F E2 W, P_gamma <= 6 E1 F W, so that
 *   8 eps P_N <= 48 eps E1 E2 F,
 *   16 eps (P_beta E1 + P_gamma E2 + P_M L) <= 96 eps E1 E2 W (2 F + L).
 * decided rounds each term of its bounds at most 8 times (up, by at most
 * u = 2^-53 in double), this test at most 8 times (down): the factor
 * 1 + 2^-20 covers both.  A rounding below the normal doubles errs by up to
 * 2^-1075 absolutely: 2^-1000 covers all of them.  The right-hand side,
 * TRIANGLE_POINT_SLACK L |M|, and |N| are computed as there.  So where this is true,
 * decided is; where not (and for NaN), decided decides. */
static inline bool bounded_by_largest(const double e1[3], const double e2[3], const double d[3], const double f[3],
                                      double k, double tiny)
{
    double m = fabs(crossing_det(e1, e2, d)), n = fabs(crossing_det(e1, e2, f));
    double big_e1 = crossing_biggest(e1), big_e2 = crossing_biggest(e2);
    double big_w = crossing_biggest(d), big_f = crossing_biggest(f);
    double big_l = crossing_larger(big_e1, big_e2), e12 = big_e1 * big_e2;
    return n > k * (e12 * big_f) + tiny &&
           2 * k * (e12 * big_w * (2 * big_f + big_l)) + tiny < TRIANGLE_POINT_SLACK * big_l * m;
}

/* clearly_decided on the data as they are, unscaled, with twice its
 * constant: where every coordinate is finite and below 2^100 (their
 * magnitudes sum below it), this test and decided on the scaled edges
 * compute their determinants from the same numbers up to powers of two, and
 * each errs from the exact value by at most 4 u' P (u' = 2^-52, the double
 * arithmetic of both; P <= 6 E1 E2 W for M, 6 E1 E2 F for N, with the
 * largest |components| of the exact edges) plus what roundings below the
 * normal doubles add.  So decided's |N| is at least this test's less
 * 48 u' E1 E2 F <= 48 eps E1 E2 F (eps = REAL_EPSILON >= u'), and its |M|
 * this test's less 48 u' E1 E2 W; decided's bounds are at most those
 * clearly_decided adds up (48 eps E1 E2 F and 96 eps E1 E2 W (2 F + L), to
 * the factor 1 + 2^-20).  The constant 96 eps (1 + 2^-18) here covers both
 * computations' rounding: the second condition's loss, TRIANGLE_POINT_SLACK
 * L 48 u' E1 E2 W = 6 u' E1 E2 W L, is a sixteenth of what doubling adds.
 * Roundings below the normal doubles: here at most 2^-1075 each, multiplied
 * by at most three factors below 2^103, under 2^-750 in all; in decided
 * (scaled by 2^-ev, 2^-ed with ev, ed <= 101) under 2^-1000 in its units,
 * 2^-1000 2^(3 ev + ed) <= 2^-596 in these; the term 2^-250 covers both.
 * So where this is true, decided on the scaled edges is true (and the data
 * are finite, which scaled_edges requires); data beyond 2^100 or so small
 * that |N| or TRIANGLE_POINT_SLACK L |M| falls below 2^-250 go the scaled
 * way. */
static inline bool triangle_crossing_clear(const vec3 *va, const vec3 *vb, const vec3 *vc, ray r)
{
    const double a[3] = {(double)va->x, (double)va->y, (double)va->z};
    const double b[3] = {(double)vb->x, (double)vb->y, (double)vb->z};
    const double c[3] = {(double)vc->x, (double)vc->y, (double)vc->z};
    const double p[3] = {(double)r.p.x, (double)r.p.y, (double)r.p.z};
    const double d[3] = {(double)r.d.x, (double)r.d.y, (double)r.d.z};
    /* written out, not in loops: the arrays then stay in registers */
    double sum = (fabs(a[0]) + fabs(a[1]) + fabs(a[2])) + (fabs(b[0]) + fabs(b[1]) + fabs(b[2])) +
                 (fabs(c[0]) + fabs(c[1]) + fabs(c[2])) + (fabs(p[0]) + fabs(p[1]) + fabs(p[2])) +
                 (fabs(d[0]) + fabs(d[1]) + fabs(d[2]));
    if (!(sum < 0x1p100)) /* also infinity and NaN */
        return false;
    const double e1[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    const double e2[3] = {a[0] - c[0], a[1] - c[1], a[2] - c[2]};
    const double f[3] = {a[0] - p[0], a[1] - p[1], a[2] - p[2]};
    /* k exact: 3 + 3 2^-18 fits in 53 bits */
    return bounded_by_largest(e1, e2, d, f, 96 * (double)REAL_EPSILON * (1 + 0x1p-18), 0x1p-250);
}

#endif
