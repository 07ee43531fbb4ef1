/* triangle.c - chapter 03: the barycentric ray-triangle intersection. */
#include "03_triangle/triangle.h"
#include "crossing.h"

bool triangle_cramer(const triangle *tri, ray r, real t_min, real t_max, triangle_hit *hit)
{
    /* EXERCISE cramer: the hit of the ray with the triangle in the window (t_min, t_max), edges
     * included, by Cramer's rule with det3 (README, "The intersection: three equations, three unknowns"
     * and "Edges: closed"); false where the system has no single finite solution. */
    vec3 a_b = vec3_sub(tri->a, tri->b);
    vec3 a_c = vec3_sub(tri->a, tri->c);
    vec3 a_p = vec3_sub(tri->a, r.p);
    real M = det3(a_b, a_c, r.d);
    if (M == 0 || !isfinite(M))
        return false;
    real t = det3(a_b, a_c, a_p) / M;
    if (!(t > t_min && t < t_max))
        return false;
    real gamma = det3(a_b, a_p, r.d) / M;
    if (!(gamma >= 0 && gamma <= 1))
        return false;
    real beta = det3(a_p, a_c, r.d) / M;
    if (!(beta >= 0 && beta + gamma <= 1))
        return false;
    *hit = (triangle_hit){.t = t, .beta = beta, .gamma = gamma};
    return true;
    /* STUB
    (void)tri, (void)r, (void)t_min, (void)t_max, (void)hit;
    return false;
    END EXERCISE */
}

bool triangle_intersect(const triangle *tri, ray r, real t_min, real t_max, triangle_test test, triangle_hit *hit)
{
    /* A d of extreme length: divided by 2^k exactly (real.h), t and the window multiplied by it. */
    const int k = vec3_scale_exponent(r.d);
    if (k != 0) {
        const ray scaled = {r.p, vec3_ldexp(r.d, -k)};
        if (!triangle_intersect(tri, scaled, (real)ldexp(t_min, k), (real)ldexp(t_max, k), test, hit))
            return false;
        hit->t = (real)ldexp(hit->t, -k);
        return true;
    }
    if (test == TRIANGLE_WATERTIGHT) {
        watertight_ray wr;
        return watertight_ray_make(r, &wr) && watertight_ray_hit(&wr, tri, t_min, t_max, hit);
    }
    /* Only a hit whose crossing the data decide counts (crossing.h). */
    triangle_hit h;
    if (!triangle_cramer(tri, r, t_min, t_max, &h) || !triangle_crossing_certain(&tri->a, &tri->b, &tri->c, r))
        return false;
    *hit = h;
    return true;
}

vec3 triangle_normal(const triangle *tri)
{
    vec3 n = vec3_cross(vec3_sub(tri->b, tri->a), vec3_sub(tri->c, tri->a));
    real largest = vec3_max_abs(n);
    if (!(largest > 0 && isfinite(largest)))
        return vec3_make(0, 0, 0); /* collinear or coincident vertices: no plane */
    return vec3_normalize(vec3_scale(n, 1 / largest)); /* |n| neither overflows nor underflows */
}
