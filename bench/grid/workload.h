/* workload.h - bench-grid's mesh and rays (workload.c): every vertex and every
 * ray rounded to float, so that Embree (which works in float) and the grid
 * (in `real`) get the same numbers. */
#ifndef BENCH_GRID_WORKLOAD_H
#define BENCH_GRID_WORKLOAD_H

#include "ray.h"

typedef struct {
    float *v;      /* 3 per vertex */
    unsigned *tri; /* 3 per triangle */
    long n_v, n_tri;
} float_mesh;

typedef struct {
    float o[3], d[3];
} float_ray;

/* The mesh of an OBJ file (exits with a message when it cannot be read). */
void load_obj(const char *path, float_mesh *fm);

/* A unit sphere of about `wanted` triangles. */
void make_sphere(long wanted, float_mesh *fm);

/* Vertex k of the mesh, as a vec3. */
vec3 mesh_vertex(const float_mesh *fm, unsigned k);

/* The bounding box of the mesh's vertices. */
void mesh_box(const float_mesh *fm, float lo[3], float hi[3]);

/* size x size primary rays of a pinhole camera whose view the mesh fills. */
float_ray *make_rays(const float_mesh *fm, int size);

/* n incoherent rays: origins uniform in the mesh's box, directions uniform on the sphere. */
float_ray *make_random_rays(const float_mesh *fm, long n);

/* The ray in `real` (inline: the timed loops make one per ray). */
static inline ray to_ray(const float_ray *r)
{
    return (ray){{r->o[0], r->o[1], r->o[2]}, {r->d[0], r->d[1], r->d[2]}};
}

#endif
