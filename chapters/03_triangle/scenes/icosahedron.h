/* icosahedron.h - chapter 03: a small closed mesh, built in code.
 *
 * The regular icosahedron: 12 vertices, 20 triangular faces, 30 edges, each
 * edge shared by exactly two faces.  It is closed, so every ray that starts
 * inside must leave through some face: the test of whether a triangle test
 * lets rays slip through the cracks between faces.
 */
#ifndef CH03_ICOSAHEDRON_H
#define CH03_ICOSAHEDRON_H

#include "03_triangle/triangle.h"

enum { ICOSAHEDRON_VERTICES = 12, ICOSAHEDRON_FACES = 20, ICOSAHEDRON_EDGES = 30 };

/* The faces as indices into the vertices, counter-clockwise seen from
 * outside: every triangle_normal() points out. */
extern const int icosahedron_faces[ICOSAHEDRON_FACES][3];

/* The vertices of the icosahedron around `centre` whose vertices lie at
 * distance `radius` from it: centre + radius * normalize(v) for the corners
 * v of three golden rectangles, (0, +-1, +-phi) and its cyclic shifts. */
void icosahedron_vertices(vec3 centre, real radius, vec3 out[ICOSAHEDRON_VERTICES]);

/* The 20 faces as triangles (vertices shared bit for bit between faces). */
void icosahedron_triangles(const vec3 vertices[ICOSAHEDRON_VERTICES], triangle out[ICOSAHEDRON_FACES]);

/* The 30 edges as pairs of vertex indices, each once. */
void icosahedron_edges(int out[ICOSAHEDRON_EDGES][2]);

#endif
