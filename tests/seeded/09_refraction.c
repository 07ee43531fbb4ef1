/* Chapter 09's checks of inputs drawn at grading time (tests/answers.h):
 * transmitted directions and Fresnel's reflectance (exact and Schlick's)
 * for directions, normals and indices drawn from the grader's seed, and
 * scenes with glass drawn from it rendered with shade_glass (seeded_scene.h
 * says why that tolerance), against the reference's answers.  The angles
 * stay 0.05 radians from the critical angle, where cos(theta_t) =
 * sqrt(1 - |S_t|^2) loses digits: away from it T and cos(theta_t) are a
 * few roundings of unit values (64 REAL_EPSILON), and R a few more (64). */
#include "09_refraction/fresnel.h"
#include "09_refraction/refract.h"
#include "09_refraction/shade_glass.h"
#include "seeded_scene.h"

/* Indices, and an incoming unit direction away from the critical angle. */
static void draw(unsigned long *rng, vec3 *d, vec3 *n, real *eta_i, real *eta_t)
{
    *eta_i = (real)seeded_between(rng, 1, 2);
    *eta_t = (real)seeded_between(rng, 1, 2);
    double critical = *eta_i > *eta_t ? asin(*eta_t / *eta_i) : 10, theta;
    do
        theta = seeded_between(rng, 0, 1.5);
    while (fabs(theta - critical) < 0.05);
    *n = suite_random_unit(rng);
    *d = seeded_at_angle(rng, vec3_neg(*n), theta);
}

static void seeded_refract(unsigned long *rng)
{
    for (int k = 0; k < 10; k++) {
        vec3 d, n, T = {0, 0, 0};
        real eta_i, eta_t, cos_t = 0;
        draw(rng, &d, &n, &eta_i, &eta_t);
        bool through = refract(d, n, eta_i, eta_t, &T, &cos_t);
        const char *in = describe("refract(d = (%.9g, %.9g, %.9g), n = (%.9g, %.9g, %.9g), eta_i = %.9g, eta_t = "
                                  "%.9g)",
                                  d.x, d.y, d.z, n.x, n.y, n.z, eta_i, eta_t);
        suite_answer(describe("%s: transmitted", in), through, 0);
        suite_answer_vec3(describe("%s: T", in), through ? T : vec3_make(0, 0, 0), 64 * REAL_EPSILON);
        suite_answer(describe("%s: cos_t", in), through ? cos_t : 0, 64 * REAL_EPSILON);
    }
}

static void seeded_fresnel(unsigned long *rng)
{
    for (int k = 0; k < 10; k++) {
        vec3 d, n;
        real eta_i, eta_t;
        draw(rng, &d, &n, &eta_i, &eta_t);
        /* the cosines by Snell's law here, not by the student's refract */
        double cos_i = -vec3_dot(d, n), sin2_t = (eta_i / eta_t) * (eta_i / eta_t) * (1 - cos_i * cos_i);
        if (sin2_t >= 1)
            continue; /* total internal reflection: no cos_t */
        real cos_t = (real)sqrt(1 - sin2_t);
        const char *in = describe("(cos_i = %.9g, cos_t = %.9g, eta_i = %.9g, eta_t = %.9g)", cos_i, cos_t, eta_i,
                                  eta_t);
        suite_answer(describe("fresnel_exact%s", in), fresnel_exact((real)cos_i, cos_t, eta_i, eta_t),
                     64 * REAL_EPSILON);
        suite_answer(describe("fresnel_schlick%s", in), fresnel_schlick((real)cos_i, cos_t, eta_i, eta_t),
                     64 * REAL_EPSILON);
    }
}

static void seeded_glass(unsigned long *rng)
{
    static const glass_knobs knobs = GLASS_KNOBS_DEFAULT;
    const path_knobs *path = &knobs.path;
    const stage_knobs aimed = {.spawn = &path->phong.spawn, .phong = &path->phong, .path = path, .glass = &knobs};
    seeded_scenes(rng, (seeded_materials){1, 1, 1}, shade_glass, &aimed, "glass");
}

SEEDED_CHECKS(SEEDED(test_refract_normal_incidence, seeded_refract),
              SEEDED(test_refract_equal_indices, seeded_refract), SEEDED(test_snell_law, seeded_refract),
              SEEDED(test_critical_angle, seeded_refract), SEEDED(test_fresnel_normal_incidence, seeded_fresnel),
              SEEDED(test_fresnel_exact_values, seeded_fresnel),
              SEEDED(test_r_plus_t, seeded_fresnel), SEEDED(test_schlick_cosines, seeded_fresnel),
              SEEDED(test_sphere_centre_undeviated, seeded_glass),
              SEEDED(test_slab_returns_entry_direction, seeded_glass),
              SEEDED(test_total_internal_reflection_rays, seeded_glass),
              SEEDED(test_glass_weights, seeded_glass),
              SEEDED(test_furnace_glass_sphere, seeded_glass),
              SEEDED(test_index_one_sphere_invisible, seeded_glass), SEEDED(test_rays_only_where_needed, seeded_glass))
