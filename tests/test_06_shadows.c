/* Chapter 06: shadow rays, the epsilon policy, acne and leaks. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "05_lambert/lambert.h"
#include "06_shadows/lab/acne.h"
#include "06_shadows/shade_shadows.h"
#include "06_shadows/shadow.h"
#include "06_shadows/spawn.h"
#include "scene_build.h"
#include "shading_suite.h"
#include "suite.h"

/* A few roundings of values of size about 1 (see test_05_lambert.c). */
#define TOL(size) (32 * REAL_EPSILON * (size))

static const eps_policy policies[] = {EPS_NONE, EPS_FIXED, EPS_BOUND};

/* ---- a scene and one of its points, as the renderer shades it --------------------------------- */

/* The floor is the triangle in the plane y = 2 around (20, 2, -10), wound so
 * that its normal is +y; the eye looks down at it from above. */
static const vec3 floor_centre = {20.25, 2, -10.5};

static void add_floor(scene *desc) { suite_add_floor(desc, -1, floor_centre); }

/* Prepares desc and finds the shading point the eye ray from `eye` to
 * `target` hits: the view stays alive for light_blocked (release it). */
static shading_view *shade_at(const scene *desc, vec3 eye, vec3 target, shading_point *sp)
{
    return suite_shading_point(desc, NULL, (ray){eye, vec3_sub(target, eye)}, sp);
}

/* The point of the floor below the eye, a little off centre. */
static const vec3 eye = {21.75, 9.5, -6.25};
static const vec3 spot = {20.625, 2, -11.375};

/* Is the light at light_pos blocked from the floor point, with each policy? */
static void check_blocked(const scene *desc, vec3 light_pos, bool expected, const char *what)
{
    shading_point sp;
    shading_view *view = shade_at(desc, eye, spot, &sp);
    assert_vec3_close(vec3_make(0, 1, 0), sp.hit.normal, TOL(1));
    for (int p = 0; p < 3; p++) {
        uint64_t rays[RAY_KINDS] = {0};
        bool blocked = light_blocked(&view->tr, &sp, light_pos, policies[p], rays);
        if (blocked != expected)
            fail_msg("light_blocked with %s, policy %s: %s, expected %s\n    likely mistake: %s", what,
                     eps_policy_names[p], blocked ? "blocked" : "not blocked", expected ? "blocked" : "not blocked",
                     expected ? "ask tr->closest_hit(tr->accel, ray, 0, t_max, &hit) with the ray and t_max that "
                                "spawn_ray_to gives, and return what it says"
                              : "the window must be the segment (0, t_max) that spawn_ray_to gives: not beyond the "
                                "light (t_max, not infinity), not behind the point (0, not -infinity)");
        if (rays[RAY_SHADOW] != 1)
            fail_msg("light_blocked with %s: %llu shadow rays counted, expected 1\n    likely mistake: count the "
                     "shadow ray, ++rays[RAY_SHADOW]",
                     what, (unsigned long long)rays[RAY_SHADOW]);
        assert_int_equal(0, rays[RAY_EYE]);
    }
    shading_release(view);
}

/* A sphere between the point and the light blocks it; the same sphere
 * beyond the light, or behind the point (below the floor), does not.  The
 * light is 6 above the point, off to the side; the spheres sit on the line
 * through both. */
static void test_occluder_between_beyond_behind(void **state)
{
    (void)state;
    const vec3 light = vec3_add(spot, vec3_make(1.5, 6, -0.75));
    const vec3 along = vec3_sub(light, spot); /* the point at 0, the light at 1 */
    const struct {
        real where; /* the sphere's centre along the line */
        bool blocks;
    } cases[] = {{0.5, true}, {0.9, true}, {1.3, false}, {2.5, false}, {-0.6, false}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        scene desc;
        scene_init(&desc);
        add_floor(&desc);
        scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = -1,
                                                 .center = vec3_add(spot, vec3_scale(along, cases[k].where)),
                                                 .radius = 0.4});
        check_blocked(&desc, light, cases[k].blocks,
                      describe("a sphere at %g of the way from the point (0) to the light (1)", (double)cases[k].where));
        scene_free(&desc);
    }
}

