/* closest_hit.c - chapter 04: the first surface along a ray. */
#include "04_many_shapes/closest_hit.h"
#include "exercise.h"

/* snippet: surfaces_intersect */
bool surfaces_intersect(const surface_list *list, ray r, real t_min, real t_max, hit_record *hit)
{
    /* TODO closest: the lecture's "Intersection against many shapes":
     *     tBest = tMax; firstSurface = null
     *     for surface in surfaceList
     *         hitSurface, t = surface.intersect(ray, tMin, tBest)
     *         if hitSurface is not null: tBest = t; firstSurface = hitSurface
     * Test surface k with surface_intersect(&list->items[k], list, r, t_min, t_best, &candidate):
     * it only reports hits with t < t_best, so every hit it reports is closer
     * than the best so far.  Copy such a candidate to *hit, set hit->surface = k,
     * and return whether anything was hit. */
    EXERCISE_STUB("04_many_shapes", "closest_hit.c", "closest"); /* delete this line when done */
    (void)list;
    (void)r;
    (void)t_min;
    (void)t_max;
    (void)hit;
    return false;
}
/* end snippet */
