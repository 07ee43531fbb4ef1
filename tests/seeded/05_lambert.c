/* Chapter 05's checks of inputs drawn at grading time (tests/answers.h): for
 * each graded test, lambert (directly, or through the tracer as the test
 * does) at points, normals, lights and reflectances drawn from the grader's
 * seed; the reference's answers to the same inputs are the expected ones.
 *
 * Tolerance: the inputs are of size up to ~60 and the light is r away, so
 * light.pos - point carries a rounding of about (|point| + r) REAL_EPSILON,
 * relative (1 + |point| / r) REAL_EPSILON, and r^2, l and n . l a few times
 * that; k_d I / r^2 (the facing value) bounds the answer.  Two correct
 * formulas differ by twice what each may be off: 64 REAL_EPSILON (1 + |point|
 * / r) of the facing value. */
#include <math.h>

#include "05_lambert/lambert.h"
#include "05_lambert/shade_lambert.h"
#include "seeded.h"
#include "shading_suite.h"

static double tolerance(color k_d, color I, vec3 point, double r)
{
    double facing = fmax(k_d.r * I.r, fmax(k_d.g * I.g, k_d.b * I.b)) / (r * r);
    return 64 * REAL_EPSILON * facing * (1 + vec3_length(point) / r);
}

/* lambert at a light r away along u from a random point, its answer given. */
static void answer_lambert(unsigned long *rng, vec3 n, vec3 u, double r, const char *what)
{
    vec3 point = seeded_point(rng, 50);
    color k_d = seeded_color(rng, 0.05, 1), I = seeded_color(rng, 0.5, 30);
    scene_light light = {.position = vec3_add(point, vec3_scale(u, (real)r)), .intensity = I};
    color L = lambert(k_d, point, n, &light);
    const char *in = describe("lambert(k_d = (%.6g, %.6g, %.6g), point (%.6g, %.6g, %.6g), n = (%.6g, "
                              "%.6g, %.6g), light at (%.6g, %.6g, %.6g), I = (%.6g, %.6g, %.6g)) [%s]",
                              k_d.r, k_d.g, k_d.b, point.x, point.y, point.z, n.x, n.y, n.z, light.position.x,
                              light.position.y, light.position.z, I.r, I.g, I.b, what);
    suite_answer_rgb(in, L, tolerance(k_d, I, point, r));
}

static void seeded_facing(unsigned long *rng)
{
    for (int k = 0; k < 6; k++) {
        vec3 n = suite_random_unit(rng);
        answer_lambert(rng, n, n, seeded_between(rng, 0.5, 10), "light along n");
    }
}

/* Every other light in front of the point (within 1.4 rad of n, where the
 * answer is at least 0.17 of the facing value): at any angle alone, all
 * eight fell behind (where the answer is 0) in one grading of 256, and a
 * lambert that answers 0 to everything passed. */
static void seeded_cosine(unsigned long *rng)
{
    for (int k = 0; k < 8; k++) {
        vec3 n = suite_random_unit(rng);
        vec3 u = seeded_at_angle(rng, n, seeded_between(rng, 0, k % 2 ? acos(-1.0) : 1.4));
        answer_lambert(rng, n, u, seeded_between(rng, 1, 6), "any angle");
    }
}

static void seeded_inverse_square(unsigned long *rng)
{
    for (int k = 0; k < 6; k++) {
        vec3 n = suite_random_unit(rng);
        vec3 u = seeded_at_angle(rng, n, seeded_between(rng, 0, 1.2));
        answer_lambert(rng, n, u, pow(10, seeded_between(rng, 0, 3)), "far lights");
    }
}

static void seeded_behind(unsigned long *rng)
{
    for (int k = 0; k < 6; k++) {
        vec3 n = suite_random_unit(rng), u = seeded_at_angle(rng, n, seeded_between(rng, 1.8, acos(-1.0)));
        double r = seeded_between(rng, 0.5, 8);
        answer_lambert(rng, n, u, r, "light behind");
        answer_lambert(rng, vec3_neg(n), u, r, "light behind, n flipped");
    }
}

