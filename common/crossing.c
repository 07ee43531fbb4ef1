/* crossing.c - a ray and a triangle's plane: determinants against their own rounding error. */
#include "crossing.h"

#include <stdint.h>
#include <string.h>

/* e such that 2^(e - 1) <= largest < 2^e (frexp's exponent); 0 for 0.  For
 * a normal double that is its biased exponent field minus 1022, read from
 * the bits (it is called on every hit); frexp for 0 and the subnormals. */
static int exponent_of(real largest)
{
    double x = (double)largest;
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    int field = (int)(bits >> 52 & 0x7ff);
    if (field != 0)
        return field - 1022;
    int e;
    frexp(x, &e);
    return e;
}

/* 2^-e, when it and 2^e are normal doubles (|e| <= 1022); 0 otherwise.
 * Built from its bits: biased exponent field 1023 - e, no fraction. */
static double power_of_two(int e)
{
    if (e < -1022 || e > 1022)
        return 0;
    uint64_t bits = (uint64_t)(1023 - e) << 52;
    double x;
    memcpy(&x, &bits, sizeof x);
    return x;
}

/* v / 2^e in double: exact (only the exponent moves), so that the products
 * below stay far from overflow and underflow for any finite input.  The
 * product with the power of two 2^-e is ldexp's result (exact, or below the
 * normal doubles rounded once, as ldexp rounds); only exponents whose power
 * of two is not a normal double take the library call. */
static inline void scaled(vec3 v, int e, double scale, double out[3])
{
    if (scale != 0) {
        out[0] = (double)v.x * scale;
        out[1] = (double)v.y * scale;
        out[2] = (double)v.z * scale;
        return;
    }
    out[0] = ldexp((double)v.x, -e);
    out[1] = ldexp((double)v.y, -e);
    out[2] = ldexp((double)v.z, -e);
}

/* fmax of two values that are not NaN (the data were checked finite). */
static inline double larger(double x, double y) { return x > y ? x : y; }

/* e1 . (e2 x w), in one fixed order of operations: the quick test below and
 * decided must see the same rounded value. */
static double det_of(const double e1[3], const double e2[3], const double w[3])
{
    return e1[0] * (e2[1] * w[2] - e2[2] * w[1]) + e1[1] * (e2[2] * w[0] - e2[0] * w[2]) +
           e1[2] * (e2[0] * w[1] - e2[1] * w[0]);
}

/* P of det[u v w]: the six products of the determinant without their signs,
 * sum |u_i| |v_j| |w_k| over the six orders i, j, k of the axes. */
static double size_of(const double u[3], const double v[3], const double w[3])
{
    double p = 0;
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        p += fabs(u[i]) * (fabs(v[j] * w[k]) + fabs(v[k] * w[j]));
    }
    return p;
}

static double biggest(const double v[3]) { return larger(fabs(v[0]), larger(fabs(v[1]), fabs(v[2]))); }

/* snippet: decided */
/* Whether Cramer's rule, computed in real arithmetic on the data as they are
 * stored, decides the crossing.  A determinant det[u v w] computed in real
 * errs by at most 4 eps P(u, v, w) (to first order: 5 u in the products,
 * 3 u in the differences a - b, a - c, a - p; u = eps / 2), where P is the
 * sum of its six products without their signs.  With M = det[e1 e2 d],
 * N = det[e1 e2 f] (f = a - p; t = N / M), beta = det[f e2 d] / M and
 * gamma = det[e1 f d] / M:
 *   - the sign of N must be certain, |N| > 8 eps P_N, so that the ray does
 *     not start in the plane (t = 0 or no crossing);
 *   - the hit point a + beta (b - a) + gamma (c - a) must be known to
 *     within TRIANGLE_POINT_SLACK of the triangle's size L.  When |M| is at least
 *     twice its error, the errors of beta and gamma are at most twice
 *     (4 eps P_beta + |beta| 4 eps P_M) / |M| and (4 eps P_gamma + |gamma|
 *     4 eps P_M) / |M|, and the point's at most their sum times the edge
 *     lengths (|beta| + |gamma| <= 1 inside); measured by the largest
 *     |component| (E1, E2, L), lengths are at most 2 times that:
 *         16 eps (P_beta E1 + P_gamma E2 + P_M L) <= TRIANGLE_POINT_SLACK L |M|.
 *     It implies |M| > 8 eps P_M: the sign of M is certain too.  (The error
 *     of t moves the point along the ray: a ray from far away knows its t
 *     only to eps times the distance, whatever the check does.)
 * A degenerate triangle (collinear or coincident vertices) and a ray along
 * its plane fail it, because M is then rounding noise or too small to
 * place the point; so does a triangle so thin that beta or gamma are
 * noise even where M is not.  The data themselves are taken as they are:
 * a vertex far from the origin is where its coordinates say, to the last
 * digit, so a crossing that the arithmetic decides is a hit at any
 * distance.  (Budgeting also a rounding of the data of the size of their
 * coordinates lost nine in ten clear hits on float triangles 10^6 edge
 * lengths from the origin.)  There is no absolute epsilon: every term
 * scales with the data. */
