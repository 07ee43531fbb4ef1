/* shading_normal.c - chapter 10: the interpolated normal. */
#include "10_interpolation/shading_normal.h"

#include "10_interpolation/interpolate.h"

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
