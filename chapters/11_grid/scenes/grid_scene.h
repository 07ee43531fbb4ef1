/* grid_scene.h - chapter 11: the built-in scene, what grids are for and where they break.
 *
 * A floor of two huge triangles under a torus of 2304 small ones and a
 * spiral of 1000 small spheres, one big sphere behind them, lit by two point
 * lights: 3307 surfaces, most of them small and far apart, and two that
 * span the whole grid.
 */
#ifndef CH11_GRID_SCENE_H
#define CH11_GRID_SCENE_H

#include "scene.h"

/* Fills desc (already scene_init'ed); 0, or -1 when out of memory. */
int grid_scene(scene *desc);

#endif