/* A light exactly on a surface is not shadowed by that surface: on the
 * plane of a wall (x = 25.5, facing the point) and on a sphere, at the point
 * of the sphere that faces the floor point, so that the segment touches the
 * sphere there only. */
static void test_light_on_a_surface(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    add_floor(&desc);
    /* the wall x = 25.5, from y = 0 to 20 */
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_TRIANGLE, .shader = -1, .v0 = {25.5, 0, -30},
                                             .v1 = {25.5, 0, 10}, .v2 = {25.5, 20, -10}});
    check_blocked(&desc, vec3_make(25.5, 7.25, -11.125), false, "the light exactly on a wall");
    scene_free(&desc);

    scene_init(&desc);
    add_floor(&desc);
    /* the unit sphere above the point; the light on it, where it faces the point */
    vec3 c = vec3_add(spot, vec3_make(-2.5, 5.5, 1.5));
    vec3 towards = vec3_normalize(vec3_sub(spot, c));
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = -1, .center = c, .radius = 1});
    check_blocked(&desc, vec3_add(c, towards), false, "the light exactly on a sphere, facing the point");
    scene_free(&desc);

    /* A light 1.5e-3 above the floor point, in front of it.  With the fixed policy the segment starts 1e-3 up
     * and ends 1e-3 before the light: it ends before it starts (t_max = 1 - 1e-3 / 5e-4 = -1), and no surface
     * lies on an empty segment, so nothing blocks the light; the other policies' offsets are far smaller
     * (t_max > 0) and the segment above the floor is clear.  With every policy: not blocked. */
    scene_init(&desc);
    add_floor(&desc);
    const vec3 near_light = vec3_add(spot, vec3_make(0, (real)1.5e-3, 0));
    shading_point sp;
    shading_view *view = shade_at(&desc, eye, spot, &sp);
    for (int p = 0; p < 3; p++) {
        real t_end;
        (void)spawn_ray_to(&sp, near_light, policies[p], &t_end);
        uint64_t rays[RAY_KINDS] = {0};
        const bool blocked = light_blocked(&view->tr, &sp, near_light, policies[p], rays);
        assert_true_why(!blocked,
                        "light_blocked(policy %s, a light 1.5e-3 above the floor point, in front of it: spawn_ray_to's "
                        "segment ends at t_max = %g)\n    expected not blocked\n    got      blocked\n"
                        "    likely mistake: %s",
                        eps_policy_names[p], (double)t_end,
                        t_end > 0 ? "the window must be the segment (0, t_max) that spawn_ray_to gives"
                                  : "a segment that ends before it starts (t_max <= 0) holds no surface: the light "
                                    "is not blocked (return false, as for a clear segment)");
    }
    shading_release(view);
    scene_free(&desc);
}

/* A light behind the surface, as its shading normal sees it, is blocked by
 * the surface itself, and no shadow ray is cast.  Seen from below, the
 * floor's shading normal is -y (turned towards the viewer) while its
 * geometric normal stays +y: a light below it is then in front. */
