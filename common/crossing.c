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
    double m = fabs(crossing_det(e1, e2, d)), n = fabs(crossing_det(e1, e2, f)), p_m = size_of(e1, e2, d);
    double big_e1 = crossing_biggest(e1), big_e2 = crossing_biggest(e2), big_l = crossing_larger(big_e1, big_e2);
    if (!(n > 8 * eps * size_of(e1, e2, f))) /* NaN fails */
        return false;
    double error = size_of(f, e2, d) * big_e1 + size_of(e1, f, d) * big_e2 + p_m * big_l;
    return 16 * eps * error <= TRIANGLE_POINT_SLACK * big_l * m && m > 0;
}
/* end snippet */

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
    real largest = (real)crossing_larger(crossing_larger(vec3_max_abs(*va), vec3_max_abs(*vb)),
                                         crossing_larger(vec3_max_abs(*vc), vec3_max_abs(r.p)));
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

bool triangle_crossing_scaled(const vec3 *a, const vec3 *b, const vec3 *c, ray r)
{
    double e1[3], e2[3], d[3], f[3];
    return scaled_edges(a, b, c, r, e1, e2, d, f) && (clearly_decided(e1, e2, d, f) || decided(e1, e2, d, f));
}
