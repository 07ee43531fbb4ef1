/* flat_shading.h - chapter 04: one flat colour per surface, the lecture's
 * first Scene.trace (README, "Flat colours"). */
#ifndef CH04_FLAT_SHADING_H
#define CH04_FLAT_SHADING_H

#include "04_many_shapes/surface.h"
#include "scene.h"

/* The flat colour of a hit: (n + 1) / 2 for RGBNormals, else the diffuseColor (none: white). */
color flat_color(const scene *desc, const hit_record *hit);

/* The flat colour of r's closest hit in (t_min, t_max), or the backColor when r hits nothing. */
color trace_flat(const surface_list *list, const scene *desc, ray r, real t_min, real t_max);

#endif
