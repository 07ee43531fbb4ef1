/* Chapter 05: point lights and the Lambert term, the tracer, the shading normal. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "05_lambert/lambert.h"
#include "05_lambert/shade_lambert.h"
#include "05_lambert/scenes/shading_scene.h"
#include "05_lambert/renderer/shading_stage.h"
#include "05_lambert/tracer.h"
#include "scene_build.h"
#include "shading_suite.h"
#include "suite.h"

/* The Lambert term is a few roundings (a difference, a square root, a
 * division, a dot product, two products) of values of size about 1: relative
 * error a few REAL_EPSILON.  32 REAL_EPSILON of the expected size leaves room
 * for the rounding of the test's own inputs (a normalized normal, a point far
 * from the origin). */
#define TOL(size) (32 * REAL_EPSILON * (size))
/* A light placed at `point` + r l is rounded to the spacing of reals near
 * |point| ~ 54, so light.pos - point, r^2 and n . l carry relative errors up
 * to about 54 REAL_EPSILON / r each: the tolerance grows by that much. */
#define FAR_TOL(size, r) (TOL(size) * (1 + 54 / (r)))

/* A point far from the origin and a unit normal in general position. */
static const vec3 point = {37.25, -12.5, 53.125};
static vec3 unit_normal(void) { return vec3_normalize(vec3_make(2, -3, 6)); } /* (2, -3, 6) / 7 */

/* A unit vector at angle theta from n, in the plane of n and (1, 0, 0). */
static vec3 at_angle(vec3 n, double theta)
{
    vec3 side = vec3_normalize(vec3_sub(vec3_make(1, 0, 0), vec3_scale(n, n.x))); /* perpendicular to n */
    return vec3_add(vec3_scale(n, (real)cos(theta)), vec3_scale(side, (real)sin(theta)));
}

/* ---- the Lambert term ------------------------------------------------------------------ */

/* A light straight above the point (along n) at distance r: n . l = 1, so
 * L_d = k_d I / r^2 in each channel, here with r = 2.5 (r^2 = 6.25). */
static void test_irradiance_facing(void **state)
{
    (void)state;
    vec3 n = unit_normal();
    scene_light light = {.position = vec3_add(point, vec3_scale(n, (real)2.5)), .intensity = {10, 20, 5}};
    color k_d = {0.3, 0.2, 0.7};
    color L = lambert(k_d, point, n, &light);
    const char *in = describe("lambert(k_d = (0.3, 0.2, 0.7), light 2.5 straight above the point, I = (10, 20, 5))");
    const suspect sr[] = {
        {0.3 * 10, "no falloff: divide by r^2, the squared distance to the light"},
        {0.3 * 10 / 2.5, "divided by r, not r^2 (the light spreads over a sphere of area 4 pi r^2), or l not "
                         "normalized (n . (light.pos - point) is r times the cosine)"},
        {0, "nothing from a light straight above: l points from the point towards the light, light.pos - point"},
        {10 / 6.25, "k_d missing: the surface reflects k_d of the irradiance"},
        {0.3 / 6.25, "the light's intensity I missing: L_d = k_d max(0, n . l) I / r^2"},
        {0.3 * 10 / sqrt(2.5), "r^2 taken as the length |light.pos - point|, not its square (l = (light.pos - point) "
                               "/ r then is not a unit vector either)"},
        {0.3 / acos(-1.0) * 10 / 6.25, "divided by pi: the scene's diffuseColor is k_d = R / pi already"},
        {(0.3 + 10) / 6.25, "k_d added to I: multiply them, channel by channel (color_mul)"},
    };
    assert_close_why(0.3 * 10 / 6.25, L.r, FAR_TOL(0.5, 2.5), describe("%s: red", in),
                     "L_d = k_d max(0, n . l) I / r^2", sr, sizeof sr / sizeof sr[0]);
    assert_close_why(0.2 * 20 / 6.25, L.g, FAR_TOL(0.7, 2.5), describe("%s: green", in),
                     "each channel: k_d.g I.g, not another channel's", NULL, 0);
    assert_close_why(0.7 * 5 / 6.25, L.b, FAR_TOL(0.6, 2.5), describe("%s: blue", in),
                     "each channel: k_d.b I.b, not another channel's", NULL, 0);
}

/* Lambert's cosine law: the light at angle theta from the normal, always at
 * distance 3, gives cos(theta) of the facing value: 60 degrees half of it
 * (the lecture's rotated cube), 0 at and beyond 90 degrees. */