static void test_light_behind_the_surface(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    add_floor(&desc);
    const vec3 below = vec3_add(spot, vec3_make((real)1.25, -7, (real)0.75)); /* an eye under the floor */
    const vec3 under = vec3_add(spot, vec3_make(1, -3, 1)), over = vec3_add(spot, vec3_make(1, 3, 1));
    const char *side = "the side was judged by the geometric normal hit.normal: use the shading normal sp->n, which "
                       "faces the viewer";
    const struct {
        vec3 eye, light;
        bool blocked;
        const char *what, *hint;
    } cases[] = {
        {eye, under, true, "a light below the floor, the eye above it",
         "a light behind the surface is blocked by the surface itself: n . (light_pos - point) <= 0"},
        {below, under, false, "a light below the floor, the eye below it too", side},
        {below, over, true, "a light above the floor, the eye below it", side},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        shading_point sp;
        shading_view *view = shade_at(&desc, cases[k].eye, spot, &sp);
        uint64_t rays[RAY_KINDS] = {0};
        bool blocked = light_blocked(&view->tr, &sp, cases[k].light, EPS_BOUND, rays);
        if (blocked != cases[k].blocked)
            fail_msg("light_blocked with %s: %s, expected %s\n    likely mistake: %s", cases[k].what,
                     blocked ? "blocked" : "not blocked", cases[k].blocked ? "blocked" : "not blocked", cases[k].hint);
        if (rays[RAY_SHADOW] != (cases[k].blocked ? 0u : 1u))
            fail_msg("light_blocked with %s: %llu shadow rays counted, expected %d\n    likely mistake: %s",
                     cases[k].what, (unsigned long long)rays[RAY_SHADOW], cases[k].blocked ? 0 : 1,
                     cases[k].blocked ? "no shadow ray towards a light behind the surface: the surface blocks it"
                                      : "count the one shadow ray cast");
        shading_release(view);
    }
    /* A light in the floor's own plane: the normal is +y exactly and light_pos - point has no y, so
     * n . (light_pos - point) is 0 exactly; such a light lights nothing (n . l = 0), as one behind. */
    shading_point sp;
    shading_view *view = shade_at(&desc, eye, spot, &sp);
    uint64_t rays[RAY_KINDS] = {0};
    bool blocked = light_blocked(&view->tr, &sp, vec3_add(sp.hit.point, vec3_make(3, 0, 2)), EPS_BOUND, rays);
    if (!blocked || rays[RAY_SHADOW] != 0)
        fail_msg("light_blocked with a light in the floor's plane, 3.6 from the point: %s, %llu shadow rays; "
                 "expected blocked, no shadow ray\n    likely mistake: a light with n . (light_pos - point) = 0 "
                 "is blocked as one behind: only n . (light_pos - point) > 0 is in front (> 0, not >= 0)",
                 blocked ? "blocked" : "not blocked", (unsigned long long)rays[RAY_SHADOW]);
    /* A light just above that plane, 1e-3 up and 36000 away (n . l = 2.8e-8): in front, however grazing.  Its
     * shadow ray runs above the plane all the way: it starts above the point (by eps_bound, 8.3e-5 at most in
     * float, far less than 1e-3) and rises to the light: not blocked, one ray. */
    rays[RAY_SHADOW] = 0;
    blocked = light_blocked(&view->tr, &sp, vec3_add(sp.hit.point, vec3_make(30000, (real)1e-3, 20000)), EPS_BOUND,
                            rays);
    if (blocked || rays[RAY_SHADOW] != 1)
        fail_msg("light_blocked with a light 1e-3 above the floor's plane, 36000 from the point: %s, %llu shadow rays; "
                 "expected not blocked, one shadow ray\n    likely mistake: a tolerance of one's own in the test of a "
                 "light behind: only n . (light_pos - point) <= 0 is behind, and any n . (light_pos - point) > 0, "
                 "however small, is in front",
                 blocked ? "blocked" : "not blocked", (unsigned long long)rays[RAY_SHADOW]);
    shading_release(view);
    scene_free(&desc);
}

/* A closest-hit query that records the segment it is asked about and finds nothing. */
static struct {
    ray r;
    real t_min, t_max;
    int calls;
} asked;

static bool record_query(const void *accel, ray r, real t_min, real t_max, hit_record *hit)
{
    (void)accel;
    (void)hit;
    asked.r = r;
    asked.t_min = t_min;
    asked.t_max = t_max;
    ++asked.calls;
    return false;
}

/* The shadow ray is the segment spawn_ray_to gives with the caller's policy:
 * the same start and the same end, whatever the length of its direction.
 * Both ends are computed as spawn_ray_to computes them, or from a direction
 * scaled by the student, a few roundings of coordinates of size ~30 apart. */
