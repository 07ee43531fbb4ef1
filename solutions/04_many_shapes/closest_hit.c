/* closest_hit.c - chapter 04: the first surface along a ray. */
#include "04_many_shapes/closest_hit.h"

bool surfaces_intersect(const surface_list *list, ray r, real t_min, real t_max, hit_record *hit)
{
    /* EXERCISE closest: the closest hit in (t_min, t_max) of all the list's surfaces, found by the
     * lecture's loop with surface_intersect, its index in hit->surface (README, "The closest hit"). */
    bool found = false;
    real t_best = t_max;
    for (int k = 0; k < list->n; k++) {
        hit_record candidate;
        if (surface_intersect(&list->items[k], list, r, t_min, t_best, &candidate)) {
            t_best = candidate.t; /* the ray now ends here: only closer hits count */
            candidate.surface = k;
            *hit = candidate;
            found = true;
        }
    }
    return found;
    /* STUB
    (void)list, (void)r, (void)t_min, (void)t_max, (void)hit;
    return false;
    END EXERCISE */
}
