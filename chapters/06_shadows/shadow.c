/* shadow.c - chapter 06: is the light blocked? */
#include "06_shadows/shadow.h"
#include "exercise.h"

bool light_blocked(const tracer *tr, const shading_point *sp, vec3 light_pos, eps_policy policy, uint64_t *rays)
{
    /* TODO shadow: whether the light at light_pos is blocked from sp's point, by the surface itself
     * (a light behind it, as the shading normal sees it, needs no ray) or by any surface on the shadow
     * segment from the point to the light; the segment leaves the surface by `policy`, and each shadow
     * ray cast is counted (README, "The shadow ray" and "One way out for every secondary ray"). */
    EXERCISE_STUB("06_shadows", "shadow.c", "shadow"); /* delete this line when done */
    (void)tr, (void)sp, (void)light_pos, (void)policy, (void)rays;
    return false;
}
