/* scene_cost.h - what a scene costs a stage without an acceleration structure.
 *
 * Before chapter 11 every ray tests every surface (chapter 04's linear scan),
 * so a mesh of a few thousand triangles takes minutes where chapter 11's grid
 * takes a second (the teapot: 77 s with chapter 07, 0.5 s with chapter 11).
 * The renderer says so before it starts (renderer.c).
 */
#ifndef RT_SCENE_COST_H
#define RT_SCENE_COST_H

#include <stddef.h>

#include "scene.h"

/* Above this many triangles a stage without the grid is warned of. */
#define SCENE_MANY_TRIANGLES 4096

/* The triangles a stage that models the features `modelled` tests for each
 * ray: the Triangle surfaces and, when it models meshes, every mesh face. */
long scene_triangles(const scene *s, unsigned modelled);

/* When the stage has no acceleration structure and the scene more than
 * SCENE_MANY_TRIANGLES triangles, one sentence saying it will be slow and
 * that chapter 11 makes it fast; else "". */
void scene_cost_note(const scene *s, unsigned modelled, char *out, size_t out_size);

#endif
