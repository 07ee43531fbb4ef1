/* box.c - axis-aligned boxes and the rounding a grid over them must allow for. */
#include "box.h"

#include <math.h>

box box_empty(void)
{
    const vec3 inf = vec3_make(REAL_INFINITY, REAL_INFINITY, REAL_INFINITY);
    return (box){inf, vec3_neg(inf)};
}

box box_union(box a, box b)
{
    return (box){vec3_make(real_fmin(a.lo.x, b.lo.x), real_fmin(a.lo.y, b.lo.y), real_fmin(a.lo.z, b.lo.z)),
                 vec3_make(real_fmax(a.hi.x, b.hi.x), real_fmax(a.hi.y, b.hi.y), real_fmax(a.hi.z, b.hi.z))};
}

box box_of_sphere(vec3 c, real radius)
{
    real r = real_abs(radius);
    return (box){vec3_make(c.x - r, c.y - r, c.z - r), vec3_make(c.x + r, c.y + r, c.z + r)};
}

box box_of_triangle(vec3 a, vec3 b, vec3 c)
{
    return (box){vec3_make(real_fmin(a.x, real_fmin(b.x, c.x)), real_fmin(a.y, real_fmin(b.y, c.y)),
                           real_fmin(a.z, real_fmin(b.z, c.z))),
                 vec3_make(real_fmax(a.x, real_fmax(b.x, c.x)), real_fmax(a.y, real_fmax(b.y, c.y)),
                           real_fmax(a.z, real_fmax(b.z, c.z)))};
}

box box_widen(box b, real m)
{
    return (box){vec3_make(b.lo.x - m, b.lo.y - m, b.lo.z - m), vec3_make(b.hi.x + m, b.hi.y + m, b.hi.z + m)};
}

bool box_is_finite(box b) { return vec3_is_finite(b.lo) && vec3_is_finite(b.hi); }

real box_margin(box b)
{
    real margin = 64 * REAL_EPSILON * real_fmax(vec3_max_abs(b.lo), vec3_max_abs(b.hi));
    return margin > 0 ? margin : 1;
}

int real_to_index(real f, int lowest, int highest)
{
    if (!(f >= (real)lowest)) /* also NaN */
        return lowest;
    if (f >= (real)highest)
        return highest;
    return (int)f;
}

real box_ray_slack(box b, ray r, real inv_d[3], real slack[3])
{
    const real reach = 16 * REAL_EPSILON * (vec3_max_abs(r.p) + real_fmax(vec3_max_abs(b.lo), vec3_max_abs(b.hi)));
    for (int a = 0; a < 3; a++) {
        inv_d[a] = 1 / vec3_axis(r.d, a);
        if (!isfinite(inv_d[a])) /* d_a = +0 or -0, or so small that 1 / d_a overflows */
            inv_d[a] = 0;
        slack[a] = reach * real_abs(inv_d[a]);
    }
    return reach;
}
