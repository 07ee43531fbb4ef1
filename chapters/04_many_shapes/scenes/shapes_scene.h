/* shapes_scene.h - chapter 04: the built-in scene, overlapping shapes in flat colours.
 *
 * A floor slab, two spheres that cut into each other, a box pushed into one
 * of them, a standing triangle and a small RGBNormals sphere, each its own
 * flat colour.  The shading chapters' scene (05_lambert/shading_scene.h)
 * puts its shapes in the same places and looks at them the same way.
 */
#ifndef CH04_SHAPES_SCENE_H
#define CH04_SHAPES_SCENE_H

#include "scene.h"

/* The camera: 2.2 above the floor and 6.5 back, looking ahead and down. */
void shapes_view(scene *desc);

/* The four shapes both scenes share, in this order, with the given shaders:
 * the floor slab, the red and the blue sphere that cut into each other, and
 * the green box pushed into the blue one.  0, or -1 when out of memory. */
int shapes_add_solids(scene *desc, const int shader[4]);

/* Fills desc (already scene_init'ed); 0, or -1 when out of memory. */
int shapes_scene(scene *desc);

#endif
