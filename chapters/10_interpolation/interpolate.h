/* interpolate.h - chapter 10: values stored at vertices, read between them.
 *
 * The lecture's "Interpolation in ray tracing": "when values are stored at
 * vertices, use linear (barycentric) interpolation to define values across
 * the whole surface": during the triangle intersection compute the
 * barycentric coordinates (chapter 03 did: beta, gamma), then "use them to
 * average attributes given at vertices".  With alpha = 1 - beta - gamma the
 * value at the point a + beta (b - a) + gamma (c - a) is
 *
 *     A(beta, gamma) = alpha A_a + beta A_b + gamma A_c
 *
 * It matches the values at the vertices (beta = gamma = 0 gives A_a), is
 * continuous across an edge that two triangles share (on the edge only its
 * two vertices' values count), and is linear over each triangle.  The
 * attributes of this chapter are the OBJ file's per-vertex normals (vn) and
 * texture coordinates (vt).
 */
#ifndef CH10_INTERPOLATE_H
#define CH10_INTERPOLATE_H

#include "mesh.h"
#include "vec3.h"

/* The attribute A_a, A_b, A_c of vertices a, b, c at the point with
 * barycentric coordinates (beta, gamma): (1 - beta - gamma) A_a + beta A_b +
 * gamma A_c.  A normal comes out of it with the length it happens to have
 * (shorter than 1 between two different unit normals): normalize it. */
vec3 interpolate_vec3(vec3 A_a, vec3 A_b, vec3 A_c, real beta, real gamma);

/* The same for texture coordinates (u, v). */
mesh_uv interpolate_uv(mesh_uv A_a, mesh_uv A_b, mesh_uv A_c, real beta, real gamma);

#endif
