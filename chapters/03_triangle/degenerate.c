/* degenerate.c - chapter 03: determinants against their own rounding error. */
#include "03_triangle/degenerate.h"

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
 * det_certain must see the same rounded value. */
static double det_of(const double e1[3], const double e2[3], const double w[3])
{
    return e1[0] * (e2[1] * w[2] - e2[2] * w[1]) + e1[1] * (e2[2] * w[0] - e2[0] * w[2]) +
           e1[2] * (e2[0] * w[1] - e2[1] * w[0]);
}

/* snippet: det_certain */
/* Whether det[e1 e2 w] = e1 . (e2 x w) is larger than the error rounding may
 * have put into it.  With u = epsilon / 2 (the unit roundoff) and, to first
 * order:
 *   - computing the determinant (two roundings in each component of the
 *     cross product, three in the dot product) errs by at most 5 u P, where
 *     P = sum |e1_i| |e2_j| |w_k| over the six orders i, j, k of the axes:
 *     the six products of the determinant without their signs;
 *   - computing e1 = a - b and e2 = a - c (one rounding each) moves it by
 *     2 u P, and w (a direction, or a difference of points) by one or two
 *     more roundings: 2 u P;
 *   - the data are rounded too: a vertex coordinate that came from a
 *     rotation, a translation or a file is known to within u to 2 u of
 *     s_i, the largest |coordinate| of the vertices along axis i plus the
 *     largest edge component (a rotation mixes the axes, so an axis along
 *     which the triangle is thin still carries rounding of its size).  That
 *     moves e1 and e2 by up to 4 u s_i and the determinant by up to 4 u Q,
 *     with Q = sum s_i (|e1_j| + |e2_j|) |w_k|; and when w = a - p is a
 *     difference of points it moves w by up to 4 u sw_k (sw as s, over a
 *     and p), the determinant by 4 u R with R = sum |e1_i| |e2_j| sw_k.
 * In all the error is at most 9 u P + 4 u Q + 4 u R.  The test asks for
 * twice the margin on the arithmetic: |det| > 8 eps P + 2 eps Q + 2 eps R.
 * Below that, even the sign of the determinant is rounding noise.  There is
 * no absolute epsilon: P, Q and R scale with the data. */
static bool det_certain(const double e1[3], const double e2[3], const double w[3], const double s[3],
                        const double sw[3])
{
    double det = det_of(e1, e2, w), p = 0, q = 0, r = 0;
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        p += fabs(e1[i]) * (fabs(e2[j] * w[k]) + fabs(e2[k] * w[j]));
        q += s[i] * ((fabs(e1[j]) + fabs(e2[j])) * fabs(w[k]) + (fabs(e1[k]) + fabs(e2[k])) * fabs(w[j]));
        r += sw[i] * (fabs(e1[j] * e2[k]) + fabs(e1[k] * e2[j]));
    }
    const double eps = (double)REAL_EPSILON;
    return fabs(det) > 8 * eps * p + 2 * eps * q + 2 * eps * r; /* NaN fails */
}
/* end snippet */

/* A quick sufficient test for det_certain, which the common case (a clear
 * hit) passes at a third of the cost.  Each of the six terms of P is at
 * most E1 E2 W, where E1 = max_i |e1_i|, E2 and W likewise; each of Q at
 * most S (E1 + E2) W, S = max_i s_i; each of R at most SW E1 E2.  So
 *   8 eps P + 2 eps Q + 2 eps R <= 12 eps (W (4 E1 E2 + S (E1 + E2)) + SW E1 E2).
 * det_certain rounds each term of its bound at most 8 times (up, by at most
 * u = 2^-53 in double), this bound at most 6 times (down): the factor
 * 1 + 2^-20 covers both.  A rounding below the normal doubles errs by up to
 * 2^-1075 absolutely: 2^-1000 covers all of them.  So where |det|, computed
 * by det_of as there, is larger than this, det_certain is true; where not
 * (and for NaN), det_certain decides. */
static bool clearly_certain(const double e1[3], const double e2[3], const double w[3], double big_e1,
                            double big_e2, double big_s, double big_sw)
{
    double big_w = larger(fabs(w[0]), larger(fabs(w[1]), fabs(w[2])));
    double e12 = big_e1 * big_e2;
    const double k = 12 * (double)REAL_EPSILON * (1 + 0x1p-20); /* exact: 3 + 3 2^-20 fits in 53 bits */
    return fabs(det_of(e1, e2, w)) > k * (big_w * (4 * e12 + big_s * (big_e1 + big_e2)) + big_sw * e12) + 0x1p-1000;
}

