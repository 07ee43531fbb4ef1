/* closest_hit.c - chapter 04: the first surface along a ray. */
#include "04_many_shapes/closest_hit.h"
#include "exercise.h"

bool surfaces_intersect(const surface_list *list, ray r, real t_min, real t_max, hit_record *hit)
{
    /* TODO closest: the closest hit in (t_min, t_max) of all the list's surfaces, found by the
     * lecture's loop with surface_intersect, its index in hit->surface (README, "The closest hit"). */
    EXERCISE_STUB("04_many_shapes", "closest_hit.c", "closest"); /* delete this line when done */
    (void)list, (void)r, (void)t_min, (void)t_max, (void)hit;
    return false;
}
