/* crossing_reference.c - chapter 03: Cramer's rule in long double. */
#include "03_triangle/lab/crossing_reference.h"

#include <float.h>
#include <math.h>

static long double det_ld(const long double u[3], const long double v[3], const long double w[3])
{
    return u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) +
           u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/* The six products of det[u v w] without their signs (common/crossing.c). */
static long double size_ld(const long double u[3], const long double v[3], const long double w[3])
{
    long double p = 0;
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        p += fabsl(u[i]) * (fabsl(v[j] * w[k]) + fabsl(v[k] * w[j]));
    }
    return p;
}

static void to_ld(vec3 v, long double out[3])
{
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

bool crossing_reference(const triangle *tri, ray r, crossing *x)
{
    long double a[3], b[3], c[3], p[3], d[3], e1[3], e2[3], s[3];
    to_ld(tri->a, a);
    to_ld(tri->b, b);
    to_ld(tri->c, c);
    to_ld(r.p, p);
    to_ld(r.d, d);
    for (int i = 0; i < 3; i++) {
        e1[i] = a[i] - b[i];
        e2[i] = a[i] - c[i];
        s[i] = a[i] - p[i];
    }
    long double M = det_ld(e1, e2, d);
    if (!(fabsl(M) > 8 * LDBL_EPSILON * size_ld(e1, e2, d)))
        return false; /* also NaN */
    long double beta = det_ld(s, e2, d) / M, gamma = det_ld(e1, s, d) / M, alpha = 1 - beta - gamma;
    x->t = det_ld(e1, e2, s) / M;
    x->beta = beta;
    x->gamma = gamma;
    x->least = fminl(alpha, fminl(beta, gamma));
    return true;
}

static long double length_ld(vec3 v)
{
    long double x = v.x, y = v.y, z = v.z;
    return sqrtl(x * x + y * y + z * z);
}

static long double longest_edge(const triangle *tri)
{
    return fmaxl(length_ld(vec3_sub(tri->b, tri->a)),
                 fmaxl(length_ld(vec3_sub(tri->c, tri->a)), length_ld(vec3_sub(tri->c, tri->b))));
}

long double hit_error(const triangle *tri, ray r, triangle_hit h, const crossing *x)
{
    long double e = fabsl(h.t - x->t) * length_ld(r.d) + fabsl(h.beta - x->beta) * length_ld(vec3_sub(tri->b, tri->a)) +
                    fabsl(h.gamma - x->gamma) * length_ld(vec3_sub(tri->c, tri->a));
    return e / longest_edge(tri);
}

static long double dot_ld(const long double u[3], const long double v[3])
{
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

static void sub_ld(const long double u[3], const long double v[3], long double out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = u[i] - v[i];
}

/* The distance from x to the segment from u to v. */
static long double segment_distance(const long double x[3], const long double u[3], const long double v[3])
{
    long double e[3], w[3], q[3];
    sub_ld(v, u, e);
    sub_ld(x, u, w);
    long double ee = dot_ld(e, e), s = ee > 0 ? dot_ld(w, e) / ee : 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    for (int i = 0; i < 3; i++)
        q[i] = w[i] - s * e[i];
    return sqrtl(dot_ld(q, q));
}

long double hit_distance(const triangle *tri, ray r, long double t)
{
    long double v[3][3], p[3], d[3], x[3];
    to_ld(tri->a, v[0]);
    to_ld(tri->b, v[1]);
    to_ld(tri->c, v[2]);
    to_ld(r.p, p);
    to_ld(r.d, d);
    for (int i = 0; i < 3; i++)
        x[i] = p[i] + t * d[i];
    long double nearest = INFINITY, longest = 0;
    for (int k = 0; k < 3; k++) {
        long double e[3];
        sub_ld(v[(k + 1) % 3], v[k], e);
        longest = fmaxl(longest, sqrtl(dot_ld(e, e)));
        nearest = fminl(nearest, segment_distance(x, v[k], v[(k + 1) % 3]));
    }
    /* Inside the triangle's prism: the distance to its plane. */
    long double e1[3], e2[3], w[3], n[3];
    sub_ld(v[1], v[0], e1);
    sub_ld(v[2], v[0], e2);
    sub_ld(x, v[0], w);
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    long double nn = dot_ld(n, n);
    if (nn > 0) {
        long double m[3]; /* w x e2 . n / nn = beta, e1 x w . n / nn = gamma */
        m[0] = w[1] * e2[2] - w[2] * e2[1];
        m[1] = w[2] * e2[0] - w[0] * e2[2];
        m[2] = w[0] * e2[1] - w[1] * e2[0];
        long double beta = dot_ld(m, n) / nn;
        m[0] = e1[1] * w[2] - e1[2] * w[1];
        m[1] = e1[2] * w[0] - e1[0] * w[2];
        m[2] = e1[0] * w[1] - e1[1] * w[0];
        long double gamma = dot_ld(m, n) / nn;
        if (beta >= 0 && gamma >= 0 && beta + gamma <= 1)
            nearest = fminl(nearest, fabsl(dot_ld(w, n)) / sqrtl(nn));
    }
    return longest > 0 ? nearest / longest : nearest;
}
