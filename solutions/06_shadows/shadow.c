/* shadow.c - chapter 06: is the light blocked? */
#include "06_shadows/shadow.h"

bool light_blocked(const tracer *tr, const shading_point *sp, vec3 light_pos, eps_policy policy, uint64_t *rays)
{
    /* EXERCISE shadow: whether the light at light_pos is blocked from sp's point, by the surface itself
     * (a light behind it, as the shading normal sees it, needs no ray) or by any surface on the shadow
     * segment from the point to the light; the segment leaves the surface by `policy`, and each shadow
     * ray cast is counted (README, "The shadow ray" and "One way out for every secondary ray"). */
    if (!(vec3_dot(sp->n, vec3_sub(light_pos, sp->hit.point)) > 0)) /* the light is behind the surface */
        return true;
    real t_max;
    ray shadow = spawn_ray_to(sp, light_pos, policy, &t_max); /* the light at t = 1, the segment ends at t_max */
    ++rays[RAY_SHADOW];
    hit_record blocker;
    return t_max > 0 && tr->closest_hit(tr->accel, shadow, 0, t_max, &blocker);
    /* STUB
    (void)tr, (void)sp, (void)light_pos, (void)policy, (void)rays;
    return false;
    END EXERCISE */
}
