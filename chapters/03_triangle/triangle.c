/* triangle.c - chapter 03: the barycentric ray-triangle intersection. */
#include "03_triangle/triangle.h"
#include "exercise.h"

#include "03_triangle/degenerate.h"
#include "03_triangle/watertight.h"

/* The lecture's slide "Barycentric ray-triangle intersection":
 *     p + t d = a + beta (b - a) + gamma (c - a)
 * is, collected by unknown,
 *     [a - b   a - c   d] [beta gamma t]^T = a - p,
 * three linear equations in beta, gamma and t. */
static inline bool cramer(const triangle *tri, ray r, real t_min, real t_max, triangle_hit *hit)
{
    /* TODO cramer: the hit of the ray with the triangle in the window (t_min, t_max), edges
     * included, by Cramer's rule with det3 (README, "The intersection: three equations, three unknowns"
     * and "Edges: closed"); false where the system has no single finite solution. */
    EXERCISE_STUB("03_triangle", "triangle.c", "cramer"); /* delete this line when done */
    (void)tri;
    (void)r;
    (void)t_min;
    (void)t_max;
    (void)hit;
    return false;
}

static bool scaled_intersect(const triangle *tri, ray r, real t_min, real t_max, triangle_test test,
                             triangle_hit *hit, int k);

/* snippet: dispatch */
bool triangle_intersect(const triangle *tri, ray r, real t_min, real t_max, triangle_test test, triangle_hit *hit)
{
    /* d may have any length, and M is a product of |d| and two edges: a d
     * beyond 2^+-REAL_SAFE_EXPONENT (real.h) is first divided by a power of
     * two 2^k, exactly, that brings it just inside, and t (and the window)
     * multiplied by it. */
    const int k = vec3_scale_exponent(r.d);
    if (k != 0)
        return scaled_intersect(tri, r, t_min, t_max, test, hit, k);
    if (test == TRIANGLE_WATERTIGHT)
        return triangle_intersect_watertight(tri, r, t_min, t_max, hit);
    /* Cramer's rule divides by M; where M is only rounding noise (a
     * degenerate triangle, a ray in or along the plane) its beta, gamma and
     * t are noise too, so such a hit does not count (degenerate.h).  Only
     * hits pay for the check. */
    triangle_hit h;
    if (!cramer(tri, r, t_min, t_max, &h) || !triangle_crossing_certain(tri, r))
        return false;
    *hit = h;
    return true;
}
/* end snippet */

/* The hit of r = (p, d) as that of (p, d / 2^k), whose t is 2^k times as large. */
static bool scaled_intersect(const triangle *tri, ray r, real t_min, real t_max, triangle_test test,
                             triangle_hit *hit, int k)
{
    triangle_hit h;
    const ray scaled = {r.p, vec3_ldexp(r.d, -k)};
    if (!triangle_intersect(tri, scaled, (real)ldexp(t_min, k), (real)ldexp(t_max, k), test, &h))
        return false;
    h.t = (real)ldexp(h.t, -k);
    *hit = h;
    return true;
}

bool triangle_cramer(const triangle *tri, ray r, real t_min, real t_max, triangle_hit *hit)
{
    return cramer(tri, r, t_min, t_max, hit);
}

vec3 triangle_normal(const triangle *tri)
{
    vec3 n = vec3_cross(vec3_sub(tri->b, tri->a), vec3_sub(tri->c, tri->a));
    real largest = vec3_max_abs(n);
    if (!(largest > 0 && isfinite(largest)))
        return vec3_make(0, 0, 0); /* collinear or coincident vertices: no plane */
    /* Scaled to a largest component of 1 first, so that the squares in
     * |n| neither overflow nor underflow. */
    return vec3_normalize(vec3_scale(n, 1 / largest));
}
