/* tracer.c - chapter 05: the lecture's Scene.trace over any closest-hit query. */
#include "05_lambert/tracer.h"

#include "04_many_shapes/closest_hit.h"
#include "explain.h"
#include "surface_shader.h"

bool closest_hit_linear(const void *accel, ray r, real t_min, real t_max, hit_record *hit)
{
    return surfaces_intersect(accel, r, t_min, t_max, hit);
}

vec3 normal_towards_viewer(vec3 n, vec3 d)
{
    /* The viewer is at -d from the point: n faces it when n . (-d) > 0. */
    return vec3_dot(n, d) < 0 ? n : vec3_neg(n);
}

color trace(const tracer *tr, ray r, real t_min, real t_max, int depth, uint64_t *rays)
{
    EXPLAIN(explain_trace(r, t_min, t_max, depth, tr->weight, rays));
    hit_record hit;
    if (!tr->closest_hit(tr->accel, r, t_min, t_max, &hit)) {
        EXPLAIN(explain_miss(tr->desc->back_color); explain_radiance(tr->desc->back_color));
        return tr->desc->back_color;
    }
    shading_point sp = {.r = r, .hit = hit, .shader = surface_shader(tr->desc, hit.shader)};
    sp.v = vec3_neg(vec3_normalize(r.d));           /* v = -normalize(ray.direction) */
    sp.n = normal_towards_viewer(hit.normal, r.d); /* the normal, turned to face v */
    EXPLAIN(explain_closest(hit.surface, hit.source, hit.t, hit.point); explain_shading(hit.normal, sp.n, sp.v, sp.shader));
    color L = tr->shade(tr, &sp, depth, rays);
    EXPLAIN(explain_radiance(L));
    return L;
}
