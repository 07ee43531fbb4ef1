/* shading_normal.c - chapter 10: the interpolated normal, and where it may not go. */
#include "10_interpolation/shading_normal.h"

#include "10_interpolation/interpolate.h"

const char *const normal_source_names[] = {"interpolated", "geometric", NULL};
const char *const below_policy_names[] = {"flip", "keep", NULL};

/* snippet: vertex_normal */
bool vertex_normal(const mesh *m, const mesh_face *f, real beta, real gamma, vec3 *n)
{
    if (f->vn[0] < 0 || f->vn[1] < 0 || f->vn[2] < 0)
        return false; /* a corner without a normal: flat */
    vec3 blend = interpolate_vec3(m->normals[f->vn[0]], m->normals[f->vn[1]], m->normals[f->vn[2]], beta, gamma);
    if (!(vec3_length_squared(blend) > 0) || !vec3_is_finite(blend))
        return false;
    *n = vec3_normalize(blend);
    return true;
}
/* end snippet */

/* snippet: shading_normal */
vec3 shading_normal(vec3 n_s, vec3 n_g)
{
    return vec3_dot(n_s, n_g) < 0 ? vec3_neg(n_s) : n_s; /* the geometric normal decides the side */
}
/* end snippet */

/* snippet: mirror_above */
vec3 mirror_above(vec3 n_s, vec3 n_g, vec3 v)
{
    vec3 r = vec3_sub(vec3_scale(n_s, 2 * vec3_dot(n_s, v)), v); /* r = 2 (n_s . v) n_s - v */
    real below = vec3_dot(r, n_g);
    if (below >= 0)
        return n_s; /* above the surface: nothing to do */
    vec3 r_up = vec3_sub(r, vec3_scale(n_g, 2 * below)); /* r' = r - 2 (r . n_g) n_g */
    return vec3_normalize(vec3_add(v, r_up));           /* n' = (v + r') / |v + r'| */
}
/* end snippet */