static void test_shadow_ray_is_the_segment(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    add_floor(&desc);
    shading_point sp;
    shading_view *view = shade_at(&desc, eye, spot, &sp);
    tracer tr = view->tr;
    tr.closest_hit = record_query;
    const vec3 light = vec3_add(spot, vec3_make((real)1.5, 6, (real)-0.75));
    for (int p = 0; p < 3; p++) {
        real t_end;
        ray expected = spawn_ray_to(&sp, light, policies[p], &t_end);
        uint64_t rays[RAY_KINDS] = {0};
        asked.calls = 0;
        light_blocked(&tr, &sp, light, policies[p], rays);
        const char *in = describe("light_blocked(policy %s, a light 6 above the floor point)", eps_policy_names[p]);
        if (asked.calls != 1)
            fail_msg("%s: tr->closest_hit asked %d times, expected once\n    likely mistake: one shadow ray, "
                     "through the tracer's query tr->closest_hit", in, asked.calls);
        suspect_vec3 starts[3 + 1];
        int n = 0;
        starts[n++] = (suspect_vec3){sp.hit.point, "the ray starts at the point itself: leave the surface by the "
                                                   "policy given (spawn_ray_to with `policy`)"};
        for (int q = 0; q < 3; q++)
            if (q != p) {
                real unused;
                starts[n++] = (suspect_vec3){spawn_ray_to(&sp, light, policies[q], &unused).p,
                                             "another policy than the one given: pass `policy` on"};
            }
        assert_vec3_why(expected.p, ray_at(asked.r, asked.t_min), TOL(30), describe("%s: where the segment starts", in),
                        "the segment spawn_ray_to gives, from t = 0", starts, n);
        const suspect_vec3 ends[] = {
            {light, "the segment reaches the light: end it at the t_max that spawn_ray_to gives, a little before"},
            {sp.hit.point, "the segment runs from the light to the point: the shadow ray goes towards the light"},
            {ray_at((ray){expected.p, vec3_normalize(expected.d)}, t_end),
             "d normalized, the window kept: the light is at t = 1 only with spawn_ray_to's own d"},
        };
        assert_vec3_why(ray_at(expected, t_end), ray_at(asked.r, asked.t_max), TOL(30),
                        describe("%s: where the segment ends", in), "at t_max, as spawn_ray_to gives it", ends, 3);
    }
    shading_release(view);
    scene_free(&desc);
}

/* ---- the shade function: only the shadow rays that matter ------------------------------------- */

static void test_shadow_rays_only_when_needed(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    add_floor(&desc);
    scene_shader grey = scene_default_shader(SHADER_LAMBERTIAN);
    grey.diffuse_color = color_make((real)0.25, (real)0.25, (real)0.25);
    desc.surfaces[0].shader = scene_add_shader(&desc, grey);
    shading_point sp;

    /* no light: black, no shadow ray */
    shading_view *view = shade_at(&desc, eye, spot, &sp);
    uint64_t rays[RAY_KINDS] = {0};
    color c = shade_shadows(&view->tr, &sp, 0, rays);
    assert_close(0, c.r, 0);
    assert_int_equal(0, rays[RAY_SHADOW]);
    shading_release(view);

    /* a light below the floor (n . l < 0): black, no shadow ray */
    scene_add_light(&desc, (scene_light){.position = vec3_add(spot, vec3_make(1, -3, 1)), .intensity = {9, 9, 9}});
    view = shade_at(&desc, eye, spot, &sp);
    c = shade_shadows(&view->tr, &sp, 0, rays);
    assert_close(0, c.r, 0);
    assert_int_equal(0, rays[RAY_SHADOW]);
    shading_release(view);

    /* a light above: one shadow ray, and the Lambert term: 0.25 * 9 * (3/sqrt(11)) / 11 */
    desc.lights[0].position = vec3_add(spot, vec3_make(1, 3, 1));
    view = shade_at(&desc, eye, spot, &sp);
    c = shade_shadows(&view->tr, &sp, 0, rays);
    assert_int_equal(1, rays[RAY_SHADOW]);
    assert_close(0.25 * 9 * 3 / pow(11, 1.5), c.r, TOL(1) * 30); /* the point is ~24 from the origin */
    shading_release(view);

    /* a second light, 2 above the point, 4 strong: the stage still shades by the first light alone */
    scene_add_light(&desc, (scene_light){.position = vec3_add(spot, vec3_make(0, 2, 0)), .intensity = {4, 4, 4}});
    view = shade_at(&desc, eye, spot, &sp);
    c = shade_shadows(&view->tr, &sp, 0, rays);
    assert_close_why(0.25 * 9 * 3 / pow(11, 1.5), c.r, TOL(1) * 30,
                     "the floor point below the eye, lights 9 at the point + (1, 3, 1) and 4 at the point + (0, 2, 0)",
                     "the stage shades by the scene's first light, as chapter 05 (README, \"The stage's shade "
                     "function\")",
                     NULL, 0);
    shading_release(view);

    /* the floor seen from below, the first light below it too (the point + (1, -3, 1)): the shading normal
     * is -y, towards the viewer, and the light is in front of it: 0.25 * 9 * (3/sqrt(11)) / 11 again */
    desc.lights[0].position = vec3_add(spot, vec3_make(1, -3, 1));
    view = shade_at(&desc, vec3_add(spot, vec3_make(1, -7, 4)), spot, &sp);
    c = shade_shadows(&view->tr, &sp, 0, rays);
    assert_close_why(0.25 * 9 * 3 / pow(11, 1.5), c.r, TOL(1) * 30,
                     "the floor (geometric normal +y) seen from below, the light 9 at the point + (1, -3, 1)",
                     "the Lambert term with the shading normal sp->n, turned towards the viewer, the one "
                     "light_blocked tested (README, \"The stage's shade function\")",
                     NULL, 0);
    shading_release(view);
    scene_free(&desc);
}

