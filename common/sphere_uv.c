/* sphere_uv.c - the course's texture coordinates of a sphere. */
#include "sphere_uv.h"

#include <math.h>

mesh_uv sphere_uv(vec3 center, real radius, vec3 point)
{
    static const double pi = 3.14159265358979323846;
    vec3 d = vec3_scale(vec3_sub(point, center), 1 / radius); /* unit, up to rounding */
    double y = d.y < -1 ? -1 : d.y > 1 ? 1 : (double)d.y;    /* asin needs [-1, 1] */
    double u = 0.5 + atan2((double)d.x, (double)d.z) / (2 * pi); /* longitude around +y */
    double v = 0.5 + asin(y) / pi;                               /* latitude, 0 south, 1 north */
    return (mesh_uv){(real)u, (real)v};
}