/* A triangle about a random centre, seen from its back with the light on
 * the viewer's side, traced as the suite's test does. */
static void seeded_back_of_triangle(unsigned long *rng)
{
    for (int k = 0; k < 4; k++) {
        vec3 c = seeded_point(rng, 40);
        scene desc;
        scene_init(&desc);
        scene_shader grey = scene_default_shader(SHADER_LAMBERTIAN);
        grey.diffuse_color = seeded_color(rng, 0.1, 1);
        int s = scene_add_shader(&desc, grey);
        scene_add_surface(&desc, (scene_surface){.kind = SURFACE_TRIANGLE, .shader = s,
                                                 .v0 = vec3_add(c, vec3_make(-2, -2, 0)),
                                                 .v1 = vec3_add(c, vec3_make(2, -2, 0)),
                                                 .v2 = vec3_add(c, vec3_make(0, 2, 0))});
        double lx = seeded_between(rng, -2, 2), ly = seeded_between(rng, -2, 2), lz = seeded_between(rng, -5, -1);
        vec3 to_light = vec3_make((real)lx, (real)ly, (real)lz);
        color I = seeded_color(rng, 1, 20);
        scene_add_light(&desc, (scene_light){.position = vec3_add(c, to_light), .intensity = I});
        ray from_behind = {vec3_add(c, vec3_make(0, 0, -4)), {0, 0, 1}};
        uint64_t rays[RAY_KINDS] = {0};
        color L = suite_trace(&desc, shade_lambert, NULL, from_behind, rays);
        double r = vec3_length(to_light);
        suite_answer_rgb(describe("a triangle at (%.6g, %.6g, %.6g) seen from its back, the light %.6g away on "
                                  "the viewer's side",
                                  c.x, c.y, c.z, r),
                         L, tolerance(grey.diffuse_color, I, c, r));
        scene_free(&desc);
    }
}

/* A sphere about a random centre seen from inside, the light inside. */
static void seeded_inside_of_sphere(unsigned long *rng)
{
    for (int k = 0; k < 4; k++) {
        vec3 c = seeded_point(rng, 40);
        real radius = (real)seeded_between(rng, 1, 5);
        scene desc;
        scene_init(&desc);
        scene_add_surface(&desc,
                          (scene_surface){.kind = SURFACE_SPHERE, .shader = -1, .center = c, .radius = radius});
        color I = seeded_color(rng, 1, 20);
        vec3 light = vec3_add(c, vec3_scale(suite_random_unit(rng), radius * (real)seeded_between(rng, 0, 0.5)));
        scene_add_light(&desc, (scene_light){.position = light, .intensity = I});
        ray inside = {vec3_add(c, vec3_scale(suite_random_unit(rng), radius * (real)0.3)), suite_random_unit(rng)};
        uint64_t rays[RAY_KINDS] = {0};
        color L = suite_trace(&desc, shade_lambert, NULL, inside, rays);
        double r = radius * 0.5; /* the light is at least that far from the surface */
        suite_answer_rgb(describe("a sphere of radius %.6g at (%.6g, %.6g, %.6g) seen from inside, the light "
                                  "inside",
                                  radius, c.x, c.y, c.z),
                         L, tolerance(color_make(1, 1, 1), I, c, r));
        scene_free(&desc);
    }
}

SEEDED_CHECKS(SEEDED(test_irradiance_facing, seeded_facing), SEEDED(test_cosine_law, seeded_cosine),
              SEEDED(test_inverse_square, seeded_inverse_square), SEEDED(test_light_behind, seeded_behind),
              SEEDED(test_back_of_triangle_lit, seeded_back_of_triangle),
              SEEDED(test_inside_of_sphere_lit, seeded_inside_of_sphere))
