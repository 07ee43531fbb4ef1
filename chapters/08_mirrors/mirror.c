/* mirror.c - chapter 08: the mirror direction and the mirror term L_m. */
#include "08_mirrors/mirror.h"
#include "exercise.h"

#include "06_shadows/spawn.h"
#include "08_mirrors/path.h"

/* snippet: reflect */
vec3 reflect(vec3 d, vec3 n)
{
    /* TODO reflect: the lecture's mirror direction r = 2 (n . v) n - v,
     *     written for the ray's direction d = -v:
     *         r = d - 2 (d . n) n
     *     n is a unit vector; d may have any length (r gets the same one). */
    EXERCISE_STUB("08_mirrors", "mirror.c", "reflect"); /* delete this line when done */
    (void)n;
    return d;
}
/* end snippet */

/* snippet: mirror_radiance */
color mirror_radiance(const tracer *tr, const shading_point *sp, color k_m, int depth, uint64_t *rays)
{
    /* TODO recursion: the lecture's "ask what color is seen from surface
     *     point in reflection direction", by calling trace() again:
     *     - ask path_next(tr, depth, k_m, &next) whether the ray is cast at
     *       all (the depth, the path's weight); if not, it brings black;
     *     - the mirror direction: reflect(sp->r.d, sp->n);
     *     - the ray leaves the surface as a shadow ray does (chapter 06):
     *       spawn_ray(sp, direction, tracer_eps(tr));
     *     - count it: ++rays[RAY_REFLECTED];
     *     - and trace it, one level deeper: trace(&next.tr, ray, 0,
     *       REAL_INFINITY, depth + 1, rays). */
    EXERCISE_STUB("08_mirrors", "mirror.c", "recursion"); /* delete this line when done */
    (void)tr;
    (void)sp;
    (void)k_m;
    (void)depth;
    (void)rays;
    return color_make(0, 0, 0);
}
/* end snippet */