/* ---- leaving a surface: spawn_ray and spawn_ray_to ------------------------------------------- */

/* The offsets of each policy, for a ray to either side of the surface (a
 * shadow or mirror ray goes to the viewer's side, a refracted ray through). */
static void test_spawn_ray_offsets(void **state)
{
    (void)state;
    shading_point sp = {.r = {{100, 50, -25}, {-1, -1, 0}}};
    sp.hit.point = vec3_make(40, 3, -25);
    sp.hit.normal = vec3_normalize(vec3_make(0, 3, 4)); /* (0, 0.6, 0.8) */
    vec3 up = {0, 2, 1}, through = {0, -2, -1};
    assert_vec3_close(sp.hit.point, spawn_ray(&sp, up, EPS_NONE).p, 0);
    /* fixed: 1e-3 along d */
    vec3 moved = vec3_sub(spawn_ray(&sp, up, EPS_FIXED).p, sp.hit.point);
    assert_close(1e-3, vec3_length(moved), 64 * REAL_EPSILON);
    assert_close(0, vec3_length(vec3_cross(moved, up)), 64 * REAL_EPSILON);
    /* bound: along the geometric normal, to the side d goes, by eps_bound */
    real bound = eps_bound(&sp);
    assert_close(EPS_BOUND_ULPS * REAL_EPSILON * 100, bound, 0); /* the largest coordinate: the ray's 100 */
    vec3 out = vec3_sub(spawn_ray(&sp, up, EPS_BOUND).p, sp.hit.point);
    vec3 in = vec3_sub(spawn_ray(&sp, through, EPS_BOUND).p, sp.hit.point);
    assert_true(vec3_dot(out, sp.hit.normal) > 0);
    assert_true(vec3_dot(in, sp.hit.normal) < 0);
    assert_close(bound, vec3_length(out), bound / 4); /* rounded to the spacing of reals near 40 */
    assert_close(bound, vec3_length(in), bound / 4);
    /* the direction is kept */
    assert_vec3_close(up, spawn_ray(&sp, up, EPS_BOUND).d, 0);
}

/* The segment to a target ends at t = 1 at the target, and stops short of it
 * by nothing (none), 1e-3 (fixed), or an error bound (bound). */
