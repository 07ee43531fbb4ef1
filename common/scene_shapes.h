/* scene_shapes.h - the spheres and triangles that the surfaces of a scene file stand for.
 *
 * A Sphere is one sphere, a Triangle one triangle, a Box twelve triangles
 * (box_triangles) and a Mesh one triangle per face of its .obj file, wound
 * as the file winds it.  A box's triangles are wound counter-clockwise seen
 * from outside, so that every (b - a) x (c - a) points out of the box, as the
 * course's RGBNormals images show.  Corners are copied from the scene, never
 * computed: a box's are made of the coordinates of minPt and maxPt.
 */
#ifndef RT_SCENE_SHAPES_H
#define RT_SCENE_SHAPES_H

#include <stdbool.h>
#include <stddef.h>

#include "scene.h"
#include "vec3.h"

#define BOX_TRIANGLES 12

/* The box [min_pt, max_pt] (min_pt <= max_pt component-wise) as out[k] =
 * the corners a, b, c of triangle k: the faces -x, +x, -y, +y, -z, +z, two
 * triangles each. */
void box_triangles(vec3 min_pt, vec3 max_pt, vec3 out[BOX_TRIANGLES][3]);

typedef struct {
    bool is_sphere;
    vec3 center;   /* a sphere's */
    real radius;
    vec3 v[3];     /* a triangle's corners a, b, c */
    int shader;    /* the scene surface's: index into scene.shaders, -1 for none */
    int source;    /* index into scene.surfaces */
    int face;      /* which of the source's triangles: a Mesh's face, a Box's (0 .. 11); 0 otherwise */
} scene_shape;

/* Calls add(context, shape) for every shape of desc, surface by surface in
 * the file's order.  Returns 0, or -1 with "path:line: out of memory for the
 * surface list" in err as soon as add returns a negative number. */
int scene_shapes(const scene *desc, int (*add)(void *context, const scene_shape *shape), void *context, char *err,
                 size_t err_size);

#endif