static bool decided(const double e1[3], const double e2[3], const double d[3], const double f[3])
{
    const double eps = (double)REAL_EPSILON;
    double m = fabs(det_of(e1, e2, d)), n = fabs(det_of(e1, e2, f)), p_m = size_of(e1, e2, d);
    double big_e1 = biggest(e1), big_e2 = biggest(e2), big_l = larger(big_e1, big_e2);
    if (!(n > 8 * eps * size_of(e1, e2, f))) /* NaN fails */
        return false;
    double error = size_of(f, e2, d) * big_e1 + size_of(e1, f, d) * big_e2 + p_m * big_l;
    return 16 * eps * error <= TRIANGLE_POINT_SLACK * big_l * m && m > 0;
}
/* end snippet */

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
    double m = fabs(det_of(e1, e2, d)), n = fabs(det_of(e1, e2, f));
    double big_e1 = biggest(e1), big_e2 = biggest(e2), big_w = biggest(d), big_f = biggest(f);
    double big_l = larger(big_e1, big_e2), e12 = big_e1 * big_e2;
    return n > k * (e12 * big_f) + tiny && 2 * k * (e12 * big_w * (2 * big_f + big_l)) + tiny < TRIANGLE_POINT_SLACK * big_l * m;
}

static bool clearly_decided(const double e1[3], const double e2[3], const double d[3], const double f[3])
{
    /* k exact: 3 + 3 2^-20 fits in 53 bits */
    return bounded_by_largest(e1, e2, d, f, 48 * (double)REAL_EPSILON * (1 + 0x1p-20), 0x1p-1000);
}

/* 0 when every component of v is finite (x - x is then exactly 0), NaN
 * otherwise (infinity - infinity and NaN - NaN are NaN): one test for all
 * the data instead of a branch per coordinate. */
static inline double finite_sum(vec3 v)
{
    return ((double)v.x - (double)v.x) + ((double)v.y - (double)v.y) + ((double)v.z - (double)v.z);
}

/* The edges e1 = a - b, e2 = a - c, f = a - p and the direction d as decided
 * sees them: in double, scaled by powers of two.  The float build's data are
 * exact in double, and double arithmetic errs far less than the bound allows
 * for float.  False for non-finite data. */
static bool scaled_edges(const vec3 *va, const vec3 *vb, const vec3 *vc, ray r, double e1[3], double e2[3],
                         double d[3], double f[3])
{
    if (!(finite_sum(*va) + finite_sum(*vb) + finite_sum(*vc) + finite_sum(r.p) + finite_sum(r.d) == 0))
        return false;
    real largest =
        (real)larger(larger(vec3_max_abs(*va), vec3_max_abs(*vb)), larger(vec3_max_abs(*vc), vec3_max_abs(r.p)));
    int ev = exponent_of(largest), ed = exponent_of(vec3_max_abs(r.d));
    const double sv = power_of_two(ev), sd = power_of_two(ed);
    double a[3], b[3], c[3], p[3];
    scaled(*va, ev, sv, a);
    scaled(*vb, ev, sv, b);
    scaled(*vc, ev, sv, c);
    scaled(r.p, ev, sv, p);
    scaled(r.d, ed, sd, d);
    for (int i = 0; i < 3; i++) {
        e1[i] = a[i] - b[i];
        e2[i] = a[i] - c[i];
        f[i] = a[i] - p[i];
    }
    return true;
}

bool triangle_crossing_certain_exact(const vec3 *a, const vec3 *b, const vec3 *c, ray r)
{
    double e1[3], e2[3], d[3], f[3];
    return scaled_edges(a, b, c, r, e1, e2, d, f) && decided(e1, e2, d, f);
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
bool triangle_crossing_clear(const vec3 *va, const vec3 *vb, const vec3 *vc, ray r)
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

bool triangle_crossing_certain(const vec3 *a, const vec3 *b, const vec3 *c, ray r)
{
    if (triangle_crossing_clear(a, b, c, r))
        return true;
    double e1[3], e2[3], d[3], f[3];
    return scaled_edges(a, b, c, r, e1, e2, d, f) && (clearly_decided(e1, e2, d, f) || decided(e1, e2, d, f));
}