static void test_spawn_ray_to_far_end(void **state)
{
    (void)state;
    shading_point sp = {.r = {{0, 10, 0}, {1, -1, 0}}};
    sp.hit.point = vec3_make(10, 0, 0);
    sp.hit.normal = vec3_make(0, 1, 0);
    vec3 light = {10, 8, 6}; /* 10 away */
    real t_max;
    for (int p = 0; p < 3; p++) {
        ray r = spawn_ray_to(&sp, light, policies[p], &t_max);
        assert_vec3_close(light, ray_at(r, 1), TOL(16));
        real stop = (1 - t_max) * vec3_length(r.d); /* world units before the light */
        real expected = p == 0 ? 0 : p == 1 ? (real)1e-3 : EPS_BOUND_ULPS * REAL_EPSILON * 10;
        assert_close(expected, stop, TOL(16) + expected / 1000);
    }
    /* A light far from the origin, 1000 from a point near it: a surface through the light is computed as
     * far off as the light's own coordinates allow, so the bound's segment stops 32 REAL_EPSILON times its
     * largest coordinate (800) before it.  t_max near 1 is rounded by REAL_EPSILON / 4 at most, 250
     * REAL_EPSILON of stop at |d| = 1000: 256 REAL_EPSILON, a hundredth of the stop. */
    const vec3 far_light = {10, 600, 800};
    ray r = spawn_ray_to(&sp, far_light, EPS_BOUND, &t_max);
    real stop = (1 - t_max) * vec3_length(r.d);
    assert_close_why(EPS_BOUND_ULPS * REAL_EPSILON * 800, stop, 256 * REAL_EPSILON,
                     "spawn_ray_to from the point (10, 0, 0) to the light (10, 600, 800), policy bound: how far "
                     "the segment stops before the light",
                     "spawn_ray_to is given: its back-off is the bound of the larger coordinates, the target's or "
                     "the ray's start (README, \"One way out for every secondary ray\")",
                     NULL, 0);
}

/* ---- acne and leaks ------------------------------------------------------------------------- */

/* The default policy has neither acne nor leaks, on the square or on the
 * sphere, at any scale from 1e-4 to 1e4 (acne.h).  The blunder has acne on
 * the sphere at every scale (on the square less: chapter 03's test refuses
 * a ray whose start its arithmetic cannot tell from the triangle's plane,
 * common/crossing.h, and crosses only the others). */
static void test_no_acne_no_leak(void **state)
{
    (void)state;
    for (int shape = 0; shape < ACNE_SHAPES; shape++) {
        for (int k = 0; k < ACNE_SCALES; k++) {
            acne_result bound, none;
            assert_int_equal(0, acne_measure((acne_shape)shape, acne_scales[k], EPS_BOUND, 32, &bound));
            /* every point of the square, and most of the sphere's (those that face the light) */
            const int least = shape == ACNE_SQUARE ? 32 * 32 : 32 * 32 / 2;
            assert_true_why(bound.points >= least,
                            "acne_measure(%s at scale %g, the default policy, 32 x 32 eye rays): points counted "
                            "(eye rays that hit the shape where the light is in front)\n"
                            "    expected at least %d\n    got      %ld\n    likely mistake: the eye rays miss the "
                            "shape: the intersections of chapters 02 to 04 (sphere_intersect, triangle_intersect, "
                            "surfaces_intersect; run their suites); light_blocked does not enter this count",
                            acne_shape_names[shape], (double)acne_scales[k], least, bound.points);
            if (bound.acne != 0 || bound.leak != 0)
                fail_msg("%s at scale %g: %.2f %% acne, %.2f %% leak with the default policy\n    likely mistake: %s",
                         acne_shape_names[shape], (double)acne_scales[k], bound.acne, bound.leak,
                         bound.acne != 0 ? "the shadow ray leaves from the hit point itself and meets its own "
                                           "surface: build it with spawn_ray_to(sp, light_pos, policy, &t_max), "
                                           "which moves its start off the surface as the policy says"
                                         : "the window must be (0, t_max) with the t_max spawn_ray_to gives: a "
                                           "blocker just short of the light counts");
            assert_int_equal(0, acne_measure((acne_shape)shape, acne_scales[k], EPS_NONE, 32, &none));
            if (shape == ACNE_SPHERE && none.acne < 10)
                fail_msg("sphere at scale %g: the blunder gives only %.2f %% acne", (double)acne_scales[k], none.acne);
        }
    }
}

static const graded_test tests[] = {
    GRADED(test_occluder_between_beyond_behind, 4),
    GRADED(test_light_on_a_surface, 3),
    GRADED(test_light_behind_the_surface, 2),
    GRADED(test_shadow_ray_is_the_segment, 2),
    GRADED(test_shadow_rays_only_when_needed, 2),
    GRADED(test_no_acne_no_leak, 3),
    GRADED(test_spawn_ray_offsets, 0),    /* handed out complete: no points */
    GRADED(test_spawn_ray_to_far_end, 0), /* handed out complete: no points */
};

SUITE_MAIN("06_shadows", tests)
