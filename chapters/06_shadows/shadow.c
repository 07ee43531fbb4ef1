/* shadow.c - chapter 06: is the light blocked? */
#include "06_shadows/shadow.h"
#include "exercise.h"

/* snippet: light_blocked */
bool light_blocked(const tracer *tr, const shading_point *sp, vec3 light_pos, eps_policy policy, uint64_t *rays)
{
    /* TODO shadow: the lecture's shadow ray, shadRay = (point, light.pos - point):
     *     build it with spawn_ray_to(sp, light_pos, policy, &t_max), which moves
     *     its start off the surface as the policy says, puts the light at t = 1
     *     and gives t_max, where the segment ends;
     *     count it: ++rays[RAY_SHADOW];
     *     it is blocked when tr->closest_hit(tr->accel, ray, 0, t_max, &hit)
     *     finds a surface in (0, t_max). */
    EXERCISE_STUB("06_shadows", "shadow.c", "shadow"); /* delete this line when done */
    (void)tr;
    (void)sp;
    (void)light_pos;
    (void)policy;
    (void)rays;
    return false;
}
/* end snippet */
