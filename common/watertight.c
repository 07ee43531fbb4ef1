/* watertight.c - Woop, Benthin and Wald's watertight ray/triangle test (2013). */
#include "watertight.h"

#include <stddef.h>

#include "crossing.h"

/* v's coordinate along axis k (0: x, 1: y, 2: z), read from an array rather
 * than chosen by branches: the test reads nine of them per triangle. */
static inline real component(vec3 v, int k)
{
    const real c[3] = {v.x, v.y, v.z};
    return c[k];
}

/* The coordinate along axis k of the vector stored at *v, read where it is
 * stored: the test reads nine of them per triangle, and `component` of a copy
 * would store the copy first. */
static inline real coordinate(const vec3 *v, int k)
{
    _Static_assert(offsetof(vec3, y) == sizeof(real) && offsetof(vec3, z) == 2 * sizeof(real),
                   "x, y and z follow each other");
    return *(const real *)((const char *)v + (size_t)k * sizeof(real));
}

/* The axis along which |d| is largest. */
static int largest_axis(vec3 d)
{
    real x = real_abs(d.x), y = real_abs(d.y), z = real_abs(d.z);
    return x >= y && x >= z ? 0 : y >= z ? 1 : 2;
}

bool watertight_ray_make(ray r, watertight_ray *wr)
{
    /* snippet: watertight_shear */
    /* 1. Ray space: the axis where d is largest becomes z, the other two follow
     *    cyclically (swapped when d_z < 0, which keeps the triangle's winding). */
    int kz = largest_axis(r.d), kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    real dz = component(r.d, kz);
    if (!(dz != 0 && isfinite(dz)))
        return false; /* no direction at all */
    if (dz < 0) {
        int swap = kx;
        kx = ky;
        ky = swap;
    }
    /* The shear that maps d to (0, 0, 1): x' = x - S_x z, y' = y - S_y z, z' = S_z z. */
    real sx = component(r.d, kx) / dz, sy = component(r.d, ky) / dz, sz = 1 / dz;
    /* end snippet */
    *wr = (watertight_ray){.r = r, .kx = kx, .ky = ky, .kz = kz, .sx = sx, .sy = sy, .sz = sz,
                           .p = {component(r.p, kx), component(r.p, ky), component(r.p, kz)}};
    return true;
}

bool watertight_hit(const watertight_ray *wr, const vec3 *va, const vec3 *vb, const vec3 *vc, real t_min,
                    real t_max, real out[3])
{
    const int kx = wr->kx, ky = wr->ky, kz = wr->kz;
    const real sx = wr->sx, sy = wr->sy, sz = wr->sz, *p = wr->p;
    /* snippet: watertight_vertices */
    /* 2. The vertices relative to p (p[0], p[1], p[2]: its coordinates along
     *    kx, ky, kz), sheared: the ray is now the positive z axis. */
    real za = coordinate(va, kz) - p[2], zb = coordinate(vb, kz) - p[2], zc = coordinate(vc, kz) - p[2];
    real ax = (coordinate(va, kx) - p[0]) - sx * za, ay = (coordinate(va, ky) - p[1]) - sy * za;
    real bx = (coordinate(vb, kx) - p[0]) - sx * zb, by = (coordinate(vb, ky) - p[1]) - sy * zb;
    real cx = (coordinate(vc, kx) - p[0]) - sx * zc, cy = (coordinate(vc, ky) - p[1]) - sy * zc;
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
    /* Closed edges: inside when no sign disagrees (zeros agree with both). */
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0))
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
