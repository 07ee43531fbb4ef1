/* sphere_mesh.h - chapter 10: a coarse sphere as a mesh, and a texture made in code.
 *
 * For the built-in scene and the tests: a sphere of few triangles whose
 * vertex normals are the sphere's own normals at its vertices, and whose
 * texture coordinates are the course's (u, v) of a sphere (sphere_uv.h) at
 * its vertices, so that interpolation should give back nearly the smooth,
 * textured sphere (the scene file scenes/coarse-sphere.obj is the same mesh
 * for 8 segments and 6 bands).  And a small globe map, the built-in
 * scene's texture, so that the renderer reads no file.
 */
#ifndef CH10_SPHERE_MESH_H
#define CH10_SPHERE_MESH_H

#include <stdbool.h>

#include "mesh.h"
#include "texture_image.h"

/* A sphere of `segments` (>= 3) around the y axis and `bands` (>= 2) from
 * pole to pole: 2 segments (bands - 1) triangles, wound counter-clockwise
 * seen from outside.  With normals false the mesh has no vn (it is shaded
 * flat).  Returns 0, or -1 when out of memory (m left empty). */
int sphere_mesh(mesh *m, vec3 center, real radius, int segments, int bands, bool normals);

/* A W x H latitude/longitude map with a graticule every `square` texels:
 * the top row of squares (v near 1) a white north cap, the bottom one a
 * purple south cap, a yellow equator band at v = 1/2, a red meridian at
 * u = 1/2 and a green one at u = 0 (the seam), and between them a sea that
 * brightens from u = 0 to u = 1 (as scenes/globe.png, 128 x 64, 8).
 * Returns 0, or -1 when out of memory. */
int globe_texture(texture_image *t, int width, int height, int square);

#endif
