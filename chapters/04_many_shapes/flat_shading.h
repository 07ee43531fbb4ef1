/* flat_shading.h - chapter 04: one flat colour per surface, the lecture's
 * first Scene.trace (README, "Flat colours"). */
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