static void test_cosine_law(void **state)
{
    (void)state;
    vec3 n = unit_normal();
    color k_d = {0.25, 0.25, 0.25};
    const double pi = acos(-1.0);
    /* 89.99 degrees: n . l = 1.7e-4, small but above 0, and so is L_d (a cutoff such as n . l < 1e-3 is no
     * part of max(0, n . l): it darkens a band along every terminator) */
    const double degrees[] = {0, 30, 60, 75, 89, 89.99, 90.5, 120, 180};
    for (size_t k = 0; k < sizeof degrees / sizeof degrees[0]; k++) {
        double theta = degrees[k] * pi / 180;
        scene_light light = {.position = vec3_add(point, vec3_scale(at_angle(n, theta), 3)), .intensity = {9, 9, 9}};
        double expected = 0.25 * 9 / 9 * fmax(0, cos(theta));
        color L = lambert(k_d, point, n, &light);
        const suspect sc[] = {
            {cos(theta) > 0 && cos(theta) < 1e-3 ? 0 : NAN, /* (NAN: no suspect at the other angles) */
             "none at a small n . l: max(0, n . l) is 0 only at and beyond 90 degrees, with no threshold of its own"},
            {0.25 * cos(theta), "negative: clamp the cosine, max(0, n . l): a light behind the surface gives nothing"},
            {0.25, "no cosine: the irradiance falls with cos(theta) = n . l as the surface tilts away"},
            {0.25 * 9 / 3 * fmax(0, cos(theta)), "divided by r, not r^2, or l not normalized"},
            {0.25 * fabs(cos(theta)), "|n . l|: a light behind the surface gives nothing, max(0, n . l)"},
            {0.25 * fmax(0, -cos(theta)), "l points away from the light: l = (light.pos - point) / r"},
        };
        assert_close_why(expected, L.r, FAR_TOL(0.25, 3),
                         describe("lambert(k_d = 0.25, I = 9, light 3 away at %g degrees from n): red", degrees[k]),
                         "L_d = k_d max(0, n . l) I / r^2", sc, sizeof sc / sizeof sc[0]);
        assert_close(L.r, L.g, 0);
    }
    /* 60 degrees: exactly half of facing, as the lecture says */
    scene_light facing = {.position = vec3_add(point, vec3_scale(n, 3)), .intensity = {9, 9, 9}};
    scene_light tilted = {.position = vec3_add(point, vec3_scale(at_angle(n, pi / 3), 3)), .intensity = {9, 9, 9}};
    assert_close(lambert(k_d, point, n, &facing).r / 2, lambert(k_d, point, n, &tilted).r, FAR_TOL(0.25, 3));
}

/* The 1/r^2 falloff: along the same direction at 45 degrees, r = 1, 2, 10,
 * 1000 give 1, 1/4, 1/100, 1e-6 of the value at r = 1. */
static void test_inverse_square(void **state)
{
    (void)state;
    vec3 n = unit_normal();
    vec3 l = at_angle(n, atan(1.0));
    color k_d = {0.5, 0.1, 0.9};
    scene_light near = {.position = vec3_add(point, l), .intensity = {4, 4, 4}};
    real at_one = lambert(k_d, point, n, &near).b; /* 0.9 * 4 * cos 45 / 1 */
    const suspect s1[] = {
        {0, "nothing from a light at 45 degrees in front: l points from the point towards the light, "
            "light.pos - point, and the cosine is n . l"},
        {0.9 * 4, "no cosine: the irradiance falls with cos(theta) = n . l"},
        {1, "clamped to 1: a radiance may exceed 1; only the display's encoding clamps"},
    };
    assert_close_why(0.9 * 4 * sqrt(0.5), at_one, FAR_TOL(3, 1),
                     "lambert(k_d.b = 0.9, I = 4, light 1 away at 45 degrees from n): blue",
                     "L_d = k_d max(0, n . l) I / r^2", s1, sizeof s1 / sizeof s1[0]);
    const real distances[] = {2, 10, 1000};
    for (int k = 0; k < 3; k++) {
        scene_light far = {.position = vec3_add(point, vec3_scale(l, distances[k])), .intensity = {4, 4, 4}};
        const double r = (double)distances[k];
        const suspect sr[] = {
            {at_one / r, "divided by r, not r^2 (the light spreads over a sphere of area 4 pi r^2), or l not "
                         "normalized"},
            {at_one, "no falloff: divide by r^2, the squared distance to the light"},
            {at_one / (r * r * r), "divided by r^3: l = (light.pos - point) / r is a unit vector, and only I / r^2 "
                                   "falls with the distance"},
            {0, "nothing from a light in front: l points from the point towards the light"},
        };
        assert_close_why(at_one / (r * r), lambert(k_d, point, n, &far).b, FAR_TOL(at_one / (r * r), 1),
                         describe("lambert(the same light moved %g times as far along l): blue", r),
                         "1 / r^2 of the value at r = 1", sr, sizeof sr / sizeof sr[0]);
    }
    /* r = 0.3: r^2 = 0.09 is not a float (rounded to one it is off by 4e-8
     * relative, thousands of times FAR_TOL in double), so a float slipped
     * into the double build shows; the distances above have squares that are. */
    scene_light close = {.position = vec3_add(point, vec3_scale(l, (real)0.3)), .intensity = {4, 4, 4}};
    const double expected_close = 0.9 * 4 * sqrt(0.5) / 0.09;
    assert_close_why(expected_close, lambert(k_d, point, n, &close).b, FAR_TOL(expected_close, 0.3),
                     "lambert(the same light at distance 0.3 along l): blue",
                     "a float in a computation of the double build (r^2, l or the cosine stored in a float, or "
                     "sqrtf): keep every quantity a real",
                     NULL, 0);
}

