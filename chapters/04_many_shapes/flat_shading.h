/* flat_shading.h - chapter 04: one flat colour per surface.
 *
 * Before any light (chapter 05), the lecture's first scene image colours a
 * pixel by the surface its ray hits first:
 *
 *     Scene.trace(ray, tMin, tMax)
 *         surface, t = surfs.intersect(ray, tMin, tMax)
 *         if surface is not null: return surface.color()
 *         else return backgroundColor
 *
 * surface.color() is looked up in the scene description by the hit's shader
 * index: geometry (the surface list) and shading (the scene's shaders) stay
 * apart, and chapter 05 changes only this lookup.
 */
#ifndef CH04_FLAT_SHADING_H
#define CH04_FLAT_SHADING_H

#include "04_many_shapes/surface.h"
#include "scene.h"

/* The flat colour of a hit: RGBNormals shows (n + 1) / 2; any other shader
 * its diffuseColor; a surface without a shader is white. */
color flat_color(const scene *desc, const hit_record *hit);

/* The colour seen along r: the flat colour of the closest hit in
 * (t_min, t_max), or the scene's backColor when the ray hits nothing. */
color trace_flat(const surface_list *list, const scene *desc, ray r, real t_min, real t_max);

#endif
