/* Chapter 07's checks of inputs drawn at grading time (tests/answers.h):
 * the specular term of a light in both forms (its half vector inside it), at points,
 * normals, views and lights drawn from the grader's seed, and scenes drawn
 * from it rendered with shade_phong (the loop over the lights; seeded_scene.h
 * says why that tolerance), against the reference's answers.  The specular term
 * carries light.pos - point's rounding, (1 + |point| / r) REAL_EPSILON
 * relative, times the exponent p in (n . h)^p: 64 (p + 1) (1 + |point| / r)
 * REAL_EPSILON of k_s I / r^2. */
#include "07_blinn_phong/phong.h"
#include "07_blinn_phong/shade_phong.h"
#include "seeded_scene.h"

static void seeded_specular(unsigned long *rng)
{
    for (int k = 0; k < 8; k++) {
        vec3 point = seeded_point(rng, 50), n = suite_random_unit(rng);
        vec3 v = seeded_at_angle(rng, n, seeded_between(rng, 0, 1.5));
        double r = seeded_between(rng, 1, 10);
        vec3 l = seeded_at_angle(rng, n, seeded_between(rng, 0, 1.5));
        scene_light light = {.position = vec3_add(point, vec3_scale(l, (real)r)),
                             .intensity = seeded_color(rng, 1, 30)};
        color k_s = seeded_color(rng, 0.1, 1);
        real p = (real)seeded_between(rng, 1, 50);
        phong_form form = k % 2 ? PHONG_LECTURE : PHONG_COURSE;
        color L = blinn_phong_specular(k_s, p, point, n, v, &light, form);
        double top = fmax(k_s.r * light.intensity.r, fmax(k_s.g * light.intensity.g, k_s.b * light.intensity.b));
        double tol = 64 * REAL_EPSILON * (p + 1) * (1 + vec3_length(point) / r) * top / (r * r);
        suite_answer_rgb(describe("blinn_phong_specular(k_s = (%.9g, %.9g, %.9g), p = %.9g, point (%.9g, %.9g, "
                                  "%.9g), n = (%.9g, %.9g, %.9g), v = (%.9g, %.9g, %.9g), light at (%.9g, %.9g, "
                                  "%.9g), %s)",
                                  k_s.r, k_s.g, k_s.b, p, point.x, point.y, point.z, n.x, n.y, n.z, v.x, v.y, v.z,
                                  light.position.x, light.position.y, light.position.z, phong_form_names[form]),
                         L, tol);
    }
}

static void seeded_lights(unsigned long *rng)
{
    static const phong_knobs knobs = PHONG_KNOBS_DEFAULT;
    const stage_knobs aimed = {.spawn = &knobs.spawn, .phong = &knobs};
    seeded_scenes(rng, (seeded_materials){1, 0, 0}, shade_phong, &aimed, "shade_phong");
}

SEEDED_CHECKS(SEEDED(test_half_vector, seeded_specular), SEEDED(test_exponent_behaviour, seeded_specular),
              SEEDED(test_course_and_lecture_forms, seeded_specular),
              SEEDED(test_specular_per_channel, seeded_specular),
              SEEDED(test_two_lights_add, seeded_lights), SEEDED(test_ambient_and_lights_behind, seeded_lights),
              SEEDED(test_back_face_lights, seeded_lights), SEEDED(test_shadow_policy_from_knobs, seeded_lights))