/* A light behind the surface (n . l < 0) gives nothing, never a negative
 * radiance; flipping n (the other side) lights it. */
static void test_light_behind(void **state)
{
    (void)state;
    vec3 n = unit_normal();
    scene_light light = {.position = vec3_sub(point, vec3_scale(n, 2)), .intensity = {8, 8, 8}};
    color k_d = {0.3, 0.3, 0.3};
    color L = lambert(k_d, point, n, &light);
    const suspect sb[] = {
        {-0.3 * 8 / 4, "negative: clamp the cosine, max(0, n . l): a light behind the surface gives nothing"},
        {0.3 * 8 / 4, "l points away from the light (point - light.pos), or |n . l|: the light is behind the "
                      "surface and gives nothing"},
    };
    const char *in = "lambert(k_d = 0.3, I = 8, light 2 straight behind the surface, against n)";
    assert_close_why(0, L.r, 0, describe("%s: red", in), "max(0, n . l) = 0", sb, sizeof sb / sizeof sb[0]);
    assert_close_why(0, L.g, 0, describe("%s: green", in), "max(0, n . l) = 0", sb, sizeof sb / sizeof sb[0]);
    assert_close_why(0, L.b, 0, describe("%s: blue", in), "max(0, n . l) = 0", sb, sizeof sb / sizeof sb[0]);
    const suspect sf[] = {
        {0, "nothing with the normal turned towards the light: l points from the point towards the light"},
        {-0.3 * 8 / 4, "negative with the light in front: l points away from the light, or n . l taken with -n"},
    };
    assert_close_why(0.3 * 8 / 4, lambert(k_d, point, vec3_neg(n), &light).r, FAR_TOL(1, 2),
                     "lambert(the same light, the normal turned to face it): red", "k_d I / r^2 = 0.3 * 8 / 4", sf,
                     sizeof sf / sizeof sf[0]);
}

/* ---- the shading normal, turned towards the viewer ------------------------------------------ */

/* normal_towards_viewer keeps n when the ray comes against it and flips it
 * when the ray comes from behind (n . d > 0). */
static void test_normal_towards_viewer(void **state)
{
    (void)state;
    vec3 n = unit_normal();
    vec3 d_front = vec3_make(-1, 2, -5); /* n . d < 0 */
    vec3 d_back = vec3_neg(d_front);
    assert_vec3_close(n, normal_towards_viewer(n, d_front), 0);
    assert_vec3_close(vec3_neg(n), normal_towards_viewer(n, d_back), 0);
}

/* One-surface scenes traced through the stage's tracer (chapter 04's linear
 * scan): a triangle seen from its back and a sphere seen from inside are lit
 * like a front face when the light is on the viewer's side.  The shade
 * function is given the geometric normal as it was and the shading normal
 * turned towards the viewer. */
static _Thread_local shading_point last;
static _Thread_local int last_depth;
static color record_shade(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays)
{
    last = *sp;
    last_depth = depth;
    return shade_lambert(tr, sp, depth, rays);
}

static color trace_scene(const scene *desc, ray r)
{
    uint64_t rays[RAY_KINDS] = {0};
    return suite_trace(desc, record_shade, NULL, r, rays);
}

