/* glass_scene.h - chapter 09: the built-in scene of the refraction stage.
 *
 * A glass sphere (eta = 1.5) standing over a chequered floor, with a red
 * sphere, a blue box and a yellow triangle behind it and a mirror ball of
 * chapter 08 to its right: through the glass the floor's squares are bent
 * and the shapes behind it appear upside down and shrunk, and its rim
 * reflects the room as Fresnel's R grows towards grazing angles.
 */
#ifndef CH09_GLASS_SCENE_H
#define CH09_GLASS_SCENE_H

#include "scene.h"

/* The checker floor: GLASS_SCENE_TILES x GLASS_SCENE_TILES squares of side
 * GLASS_SCENE_TILE, two triangles each, centred on the origin in the plane
 * y = 0 (few: chapter 04's linear scan tries every triangle for every ray). */
#define GLASS_SCENE_TILES 8
#define GLASS_SCENE_TILE ((real)1.5)

/* Fills desc (already scene_init'ed); 0, or -1 when out of memory. */
int glass_scene(scene *desc);

#endif
