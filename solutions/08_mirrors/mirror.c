/* mirror.c - chapter 08: the mirror direction and the mirror term L_m. */
#include "08_mirrors/mirror.h"

#include "06_shadows/spawn.h"
#include "08_mirrors/path.h"

vec3 reflect(vec3 d, vec3 n)
{
    /* EXERCISE reflect: the mirror direction of the ray's direction d (any length) about the unit
     * normal n (README, "The mirror direction"). */
    return vec3_sub(d, vec3_scale(n, 2 * vec3_dot(d, n)));
    /* STUB
    (void)n;
    return d;
    END EXERCISE */
}

color mirror_radiance(const tracer *tr, const shading_point *sp, color k_m, int depth, uint64_t *rays)
{
    /* EXERCISE recursion: L_m, the radiance seen from sp's point in the mirror direction: the reflected
     * ray with its weight k_m, if the path goes on at all, leaving the surface as every secondary ray
     * does, counted, and traced one level deeper (README, "Calling trace again" and "Where the mirror
     * ray starts"). */
    tracer next;
    if (!path_next(tr, depth, k_m, &next))
        return color_make(0, 0, 0);
    ray mirror = spawn_ray(sp, reflect(sp->r.d, sp->n), tracer_eps(tr));
    ++rays[RAY_REFLECTED];
    return trace(&next, mirror, 0, REAL_INFINITY, depth + 1, rays);
    /* STUB
    (void)tr, (void)sp, (void)k_m, (void)depth, (void)rays;
    return color_make(0, 0, 0);
    END EXERCISE */
}