static void test_back_of_triangle_lit(void **state)
{
    (void)state;
    const vec3 c = {20.5, -7.25, 13.75};
    scene desc;
    scene_init(&desc);
    scene_shader grey = scene_default_shader(SHADER_LAMBERTIAN);
    grey.diffuse_color = color_make((real)0.3, (real)0.3, (real)0.3);
    int s = scene_add_shader(&desc, grey);
    /* counter-clockwise seen from +z: the geometric normal is +z */
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_TRIANGLE, .shader = s,
                                             .v0 = vec3_add(c, vec3_make(-2, -2, 0)),
                                             .v1 = vec3_add(c, vec3_make(2, -2, 0)),
                                             .v2 = vec3_add(c, vec3_make(0, 2, 0))});
    /* the light 3 units in front of the back face, off to the side: l = (1, 1, -3) / sqrt(11) */
    scene_add_light(&desc, (scene_light){.position = vec3_add(c, vec3_make(1, 1, -3)), .intensity = {11, 11, 11}});
    ray from_behind = {vec3_add(c, vec3_make(0, 0, -4)), {0, 0, 1}};
    color L = trace_scene(&desc, from_behind);
    /* n_s = -z: n_s . l = 3 / sqrt(11), r^2 = 11: L = 0.3 * 11 * 3 / 11^1.5 */
    assert_close(0.3 * 11 * 3 / pow(11, 1.5), L.r, TOL(0.1));
    assert_vec3_close(vec3_make(0, 0, 1), last.hit.normal, TOL(1)); /* geometric: untouched */
    assert_vec3_close(vec3_make(0, 0, -1), last.n, TOL(1));         /* shading: towards the viewer */
    assert_vec3_close(vec3_make(0, 0, -1), last.v, 0);              /* v = -normalize(d) */
    /* The same ray with d four times as long (a power of two: the same hit, v exactly the same) */
    trace_scene(&desc, (ray){from_behind.p, {0, 0, 4}});
    assert_vec3_why(vec3_make(0, 0, -1), last.v, 0, "the shading point's v for a ray with d = (0, 0, 4)",
                    "v = -normalize(ray.direction), a unit vector whatever the length of d (README, \"Shading a "
                    "hit\")",
                    NULL, 0);
    /* The same hit in a scene without lights, before a grey background: a matte surface with no light to
     * reflect is black, not the background (shade_lambert.c, n_lights == 0). */
    desc.back_color = color_make((real)0.5, (real)0.5, (real)0.5);
    const int n_lights = desc.n_lights;
    desc.n_lights = 0;
    L = trace_scene(&desc, from_behind);
    desc.n_lights = n_lights;
    assert_vec3_why(vec3_make(0, 0, 0), vec3_make(L.r, L.g, L.b), 0,
                    "the triangle hit from behind in a scene without lights, background (0.5, 0.5, 0.5)",
                    "with no light a matte surface reflects nothing: black, not the background colour (README, "
                    "\"The stage's shade function\": n_lights == 0 gives black)",
                    NULL, 0);
    scene_free(&desc);
}

static void test_inside_of_sphere_lit(void **state)
{
    (void)state;
    const vec3 c = {-31.5, 4.25, 17.125};
    scene desc;
    scene_init(&desc);
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = -1, .center = c, .radius = 2});
    scene_add_light(&desc, (scene_light){.position = c, .intensity = {6, 5, 4}}); /* at the centre */
    ray inside = {vec3_add(c, vec3_make(0.5, 0, 0)), {0, 0, 3}};
    color L = trace_scene(&desc, inside);
    /* the hit is 2 from the centre, the inward normal points at the light:
     * n . l = 1, r^2 = 4, white k_d = 1 (no shader) */
    assert_close(6.0 / 4, L.r, TOL(2));
    assert_close(5.0 / 4, L.g, TOL(2));
    assert_close(4.0 / 4, L.b, TOL(2));
    vec3 outward = vec3_scale(vec3_sub(last.hit.point, c), (real)0.5);
    assert_vec3_close(outward, last.hit.normal, TOL(1));
    assert_vec3_close(vec3_neg(outward), last.n, TOL(1));
    scene_free(&desc);
}

/* ---- the tracer: any closest-hit query, the backColor on a miss ------------------------------ */

/* A closest-hit query that is not chapter 04's: one fixed hit inside its
 * window, and a count of the calls. */
typedef struct {
    real t;
    int calls;
} fake_accel;

static bool fake_closest_hit(const void *accel, ray r, real t_min, real t_max, hit_record *hit)
{
    fake_accel *fake = (fake_accel *)accel;
    fake->calls++;
    if (!(fake->t > t_min && fake->t < t_max))
        return false;
    *hit = (hit_record){.t = fake->t, .point = ray_at(r, fake->t), .normal = {0, 1, 0}, .shader = -1};
    return true;
}

