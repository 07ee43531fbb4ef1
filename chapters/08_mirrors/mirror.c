/* mirror.c - chapter 08: the mirror direction and the mirror term L_m. */
#include "08_mirrors/mirror.h"
#include "exercise.h"

#include "06_shadows/spawn.h"
#include "08_mirrors/path.h"

vec3 reflect(vec3 d, vec3 n)
{
    /* TODO reflect: the mirror direction of the ray's direction d (any length) about the unit
     * normal n (README, "The mirror direction"). */
    EXERCISE_STUB("08_mirrors", "mirror.c", "reflect"); /* delete this line when done */
    (void)n;
    return d;
}

color mirror_radiance(const tracer *tr, const shading_point *sp, color k_m, int depth, uint64_t *rays)
{
    /* TODO recursion: L_m, the radiance seen from sp's point in the mirror direction: the reflected
     * ray with its weight k_m, if the path goes on at all, leaving the surface as every secondary ray
     * does, counted, and traced one level deeper (README, "Calling trace again" and "Where the mirror
     * ray starts"). */
    EXERCISE_STUB("08_mirrors", "mirror.c", "recursion"); /* delete this line when done */
    (void)tr, (void)sp, (void)k_m, (void)depth, (void)rays;
    return color_make(0, 0, 0);
}
