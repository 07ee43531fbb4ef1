/* Chapter 06's checks of inputs drawn at grading time (tests/answers.h):
 * scenes drawn from the grader's seed rendered with shade_shadows, whose
 * radiance and shadow rays depend on light_blocked at every shading point
 * (seeded_scene.h says why the tolerance), against the reference's. */
#include "06_shadows/shade_shadows.h"
#include "seeded_scene.h"

static void seeded_shadows(unsigned long *rng)
{
    static const spawn_knobs knobs = SPAWN_KNOBS_DEFAULT;
    seeded_scenes(rng, (seeded_materials){0, 0, 0}, shade_shadows, &(stage_knobs){.spawn = &knobs}, "shadows");
}

SEEDED_CHECKS(SEEDED(test_occluder_between_beyond_behind, seeded_shadows),
              SEEDED(test_light_on_a_surface, seeded_shadows),
              SEEDED(test_shadow_rays_only_when_needed, seeded_shadows),
              SEEDED(test_no_acne_no_leak, seeded_shadows), SEEDED(test_light_behind_the_surface, seeded_shadows),
              SEEDED(test_shadow_ray_is_the_segment, seeded_shadows))
