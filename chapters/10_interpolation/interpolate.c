/* interpolate.c - chapter 10: values stored at vertices, read between them. */
#include "10_interpolation/interpolate.h"
#include "exercise.h"

vec3 interpolate_vec3(vec3 A_a, vec3 A_b, vec3 A_c, real beta, real gamma)
{
    /* TODO interpolate: the attribute at (beta, gamma) of a triangle whose vertices a, b, c carry
     * A_a, A_b, A_c (README, "Values at vertices, read in between"). */
    EXERCISE_STUB("10_interpolation", "interpolate.c", "interpolate"); /* delete this line when done */
    (void)A_b, (void)A_c, (void)beta, (void)gamma;
    return A_a;
}

mesh_uv interpolate_uv(mesh_uv A_a, mesh_uv A_b, mesh_uv A_c, real beta, real gamma)
{
    /* (u, v) as a vector (u, v, 0): the same weights */
    vec3 A = interpolate_vec3(vec3_make(A_a.u, A_a.v, 0), vec3_make(A_b.u, A_b.v, 0), vec3_make(A_c.u, A_c.v, 0),
                              beta, gamma);
    return (mesh_uv){A.x, A.y};
}
