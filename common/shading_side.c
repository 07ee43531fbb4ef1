/* shading_side.c - a shading normal on the viewer's side of the surface, and its mirror direction above it. */
#include "shading_side.h"

vec3 shading_normal(vec3 n_s, vec3 n_g)
{
    return vec3_dot(n_s, n_g) < 0 ? vec3_neg(n_s) : n_s; /* the geometric normal decides the side */
}

vec3 mirror_above(vec3 n_s, vec3 n_g, vec3 v)
{
    vec3 r = vec3_sub(vec3_scale(n_s, 2 * vec3_dot(n_s, v)), v); /* r = 2 (n_s . v) n_s - v */
    real below = vec3_dot(r, n_g);
    if (below >= 0)
        return n_s; /* above the surface: nothing to do */
    vec3 r_up = vec3_sub(r, vec3_scale(n_g, 2 * below)); /* r' = r - 2 (r . n_g) n_g */
    return vec3_normalize(vec3_add(v, r_up));           /* n' = (v + r') / |v + r'| */
}
