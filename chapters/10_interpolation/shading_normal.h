/* shading_normal.h - chapter 10: the shading normal of a mesh face whose corners have normals (vn),
 * n_s = normalize((1 - beta - gamma) n_a + beta n_b + gamma n_c), its side in common/shading_side.h. */
#ifndef CH10_SHADING_NORMAL_H
#define CH10_SHADING_NORMAL_H

#include <stdbool.h>

#include "mesh.h"
#include "shading_side.h"

/* The interpolated unit normal of face f of mesh m at (beta, gamma): true
 * and *n set when all three corners have normals and their blend is not the
 * zero vector (opposite corner normals); false otherwise (the face is then
 * shaded flat). */
bool vertex_normal(const mesh *m, const mesh_face *f, real beta, real gamma, vec3 *n);

#endif
