/* shading_scene.h - chapter 05: the built-in scene of the shading chapters.
 *
 * One scene for chapters 05, 06 and 07 (and later chapters that extend it),
 * so that a lecture can show their images side by side: a floor, a matte and
 * a shiny sphere, a box, a triangle standing on the floor and a small sphere
 * floating above it, lit by two point lights, with a little ambient light.
 * Each chapter renders what its stage models: 05 the first light's Lambert
 * term, 06 its shadows, 07 both lights, the highlights and the ambient term.
 */
#ifndef CH05_SHADING_SCENE_H
#define CH05_SHADING_SCENE_H

#include "scene.h"

/* Fills desc (already scene_init'ed); 0, or -1 when out of memory. */
int shading_scene(scene *desc);

#endif
