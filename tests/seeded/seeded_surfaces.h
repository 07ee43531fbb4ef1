/* seeded_surfaces.h - a list of surfaces drawn at grading time, and the
 * answers of a closest-hit query (tests/answers.h; chapters 04 and 11).
 * Header only, in static functions. */
#ifndef RT_TESTS_SEEDED_SURFACES_H
#define RT_TESTS_SEEDED_SURFACES_H

#include "04_many_shapes/surface.h"
#include "seeded.h"

/* list (initialized here: robust spheres, watertight triangles; free it):
 * `count` spheres (radius size / 10 to size) and triangles (corners within
 * size of each other), half and half, about the origin within 10. */
static inline void seeded_surfaces(unsigned long *rng, surface_list *list, int count, double size)
{
    surface_list_init(list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
    for (int k = 0; k < count; k++) {
        vec3 c = seeded_point(rng, 10);
        if (suite_uniform(rng) < 0.5) {
            surface_list_add_sphere(list, (sphere){c, (real)seeded_between(rng, size / 10, size)}, k, k);
        } else {
            vec3 a = vec3_add(c, seeded_point(rng, size)), b = vec3_add(c, seeded_point(rng, size));
            surface_list_add_triangle(list, (triangle){c, a, b}, k, k);
        }
    }
}

/* A ray from within 20 of the origin towards a point within 8 of it. */
static inline ray seeded_ray(unsigned long *rng)
{
    vec3 p = seeded_point(rng, 20);
    return (ray){p, vec3_sub(seeded_point(rng, 8), p)};
}

/* The answers of a query for ray r: whether it hit, which surface, and t.
 * Each surface's own hit is the reference's in both runs, so the closest is
 * the same to the last bit unless a window is narrowed otherwise: 16
 * REAL_EPSILON of the scene's size (40) in t, and the surface exactly. */
static inline void seeded_answer_hit(const char *in, ray r, bool found, const hit_record *hit)
{
    suite_answer(describe("%s: hit", in), found, 0);
    suite_answer(describe("%s: surface", in), found ? hit->surface : -1, 0);
    suite_answer(describe("%s: t", in), found ? hit->t : 0, 16 * REAL_EPSILON * 40 / vec3_length(r.d));
}

#endif
