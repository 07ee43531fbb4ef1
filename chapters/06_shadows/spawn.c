/* spawn.c - chapter 06: rays that leave a surface, and the epsilon policy. */
#include "06_shadows/spawn.h"

#include "explain.h"

const char *const eps_policy_names[] = {"none", "fixed", "bound", NULL};

eps_policy tracer_eps(const tracer *tr)
{
    const spawn_knobs defaults = SPAWN_KNOBS_DEFAULT;
    return (eps_policy)(tr->knobs.spawn ? tr->knobs.spawn : &defaults)->eps;
}

real eps_bound(const shading_point *sp)
{
    /* The point is p + t d, computed from the ray's origin p and the surface's
     * own coordinates (near the point's): each rounding is relative to those
     * magnitudes, and an intersection test takes a few dozen of them. */
    real magnitude = real_fmax(vec3_max_abs(sp->hit.point), vec3_max_abs(sp->r.p));
    return EPS_BOUND_ULPS * REAL_EPSILON * magnitude;
}

/* snippet: spawn_ray */
ray spawn_ray(const shading_point *sp, vec3 d, eps_policy policy)
{
    vec3 p = sp->hit.point;
    switch (policy) {
    case EPS_NONE: /* the classic blunder */
        break;
    case EPS_FIXED: /* 1e-3 along the ray, as the course's solution */
        p = vec3_add(p, vec3_scale(d, EPS_FIXED_OFFSET / vec3_length(d)));
        break;
    case EPS_BOUND: { /* off the surface, along the geometric normal, to d's side */
        vec3 n_g = sp->hit.normal;
        real offset = vec3_dot(d, n_g) >= 0 ? eps_bound(sp) : -eps_bound(sp);
        p = vec3_add(p, vec3_scale(n_g, offset));
        break;
    }
    }
    EXPLAIN(explain_spawn(eps_policy_names[policy], sp->hit.point, p, sp->hit.normal));
    return (ray){p, d};
}

ray spawn_ray_to(const shading_point *sp, vec3 target, eps_policy policy, real *t_max)
{
    ray r = spawn_ray(sp, vec3_sub(target, sp->hit.point), policy);
    r.d = vec3_sub(target, r.p); /* the target at t = 1 exactly */
    real length = vec3_length(r.d);
    real back_off = 0; /* in world units, before the target */
    if (policy == EPS_FIXED)
        back_off = EPS_FIXED_OFFSET;
    else if (policy == EPS_BOUND) /* a surface through the target is computed as far off as the point was */
        back_off = EPS_BOUND_ULPS * REAL_EPSILON * real_fmax(vec3_max_abs(target), vec3_max_abs(r.p));
    *t_max = 1 - back_off / length;
    EXPLAIN(explain_shadow_ray(r, *t_max, target));
    return r;
}
/* end snippet */
