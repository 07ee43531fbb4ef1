/* surface.h - chapter 04: the lecture's surfaceList, spheres and triangles (a Box's or a Mesh's)
 * with their shaders and the knobs every intersection uses (README, "The surface list"). */
#ifndef CH04_SURFACE_H
#define CH04_SURFACE_H

#include <stddef.h>

#include "02_sphere/sphere.h" /* and ray.h */
#include "03_triangle/triangle.h"
#include "scene.h"

typedef enum { SHAPE_SPHERE, SHAPE_TRIANGLE } shape_kind;

/* snippet: surface */
typedef struct {
    shape_kind kind;
    union {
        sphere sphere;     /* SHAPE_SPHERE */
        triangle triangle; /* SHAPE_TRIANGLE */
    };
    int shader; /* index into scene.shaders; -1: none (white) */
    int source; /* index into scene.surfaces: the Sphere, Box, Mesh or Triangle it came from */
    int face;   /* which piece of that source: a Mesh's face, a Box's triangle (0 .. 11); 0 otherwise */
} surface;

typedef struct {
    surface *items;
    int n, capacity;
    sphere_formula sphere_formula; /* --sphere: passed to every sphere_intersect */
    triangle_test triangle_test;   /* --triangle: passed to every triangle_intersect */
} surface_list;
/* end snippet */

/* snippet: hit_record */
typedef struct {
    real t;           /* the ray parameter: the hit is at p + t d */
    vec3 point;       /* p + t d */
    vec3 normal;      /* unit normal of the surface at point, NOT turned towards the ray:
                       * a sphere's points outwards, a triangle's is normalize((b - a) x (c - a)) */
    int surface;      /* index into the surface_list */
    int source;       /* index into scene.surfaces */
    int face;         /* which piece of the source: a Mesh's face, a Box's triangle; 0 otherwise */
    int shader;       /* index into scene.shaders; -1: none */
    real beta, gamma; /* a triangle's barycentric coordinates of point; 0 for a sphere */
} hit_record;
/* end snippet */

/* snippet: default_test */
/* From here on: Cramer's rule lets rays through shared edges (README, "Cracks in an ordinary image"). */
#define TRIANGLE_TEST_DEFAULT TRIANGLE_WATERTIGHT
/* end snippet */

/* An empty list with the given knobs; append one surface: its index, or -1 when out of memory. */
void surface_list_init(surface_list *list, sphere_formula formula, triangle_test test);
void surface_list_free(surface_list *list);
int surface_list_add_sphere(surface_list *list, sphere s, int shader, int source);
int surface_list_add_triangle(surface_list *list, triangle tri, int shader, int source);

/* Appends the scene's shapes (scene_shapes.h) in the file's order: 0, or -1 with "path:line: problem" in err. */
int surface_list_from_scene(surface_list *list, const scene *desc, char *err, size_t err_size);

/* One surface against the ray, with the list's knobs: true when it is hit at some t in (t_min, t_max);
 * then *hit holds everything but hit->surface, which only the list knows (unchanged on a miss). */
bool surface_intersect(const surface *s, const surface_list *list, ray r, real t_min, real t_max, hit_record *hit);

/* The record of a hit of s at t with unit normal n (beta, gamma: 0 for a sphere). */
hit_record surface_hit_record(const surface *s, ray r, real t, vec3 n, real beta, real gamma);

#endif
