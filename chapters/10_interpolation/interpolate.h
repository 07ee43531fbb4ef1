/* interpolate.h - chapter 10: values stored at vertices, read between them.
 *
 * The lecture's barycentric interpolation of an attribute A given at the
 * vertices a, b, c (README, "Values at vertices, read in between"):
 *
 *     A(beta, gamma) = (1 - beta - gamma) A_a + beta A_b + gamma A_c
 */
#ifndef CH10_INTERPOLATE_H
#define CH10_INTERPOLATE_H

#include "mesh.h"
#include "vec3.h"

/* A(beta, gamma) of the attribute A_a, A_b, A_c of vertices a, b, c.  A normal comes out of it
 * shorter than 1 between two different unit normals: normalize it. */
vec3 interpolate_vec3(vec3 A_a, vec3 A_b, vec3 A_c, real beta, real gamma);

/* The same for texture coordinates (u, v). */
mesh_uv interpolate_uv(mesh_uv A_a, mesh_uv A_b, mesh_uv A_c, real beta, real gamma);

#endif
