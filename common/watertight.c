/* watertight.c - Woop, Benthin and Wald's watertight ray/triangle test (2013). */
#include "watertight.h"

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
    real dz = along(&r.d, kz);
    if (!(dz != 0 && isfinite(dz)))
        return false; /* no direction at all */
    if (dz < 0) {
        int swap = kx;
        kx = ky;
        ky = swap;
    }
    /* The shear that maps d to (0, 0, 1): x' = x - S_x z, y' = y - S_y z, z' = S_z z. */
    real sx = along(&r.d, kx) / dz, sy = along(&r.d, ky) / dz, sz = 1 / dz;
    /* end snippet */
    *wr = (watertight_ray){.r = r, .kx = kx, .ky = ky, .kz = kz, .sx = sx, .sy = sy, .sz = sz,
                           .p = {along(&r.p, kx), along(&r.p, ky), along(&r.p, kz)}};
    return true;
}
