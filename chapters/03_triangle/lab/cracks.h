/* cracks.h - chapter 03's lab: counting the rays that slip between triangles.
 *
 * A ray that starts inside a closed mesh must hit it.  The hardest rays are
 * those aimed exactly at an edge or a vertex, where two or more triangles
 * meet: each triangle decides on its own, with its own rounding, whether
 * the point is inside, and when every one of them says "just outside" the
 * ray leaves through a crack.
 */
#ifndef CH03_CRACKS_H
#define CH03_CRACKS_H

#include "03_triangle/triangle.h"

typedef struct {
    long rays;   /* rays cast */
    long misses; /* rays that hit no face: cracks */
} crack_count;

/* The point a fraction s along the edge from e0 to e1: e0 + s (e1 - e0). */
vec3 edge_point(vec3 e0, vec3 e1, real s);

/* Whether r hits any of the n triangles in the window (0, infinity). */
bool hits_any(const triangle *tris, int n, ray r, triangle_test test);

/* Whether the point (beta, gamma) of tri lies within `width`, in barycentric
 * units, of an edge.  Then the nearest point of the edge, in the sense of
 * keeping the ratio of the other two barycentric coordinates, is
 * edge_point(*e0, *e1, *s); near two edges it is their common vertex
 * (*e0 = *e1, *s = 0).  The lab's --show=cracks aims rays exactly there. */
bool near_edge(const triangle *tri, real beta, real gamma, real width, vec3 *e0, vec3 *e1, real *s);

/* Origin k of the crack measurement in the icosahedron (centre, radius):
 * k = 0 is the centre, k >= 1 are scattered points inside the inscribed
 * sphere, the same on every run. */
vec3 crack_origin(vec3 centre, real radius, int k);

/* Casts, from each of origins 0 .. n_origins - 1, one ray at each of the 12
 * vertices and at edge_point(e0, e1, j / n_steps) for j = 1 .. n_steps - 1
 * on each of the 30 edges (the midpoint among them when n_steps is even),
 * and counts the rays that hit no face of the icosahedron. */
crack_count icosahedron_cracks(vec3 centre, real radius, int n_origins, int n_steps, triangle_test test);

#endif
