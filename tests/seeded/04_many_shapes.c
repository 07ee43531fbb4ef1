/* Chapter 04's checks of inputs drawn at grading time (tests/answers.h):
 * the closest hit among a list of spheres and triangles drawn from the
 * grader's seed, for rays drawn from it, against the reference's answers.
 * Each surface's own hit is the reference's (chapters 02 and 03 are the
 * reference in both runs), so the closest one is the same to the last bit
 * unless a window is narrowed otherwise: 16 REAL_EPSILON of the scene's
 * size in t, and the surface exactly. */
#include "04_many_shapes/closest_hit.h"
#include "seeded.h"

static void seeded_closest(unsigned long *rng)
{
    for (int n = 0; n < 4; n++) {
        surface_list list;
        surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
        int count = 2 + (int)seeded_between(rng, 0, 12);
        for (int k = 0; k < count; k++) {
            vec3 c = seeded_point(rng, 10);
            if (suite_uniform(rng) < 0.5) {
                surface_list_add_sphere(&list, (sphere){c, (real)seeded_between(rng, 0.3, 3)}, k, k);
            } else {
                vec3 a = vec3_add(c, seeded_point(rng, 3)), b = vec3_add(c, seeded_point(rng, 3));
                surface_list_add_triangle(&list, (triangle){c, a, b}, k, k);
            }
        }
        for (int k = 0; k < 8; k++) {
            ray r = {seeded_point(rng, 20), vec3_sub(seeded_point(rng, 6), seeded_point(rng, 20))};
            real t_max = k % 2 ? REAL_INFINITY : (real)seeded_between(rng, 0.2, 2);
            hit_record hit = {0};
            bool found = surfaces_intersect(&list, r, 0, t_max, &hit);
            const char *in = describe("surfaces_intersect(scene %d of %d surfaces, ray %d, window (0, %g))", n + 1,
                                      count, k + 1, t_max);
            suite_answer(describe("%s: hit", in), found, 0);
            suite_answer(describe("%s: surface", in), found ? hit.surface : -1, 0);
            suite_answer(describe("%s: t", in), found ? hit.t : 0, 16 * REAL_EPSILON * 40 / vec3_length(r.d));
        }
        surface_list_free(&list);
    }
}

SEEDED_CHECKS(SEEDED(test_closest_hit_in_any_order, seeded_closest), SEEDED(test_t_window, seeded_closest),
              SEEDED(test_empty_and_single, seeded_closest),
              SEEDED(test_coincident_surfaces_first_wins, seeded_closest),
              SEEDED(test_hit_record_fields, seeded_closest), SEEDED(test_box_in_scene, seeded_closest),
              SEEDED(test_scene_file, seeded_closest), SEEDED(test_rays_from_a_surface, seeded_closest),
              SEEDED(test_normals_are_unit, seeded_closest), SEEDED(test_floor_diagonal_has_no_holes, seeded_closest))
