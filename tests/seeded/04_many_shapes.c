/* Chapter 04's checks of inputs drawn at grading time (tests/answers.h):
 * the closest hit among a list of spheres and triangles drawn from the
 * grader's seed, for rays and windows drawn from it, against the
 * reference's answers (seeded_surfaces.h says why the tolerance). */
#include "04_many_shapes/closest_hit.h"
#include "seeded_surfaces.h"

static void seeded_closest(unsigned long *rng)
{
    for (int n = 0; n < 4; n++) {
        surface_list list;
        int count = 2 + (int)seeded_between(rng, 0, 12);
        seeded_surfaces(rng, &list, count, 3);
        for (int k = 0; k < 8; k++) {
            ray r = seeded_ray(rng);
            real t_max = k % 2 ? REAL_INFINITY : (real)seeded_between(rng, 0.2, 2);
            hit_record hit = {0};
            bool found = surfaces_intersect(&list, r, 0, t_max, &hit);
            seeded_answer_hit(describe("surfaces_intersect(scene %d of %d surfaces, ray %d, window (0, %g))", n + 1,
                                       count, k + 1, t_max),
                              r, found, &hit);
        }
        surface_list_free(&list);
    }
}

SEEDED_CHECKS(SEEDED(test_closest_hit_in_any_order, seeded_closest), SEEDED(test_t_window, seeded_closest),
              SEEDED(test_closest_at_any_scale, seeded_closest),
              SEEDED(test_empty_and_single, seeded_closest),
              SEEDED(test_coincident_surfaces_first_wins, seeded_closest),
              SEEDED(test_hit_record_fields, seeded_closest), SEEDED(test_box_in_scene, seeded_closest),
              SEEDED(test_scene_file, seeded_closest), SEEDED(test_rays_from_a_surface, seeded_closest),
              SEEDED(test_normals_are_unit, seeded_closest), SEEDED(test_floor_diagonal_has_no_holes, seeded_closest))
