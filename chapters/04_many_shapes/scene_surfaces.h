/* scene_surfaces.h - chapter 04: the surface list of a scene description.
 *
 * Every surface of the scene file, in the file's order:
 *   Sphere   -> one sphere
 *   Triangle -> one triangle (v0, v1, v2)
 *   Box      -> 12 triangles (box.h), normals pointing out of the box
 *   Mesh     -> one triangle per face of the .obj file, wound as the file
 *               winds it; per-vertex normals and texture coordinates wait
 *               for chapter 10
 * Each keeps its scene surface's shader and its own index in the scene.
 */
#ifndef CH04_SCENE_SURFACES_H
#define CH04_SCENE_SURFACES_H

#include <stddef.h>

#include "04_many_shapes/surface.h"
#include "scene.h"

/* Fills `list` (already surface_list_init'ed, usually empty).  Returns 0, or
 * -1 with "path:line: problem" in err when out of memory. */
int surface_list_from_scene(surface_list *list, const scene *desc, char *err, size_t err_size);

#endif
