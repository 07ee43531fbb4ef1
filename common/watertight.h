/* watertight.h - the watertight ray/triangle test.
 *
 * Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", Journal of
 * Computer Graphics Techniques 2(1), 2013.  The ray is made the z axis of a
 * sheared coordinate system; there the test is three 2D edge functions, each
 * a function of the ray and its edge's two vertices alone, so two triangles
 * that share an edge compute the same number for it, with opposite signs, and
 * no ray slips between them.  Edges are closed; both sides are hit.
 */
#ifndef RT_WATERTIGHT_H
#define RT_WATERTIGHT_H

#include <stdbool.h>
#include <stddef.h>

#include "crossing.h"
#include "ray.h"

/* The test's first step, which depends on the ray alone: the axis
 * permutation and the shear (three divisions).  A caller that tests one ray
 * against many triangles makes it once. */
typedef struct {
    ray r;
    int kx, ky, kz;  /* the axes that become x, y and z in ray space */
    real sx, sy, sz; /* the shear: x' = x - S_x z, y' = y - S_y z, z' = S_z z */
    real p[3];       /* r.p's coordinates along kx, ky and kz */
} watertight_ray;

/* Step 1 for r.  False when d has no direction: every triangle is missed. */
bool watertight_ray_make(ray r, watertight_ray *wr);

/* The coordinate along axis k of the vector stored at *v, read where it is
 * stored: the test reads nine of them per triangle, and `component` of a copy
 * would store the copy first. */
static inline real along(const vec3 *v, int k)
{
    _Static_assert(offsetof(vec3, y) == sizeof(real) && offsetof(vec3, z) == 2 * sizeof(real),
                   "x, y and z follow each other");
    return *(const real *)((const char *)v + (size_t)k * sizeof(real));
}

/* Steps 2-4 for the triangle *a, *b, *c: whether the ray meets it at
 * r.p + t r.d = a + beta (b - a) + gamma (c - a) with t in (t_min, t_max)
 * and a crossing that the data decide (crossing.h).  A degenerate triangle
 * and a ray in or parallel to its plane are misses.  out = (t, beta, gamma)
 * is written only on a hit.  Inline: it runs for every triangle a ray meets. */
static inline bool watertight_hit(const watertight_ray *wr, const vec3 *va, const vec3 *vb, const vec3 *vc, real t_min,
                    real t_max, real out[3])
{
    const int kx = wr->kx, ky = wr->ky, kz = wr->kz;
    const real sx = wr->sx, sy = wr->sy, sz = wr->sz, *p = wr->p;
    /* snippet: watertight_vertices */
    /* 2. The vertices relative to p (p[0], p[1], p[2]: its coordinates along
     *    kx, ky, kz), sheared: the ray is now the positive z axis. */
    real za = along(va, kz) - p[2], zb = along(vb, kz) - p[2], zc = along(vc, kz) - p[2];
    real ax = (along(va, kx) - p[0]) - sx * za, ay = (along(va, ky) - p[1]) - sy * za;
    real bx = (along(vb, kx) - p[0]) - sx * zb, by = (along(vb, ky) - p[1]) - sy * zb;
    real cx = (along(vc, kx) - p[0]) - sx * zc, cy = (along(vc, ky) - p[1]) - sy * zc;
    /* end snippet */

    /* snippet: watertight_edges */
    /* 3. The edge functions: twice the signed areas of the triangles that the
     *    origin (the ray) makes with each edge.  u belongs to edge bc (so to a),
     *    v to edge ca, w to edge ab.  Each is a function of its edge alone. */
    real u = cx * by - cy * bx;
    real v = ax * cy - ay * cx;
    real w = bx * ay - by * ax;
#ifdef RT_REAL_FLOAT
    /* A zero may be a rounded-away sign.  The products of two floats are exact
     * in double, so the differences have the right sign there. */
    if (u == 0 || v == 0 || w == 0) {
        u = (real)((double)cx * by - (double)cy * bx);
        v = (real)((double)ax * cy - (double)ay * cx);
        w = (real)((double)bx * ay - (double)by * ax);
    }
#endif
    /* Closed edges: inside when no sign disagrees (zeros agree with both).
     * Bitwise | and &, not || and &&: one branch, whose way no predictor knows. */
    if (((u < 0) | (v < 0) | (w < 0)) & ((u > 0) | (v > 0) | (w > 0)))
        return false;
    /* end snippet */

    /* snippet: watertight_t */
    /* 4. u + v + w is the sheared triangle's doubled area: 0 when the ray lies
     *    in its plane or the triangle is degenerate.  The hit point is
     *    (u a + v b + w c) / det, so t is the same mix of the vertices' z'. */
    real det = u + v + w;
    if (det == 0 || !isfinite(det))
        return false;
    real az = sz * za, bz = sz * zb, cz = sz * zc;
    real t = (u * az + v * bz + w * cz) / det;
    if (!(t > t_min && t < t_max))
        return false;
    /* Rounding leaves det a sliver of either sign where it should be 0: only
     * a crossing that the data decide counts (crossing.h); only hits pay. */
    if (!triangle_crossing_certain(va, vb, vc, wr->r))
        return false;
    out[0] = t;
    out[1] = v / det;
    out[2] = w / det;
    return true;
    /* end snippet */
}

#endif
