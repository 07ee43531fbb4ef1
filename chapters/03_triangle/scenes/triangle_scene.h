/* triangle_scene.h - chapter 03: the built-in scene, a large triangle and an icosahedron. */
#ifndef CH03_TRIANGLE_SCENE_H
#define CH03_TRIANGLE_SCENE_H

#include "scene.h"

/* The 20 faces of the icosahedron (centre, radius) as Triangle surfaces;
 * 0, or -1 when out of memory. */
int triangle_scene_add_icosahedron(scene *desc, vec3 centre, real radius);

/* The built-in scene: a large triangle on the left, an icosahedron on the
 * right.  0, or -1 when out of memory. */
int triangle_scene(scene *desc);

#endif
