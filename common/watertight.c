/* watertight.c - Woop, Benthin and Wald's watertight ray/triangle test (2013). */
#include "watertight.h"

#include "crossing.h"

/* v's coordinate along axis k (0: x, 1: y, 2: z), read from an array rather
 * than chosen by branches: the test reads nine of them per triangle. */
static inline real component(vec3 v, int k)
{
    const real c[3] = {v.x, v.y, v.z};
    return c[k];
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
    *wr = (watertight_ray){.r = r, .kx = kx, .ky = ky, .kz = kz, .sx = sx, .sy = sy, .sz = sz};
    return true;
}

bool watertight_hit(const watertight_ray *wr, const vec3 *va, const vec3 *vb, const vec3 *vc, real t_min,
                    real t_max, real out[3])
{
    const ray r = wr->r;
    const int kx = wr->kx, ky = wr->ky, kz = wr->kz;
    const real sx = wr->sx, sy = wr->sy, sz = wr->sz;
    /* snippet: watertight_vertices */
    /* 2. The vertices relative to p, sheared: the ray is now the positive z axis. */
    vec3 a = vec3_sub(*va, r.p), b = vec3_sub(*vb, r.p), c = vec3_sub(*vc, r.p);
    real ax = component(a, kx) - sx * component(a, kz), ay = component(a, ky) - sy * component(a, kz);
    real bx = component(b, kx) - sx * component(b, kz), by = component(b, ky) - sy * component(b, kz);
    real cx = component(c, kx) - sx * component(c, kz), cy = component(c, ky) - sy * component(c, kz);
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
    real az = sz * component(a, kz), bz = sz * component(b, kz), cz = sz * component(c, kz);
    real t = (u * az + v * bz + w * cz) / det;
    if (!(t > t_min && t < t_max))
        return false;
    /* Rounding leaves det a sliver of either sign where it should be 0: only
     * a crossing that the data decide counts (crossing.h); only hits pay. */
    if (!triangle_crossing_certain(va, vb, vc, r))
        return false;
    out[0] = t;
    out[1] = v / det;
    out[2] = w / det;
    return true;
    /* end snippet */
}
