/* shade_glass.c - chapter 09: the shade function of the refraction stage. */
#include "09_refraction/shade_glass.h"

#include "06_shadows/spawn.h"
#include "08_mirrors/mirror.h"
#include "08_mirrors/shade_glazed.h"
#include "09_refraction/refract.h"
#include "explain.h"

fresnel_mode tracer_fresnel(const tracer *tr)
{
    const glass_knobs defaults = GLASS_KNOBS_DEFAULT;
    return (fresnel_mode)(tr->knobs.glass ? tr->knobs.glass : &defaults)->fresnel;
}

glass_event glass_at(const shading_point *sp, real eta, fresnel_mode mode)
{
    glass_event e;
    bool entering = vec3_dot(sp->r.d, sp->hit.normal) < 0; /* the geometric normal points out of the glass */
    e.eta_i = entering ? 1 : eta;                           /* on the way out the indices swap ... */
    e.eta_t = entering ? eta : 1;
    vec3 n = sp->n; /* ... and the normal is flipped: sp->n faces the incoming ray already */
    vec3 d = vec3_neg(sp->v);
    e.cos_i = vec3_dot(sp->v, n);
    e.transmits = refract(d, n, e.eta_i, e.eta_t, &e.T, &e.cos_t);
    e.R = e.transmits ? fresnel(mode, e.cos_i, e.cos_t, e.eta_i, e.eta_t) : 1; /* TIR reflects it all */
    return e;
}

color transmitted_radiance(const tracer *tr, const shading_point *sp, vec3 T, color k, int depth, uint64_t *rays)
{
    tracer next;
    if (!path_next(tr, depth, k, &next))
        return color_make(0, 0, 0);
    ray through = spawn_ray(sp, T, tracer_eps(tr)); /* starts on the far side of the surface */
    ++rays[RAY_REFRACTED];
    return trace(&next, through, 0, REAL_INFINITY, depth + 1, rays);
}

color shade_glass(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays)
{
    const scene_shader *shader = sp->shader;
    if (shader->kind != SHADER_GLASS)
        return shade_glazed(tr, sp, depth, rays); /* chapter 08 */
    glass_event e = glass_at(sp, shader->refractive_index, tracer_fresnel(tr));
    EXPLAIN(explain_glass(e.eta_i, e.eta_t, e.cos_i, e.transmits, e.cos_t, e.R));
    /* EXERCISE glass: the lecture's recursive term for glass, L = R L_reflected + (1 - R) L_transmitted
     * from the event e: each ray traced one level deeper with its weight as the path's coefficient, and
     * only the rays that carry light (README, "The glass shader"; mirror.h and shade_glass.h say what
     * mirror_radiance and transmitted_radiance trace). */
    color R = color_make(e.R, e.R, e.R), T = color_make(1 - e.R, 1 - e.R, 1 - e.R);
    color L = color_make(0, 0, 0);
    if (e.R > 0) /* R L_reflected */
        L = color_mul(R, mirror_radiance(tr, sp, R, depth, rays));
    if (e.transmits && e.R < 1) /* + (1 - R) L_transmitted */
        L = color_add(L, color_mul(T, transmitted_radiance(tr, sp, e.T, T, depth, rays)));
    return L;
    /* STUB
    (void)depth, (void)rays;
    return color_make(0, 0, 0);
    END EXERCISE */
}
