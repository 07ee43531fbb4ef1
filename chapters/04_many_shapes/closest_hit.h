/* closest_hit.h - chapter 04: the first surface along a ray, the lecture's
 * "Intersection against many shapes" (README, "The closest hit"). */
#ifndef CH04_CLOSEST_HIT_H
#define CH04_CLOSEST_HIT_H

#include "04_many_shapes/surface.h"

/* The hit with the smallest t in (t_min, t_max) over the list, hit->surface its index (at the same t
 * the first in the list wins): true when there is one, else *hit is left unchanged. */
bool surfaces_intersect(const surface_list *list, ray r, real t_min, real t_max, hit_record *hit);

#endif
