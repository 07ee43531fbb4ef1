/* degenerate.c - chapter 03: determinants against their own rounding error. */
#include "03_triangle/degenerate.h"

/* e such that 2^(e - 1) <= largest < 2^e (frexp's exponent); 0 for 0. */
static int exponent_of(real largest)
{
    int e;
    frexp((double)largest, &e);
    return e;
}

/* 2^-e, when it and 2^e are normal doubles (|e| <= 1022); 0 otherwise. */
static double power_of_two(int e)
{
    return e >= -1022 && e <= 1022 ? ldexp(1.0, -e) : 0;
}

/* v / 2^e in double: exact (only the exponent moves), so that the products
 * below stay far from overflow and underflow for any finite input.  The
 * product with the power of two 2^-e is ldexp's result (exact, or below the
 * normal doubles rounded once, as ldexp rounds); only exponents whose power
 * of two is not a normal double take the library call. */
static void scaled(vec3 v, int e, double scale, double out[3])
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
    double det = 0, p = 0, q = 0, r = 0;
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        det += e1[i] * (e2[j] * w[k] - e2[k] * w[j]);
        p += fabs(e1[i]) * (fabs(e2[j] * w[k]) + fabs(e2[k] * w[j]));
        q += s[i] * ((fabs(e1[j]) + fabs(e2[j])) * fabs(w[k]) + (fabs(e1[k]) + fabs(e2[k])) * fabs(w[j]));
        r += sw[i] * (fabs(e1[j] * e2[k]) + fabs(e1[k] * e2[j]));
    }
    const double eps = (double)REAL_EPSILON;
    return fabs(det) > 8 * eps * p + 2 * eps * q + 2 * eps * r; /* NaN fails */
}
/* end snippet */

bool triangle_crossing_certain(const triangle *tri, ray r)
{
    if (!(vec3_is_finite(tri->a) && vec3_is_finite(tri->b) && vec3_is_finite(tri->c) && vec3_is_finite(r.p) &&
          vec3_is_finite(r.d)))
        return false;
    /* Everything in double, scaled by powers of two.  The float build's data
     * are exact in double, and double arithmetic errs less than the bound
     * assumes for float, so the bound still holds. */
    real largest = (real)larger(larger(vec3_max_abs(tri->a), vec3_max_abs(tri->b)),
                                larger(vec3_max_abs(tri->c), vec3_max_abs(r.p)));
    int ev = exponent_of(largest), ed = exponent_of(vec3_max_abs(r.d));
    const double sv = power_of_two(ev), sd = power_of_two(ed);
    double a[3], b[3], c[3], p[3], d[3];
    scaled(tri->a, ev, sv, a);
    scaled(tri->b, ev, sv, b);
    scaled(tri->c, ev, sv, c);
    scaled(r.p, ev, sv, p);
    scaled(r.d, ed, sd, d);
    double e1[3], e2[3], f[3], s[3], sf[3], edge = 0;
    for (int i = 0; i < 3; i++) {
        e1[i] = a[i] - b[i];
        e2[i] = a[i] - c[i];
        f[i] = a[i] - p[i];
        edge = larger(edge, larger(fabs(e1[i]), fabs(e2[i])));
    }
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