static void test_trace_uses_the_query(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    desc.back_color = color_make((real)0.1, (real)0.2, (real)0.3);
    scene_add_light(&desc, (scene_light){.position = {0, 10, 0}, .intensity = {100, 100, 100}});
    fake_accel fake = {.t = 5};
    tracer tr = {.closest_hit = fake_closest_hit, .accel = &fake, .desc = &desc, .shade = shade_lambert};
    uint64_t rays[RAY_KINDS] = {0};
    ray down = {{0, 5, 0}, {0, -1, 0}}; /* meets the fake hit at the origin */
    color lit = trace(&tr, down, 0, REAL_INFINITY, 0, rays);
    assert_close(100.0 / 100, lit.g, TOL(1)); /* white, n . l = 1, r = 10 */
    color missed = trace(&tr, down, 0, 4, 0, rays); /* the window ends before the hit */
    assert_close(desc.back_color.g, missed.g, 0);
    assert_int_equal(2, fake.calls);
    for (int k = 0; k < RAY_KINDS; k++) /* trace counts nothing itself; Lambert casts nothing */
        assert_int_equal(0, rays[k]);
    /* A second light, twice as close and four times as bright (16 times the first's L): the stage shades
     * by the first light alone, the lecture's one light */
    scene_add_light(&desc, (scene_light){.position = {0, 5, 0}, .intensity = {400, 400, 400}});
    /* the shade function is given trace's depth as it is: chapter 08's recursion counts on it */
    tr.shade = record_shade;
    last_depth = -1;
    lit = trace(&tr, down, 0, REAL_INFINITY, 3, rays);
    assert_true_why(last_depth == 3,
                    "trace(ray, 0, inf, depth 3) on the fake hit\n    expected the shade function called with depth "
                    "3\n    got      depth %d\n    likely mistake: trace hands the shade function the depth it was "
                    "given; the next level adds one where it traces again (README, \"How the later chapters plug "
                    "in\")",
                    last_depth);
    assert_close_why(1, lit.g, TOL(1),
                     "the fake hit at the origin, n (0, 1, 0), lights 100 at (0, 10, 0) and 400 at (0, 5, 0)",
                     "the stage's shade function takes the scene's first light as the lecture's one light "
                     "(README, \"The stage's shade function\")",
                     NULL, 0);
    scene_free(&desc);
}

/* The built-in scene through the stage's sample function: one eye ray per
 * sample and no other ray; every pixel finite and non-negative. */
static void test_builtin_scene_rays(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    assert_int_equal(0, shading_scene(&desc));
    assert_int_equal(2, desc.n_lights);
    char err[256] = "";
    const shading_stage stage = {.name = "test", .shade = shade_lambert};
    shading_view *view = shading_prepare(&stage, &desc, SPHERE_ROBUST, TRIANGLE_WATERTIGHT, err, sizeof err);
    assert_non_null(view);
    image img;
    assert_int_equal(0, image_init(&img, 24, 16));
    render_options opt = {.samples = 4, .threads = 2};
    render_stats stats = render_image(&img, shading_sample, view, &opt);
    assert_int_equal(24 * 16 * 4, stats.by_kind[RAY_EYE]);
    assert_int_equal(stats.by_kind[RAY_EYE], stats.rays);
    for (int k = 0; k < 24 * 16; k++) {
        color c = img.pixels[k];
        if (!(c.r >= 0 && c.g >= 0 && c.b >= 0 && isfinite(c.r) && isfinite(c.g) && isfinite(c.b)))
            fail_msg("the built-in scene at 24 x 16, 4 samples: pixel (%d, %d) is (%g, %g, %g)\n    expected a "
                     "finite radiance >= 0 in every channel\n    likely mistake: %s",
                     k % 24, k / 24, (double)c.r, (double)c.g, (double)c.b,
                     isfinite(c.r) && isfinite(c.g) && isfinite(c.b)
                         ? "the cosine not clamped: a light behind the surface gives nothing, max(0, n . l)"
                         : "a division that can be by zero, or l not normalized by the length of light.pos - point");
    }
    image_free(&img);
    shading_release(view);
    scene_free(&desc);
}

static const graded_test tests[] = {
    GRADED(test_irradiance_facing, 3),
    GRADED(test_cosine_law, 3),
    GRADED(test_inverse_square, 2),
    GRADED(test_light_behind, 2),
    GRADED(test_back_of_triangle_lit, 2),
    GRADED(test_inside_of_sphere_lit, 2),
    GRADED(test_normal_towards_viewer, 0), /* handed out complete: no points */
    GRADED(test_trace_uses_the_query, 0),  /* handed out complete: no points */
    GRADED(test_builtin_scene_rays, 0),    /* handed out complete: no points */
};

SUITE_MAIN("05_lambert", tests)
