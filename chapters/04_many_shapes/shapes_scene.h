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

/* Fills desc (already scene_init'ed); 0, or -1 when out of memory. */
int shapes_scene(scene *desc);

#endif