/* 0 when every component of v is finite (x - x is then exactly 0), NaN
 * otherwise (infinity - infinity and NaN - NaN are NaN): one test for all
 * the data instead of a branch per coordinate. */
static inline double finite_sum(vec3 v)
{
    return ((double)v.x - (double)v.x) + ((double)v.y - (double)v.y) + ((double)v.z - (double)v.z);
}

/* The data as det_certain sees them: in double, scaled by powers of two.
 * The float build's data are exact in double, and double arithmetic errs
 * less than the bound assumes for float, so the bound still holds.  False
 * for non-finite data. */
static bool scaled_data(const triangle *tri, ray r, double a[3], double b[3], double c[3], double p[3],
                        double d[3])
{
    if (!(finite_sum(tri->a) + finite_sum(tri->b) + finite_sum(tri->c) + finite_sum(r.p) + finite_sum(r.d) == 0))
        return false;
    real largest = (real)larger(larger(vec3_max_abs(tri->a), vec3_max_abs(tri->b)),
                                larger(vec3_max_abs(tri->c), vec3_max_abs(r.p)));
    int ev = exponent_of(largest), ed = exponent_of(vec3_max_abs(r.d));
    const double sv = power_of_two(ev), sd = power_of_two(ed);
    scaled(tri->a, ev, sv, a);
    scaled(tri->b, ev, sv, b);
    scaled(tri->c, ev, sv, c);
    scaled(r.p, ev, sv, p);
    scaled(r.d, ed, sd, d);
    return true;
}

/* The edges e1 = a - b, e2 = a - c and f = a - p; the largest |component| of
 * e1 and e2 (edge). */
static double edges(const double a[3], const double b[3], const double c[3], const double p[3], double e1[3],
                    double e2[3], double f[3])
{
    double edge = 0;
    for (int i = 0; i < 3; i++) {
        e1[i] = a[i] - b[i];
        e2[i] = a[i] - c[i];
        f[i] = a[i] - p[i];
        edge = larger(edge, larger(fabs(e1[i]), fabs(e2[i])));
    }
    return edge;
}

bool triangle_crossing_certain_exact(const triangle *tri, ray r)
{
    double a[3], b[3], c[3], p[3], d[3];
    if (!scaled_data(tri, r, a, b, c, p, d))
        return false;
    double e1[3], e2[3], f[3], s[3], sf[3];
    double edge = edges(a, b, c, p, e1, e2, f);
    for (int i = 0; i < 3; i++) {
        s[i] = larger(fabs(a[i]), larger(fabs(b[i]), fabs(c[i]))) + edge;
        sf[i] = larger(fabs(a[i]), fabs(p[i])) + edge;
    }
    /* snippet: crossing_certain */
    /* M = det[a - b   a - c   d] is 0 for a degenerate triangle and for a
     * direction in (or parallel to) the plane; det[a - b   a - c   a - p], the
     * numerator of t, is 0 when the origin p lies in the plane, so that the
     * ray meets the plane at t = 0 or (lying in it) nowhere.  Rounding leaves
     * either of them a sliver of either sign, and a hit computed from that
     * sliver is noise. */
    const double none[3] = {0, 0, 0};
    return det_certain(e1, e2, d, s, none) && det_certain(e1, e2, f, s, sf);
    /* end snippet */
}

bool triangle_crossing_certain(const triangle *tri, ray r)
{
    double a[3], b[3], c[3], p[3], d[3];
    if (!scaled_data(tri, r, a, b, c, p, d))
        return false;
    double e1[3], e2[3], f[3], big_e1 = 0, big_e2 = 0, big_v = 0, big_vp = 0;
    double edge = edges(a, b, c, p, e1, e2, f);
    for (int i = 0; i < 3; i++) {
        big_e1 = larger(big_e1, fabs(e1[i]));
        big_e2 = larger(big_e2, fabs(e2[i]));
        big_v = larger(big_v, larger(fabs(a[i]), larger(fabs(b[i]), fabs(c[i]))));
        big_vp = larger(big_vp, larger(fabs(a[i]), fabs(p[i])));
    }
    /* Rounding is monotonic: big_v + edge >= every s_i of the exact test,
     * big_vp + edge every sf_i. */
    double big_s = big_v + edge, big_sf = big_vp + edge;
    if (clearly_certain(e1, e2, d, big_e1, big_e2, big_s, 0) && clearly_certain(e1, e2, f, big_e1, big_e2, big_s, big_sf))
        return true;
    return triangle_crossing_certain_exact(tri, r);
}
