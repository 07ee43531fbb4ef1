/* triangle.c - chapter 03: the barycentric ray-triangle intersection. */
#include "03_triangle/triangle.h"
#include "exercise.h"
#include "crossing.h"

bool triangle_cramer(const triangle *tri, ray r, real t_min, real t_max, triangle_hit *hit)
{
    /* TODO cramer: the hit of the ray with the triangle in the window (t_min, t_max), edges
     * included, by Cramer's rule with det3 (README, "The intersection: three equations, three unknowns"
     * and "Edges: closed"); false where the system has no single finite solution. */
    EXERCISE_STUB("03_triangle", "triangle.c", "cramer"); /* delete this line when done */
    (void)tri, (void)r, (void)t_min, (void)t_max, (void)hit;
    return false;
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
