/* Chapter 08's checks of inputs drawn at grading time (tests/answers.h):
 * mirror directions of directions and normals drawn from the grader's seed
 * (a few roundings of d: 16 REAL_EPSILON |d|), and scenes with mirrors drawn
 * from it rendered with shade_glazed (mirror_radiance's recursion;
 * seeded_scene.h says why that tolerance), against the reference's. */
#include "08_mirrors/mirror.h"
#include "08_mirrors/path.h"
#include "08_mirrors/shade_glazed.h"
#include "seeded_scene.h"

static void seeded_reflect(unsigned long *rng)
{
    for (int k = 0; k < 8; k++) {
        vec3 n = suite_random_unit(rng);
        vec3 d = vec3_scale(suite_random_unit(rng), (real)pow(10, seeded_between(rng, -1, 1)));
        vec3 r = reflect(d, n);
        suite_answer_vec3(describe("reflect(d = (%.9g, %.9g, %.9g), n = (%.9g, %.9g, %.9g))", d.x, d.y, d.z, n.x,
                                   n.y, n.z),
                          r, 16 * REAL_EPSILON * vec3_length(d));
    }
}

static void seeded_mirrors(unsigned long *rng)
{
    static const path_knobs knobs = PATH_KNOBS_DEFAULT;
    const stage_knobs aimed = {.spawn = &knobs.phong.spawn, .phong = &knobs.phong, .path = &knobs};
    seeded_scenes(rng, (seeded_materials){1, 1, 0}, shade_glazed, &aimed, "mirrors");
}

SEEDED_CHECKS(SEEDED(test_reflect_known, seeded_reflect), SEEDED(test_reflect_random, seeded_reflect),
              SEEDED(test_mirror_ray_reaches_probe, seeded_mirrors),
              SEEDED(test_mirror_ray_policy_from_knobs, seeded_mirrors),
              SEEDED(test_glazed_adds_to_chapter_07, seeded_mirrors),
              SEEDED(test_facing_mirrors_depth_and_weight, seeded_mirrors),
              SEEDED(test_convex_mirror_never_sees_itself, seeded_mirrors),
              SEEDED(test_furnace_mirror_sphere, seeded_mirrors), SEEDED(test_builtin_scene_rays, seeded_mirrors))
