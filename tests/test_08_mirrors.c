/* Chapter 08: the mirror direction, the recursive call, depth and weight, the furnace. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "08_mirrors/mirror.h"
#include "08_mirrors/scenes/mirror_scene.h"
#include "08_mirrors/path.h"
#include "08_mirrors/shade_glazed.h"
#include "probe_shader.h"
#include "scene_build.h"
#include "shading_suite.h"
#include "suite.h"

/* A few roundings of values of size about 1 (see test_05_lambert.c). */
#define TOL(size) (32 * REAL_EPSILON * (size))

static const vec3 far_point = {-37.25, 12.5, 53.125};

static unsigned long rng = 12345; /* suite_uniform's state */

/* ---- the mirror direction -------------------------------------------------------------------- */

/* Known directions: 45 degrees down onto the floor comes up at 45 degrees;
 * head on comes straight back; along the surface goes on; the lecture's
 * r = 2 (n . v) n - v for v = -d. */
static void test_reflect_known(void **state)
{
    (void)state;
    vec3 up = {0, 1, 0};
    const suspect_vec3 s45[] = {
        {{1, -1, 0}, "r = d: the part of d along n must change sign"},
        {{-1, -1, 0}, "-r: r = d - 2 (d . n) n, not 2 (d . n) n - d (that is the lecture's form for v = -d)"},
        {{(real)0.70710678118654752, (real)0.70710678118654752, 0},
         "d normalized: r keeps the length of d (d may have any length), r = d - 2 (d . n) n"},
        {{1, -3, 0}, "d + 2 (d . n) n: the correction is subtracted"},
        {{1, 0, 0}, "d - (d . n) n is the part along the surface only: the factor 2 is missing"},
    };
    assert_vec3_why(vec3_make(1, 1, 0), reflect(vec3_make(1, -1, 0), up), 0,
                    "reflect(d = (1, -1, 0), n = (0, 1, 0)): 45 degrees down onto a floor",
                    "r = d - 2 (d . n) n", s45, sizeof s45 / sizeof s45[0]);
    assert_vec3_close(vec3_make(-3, 2.5, 7), reflect(vec3_make(-3, -2.5, 7), up), 0);
    assert_vec3_close(vec3_make(0, 4, 0), reflect(vec3_make(0, -4, 0), up), 0);      /* head on */
    assert_vec3_close(vec3_make(2, 0, -1), reflect(vec3_make(2, 0, -1), up), 0);      /* along the surface */
    assert_vec3_close(vec3_make(1, 1, 0), reflect(vec3_make(1, -1, 0), vec3_neg(up)), 0); /* either side of n */
    /* a tilted plane: n = (2, -3, 6) / 7 and d = (1, 2, -2): d . n = -16/7,
     * r = d + (32/7) n = (1 + 64/49, 2 - 96/49, -2 + 192/49) */
    vec3 n = vec3_normalize(vec3_make(2, -3, 6));
    const suspect_vec3 st[] = {
        {{1 - 64.0 / 49, 2 + 96.0 / 49, -2 - 192.0 / 49}, "d + 2 (d . n) n: the correction is subtracted"},
        {{1 + 32.0 / 49, 2 - 48.0 / 49, -2 + 96.0 / 49}, "the factor 2 is missing"},
    };
    assert_vec3_why(vec3_make(113.0 / 49, 2.0 / 49, 94.0 / 49), reflect(vec3_make(1, 2, -2), n), TOL(4),
                    "reflect(d = (1, 2, -2), n = (2, -3, 6) / 7)", "r = d - 2 (d . n) n", st,
                    sizeof st / sizeof st[0]);
}

/* Random directions and normals: r keeps the length of d, flips its part
 * along n and keeps the rest (r + d is along the surface, r - d along n), and
 * is the lecture's 2 (n . v) n - v with v = -d / |d|. */
static void test_reflect_random(void **state)
{
    (void)state;
    for (int k = 0; k < 1000; k++) {
        vec3 n = suite_random_unit(&rng);
        vec3 d = vec3_scale(suite_random_unit(&rng), (real)(0.1 + 10 * suite_uniform(&rng)));
        real size = vec3_length(d);
        vec3 r = reflect(d, n);
        const suspect unit[] = {{1, "d normalized: r keeps the length of d (d may have any length)"}};
        assert_close_why(size, vec3_length(r), TOL(4 * size),
                         describe("|reflect(d, n)| for |d| = %g", (double)size), "r = d - 2 (d . n) n", unit, 1);
        assert_close(-vec3_dot(d, n), vec3_dot(r, n), TOL(4 * size));
        assert_close(0, vec3_length(vec3_cross(vec3_sub(r, d), n)), TOL(8 * size));
        vec3 v = vec3_scale(d, -1 / size);
        vec3 lecture = vec3_sub(vec3_scale(n, 2 * vec3_dot(n, v)), v);
        assert_vec3_close(lecture, vec3_scale(r, 1 / size), TOL(8));
    }
}

/* ---- the recursive call ---------------------------------------------------------------------- */

/* The probe (probe_shader.h) shows its diffuse colour; every other shader is glazed. */
static color probe_shade(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays)
{
    if (probe_took(tr, sp, depth))
        return tr->desc->shaders[probe_shader].diffuse_color;
    return shade_glazed(tr, sp, depth, rays);
}

static path_knobs knobs_of(int depth, real min_weight)
{
    return (path_knobs){.phong = PHONG_KNOBS_DEFAULT, .depth = depth, .min_weight = min_weight};
}

/* The tracer's knobs aimed at *k, as chapter 08's renderer aims them. */
static stage_knobs aimed_at(const path_knobs *k)
{
    return (stage_knobs){.spawn = &k->phong.spawn, .phong = &k->phong, .path = k};
}

/* Traces one eye ray through desc with the glazed shader (and the probe). */
static color trace_one(const scene *desc, const path_knobs *knobs, ray r, uint64_t *rays)
{
    const stage_knobs aimed = aimed_at(knobs);
    return probe_trace(desc, probe_shade, &aimed, r, rays);
}

/* A count (rays, probe hits, depth) against the expected one, with the
 * input and the likely mistake in the message. */
static void check_count(long long expected, long long got, const char *input, const char *what,
                        const char *mistake)
{
    if (got != expected)
        fail_msg("%s: %s\n    expected %lld\n    got      %lld\n    likely mistake: %s", input, what, expected, got,
                 mistake);
}

/* A count, a byte or a value that must stay within a bound: got <= bound
 * (at_most) or got > bound (a NaN is neither), the message as check_count's. */
static void check_bound(bool at_most, double bound, double got, const char *input, const char *what,
                        const char *mistake)
{
    assert_true_why(at_most ? got <= bound : got > bound,
                    "%s: %s\n    expected %s %.17g\n    got      %.17g\n    likely mistake: %s", input, what,
                    at_most ? "at most" : "more than", bound, got, mistake);
}

static int add_shader(scene *desc, shader_kind kind, color diffuse, color k_m)
{
    scene_shader s = scene_default_shader(kind);
    s.diffuse_color = diffuse;
    s.mirror_coefficient = k_m;
    return scene_add_shader(desc, s);
}

/* A big triangle around `centre` in the plane with unit normal n (wound so
 * that its normal is n). */
static void add_plane(scene *desc, int shader, vec3 centre, vec3 n, real size)
{
    vec3 a = vec3_normalize(vec3_cross(n, vec3_make((real)0.3, (real)0.5, (real)0.8)));
    vec3 b = vec3_cross(n, a);
    vec3 v[3];
    for (int k = 0; k < 3; k++) {
        double angle = 2.0943951023931957 * k; /* 120 degrees apart, counter-clockwise about n */
        v[k] = vec3_add(centre,
                        vec3_add(vec3_scale(a, size * (real)cos(angle)), vec3_scale(b, size * (real)sin(angle))));
    }
    scene_add_surface(desc,
                      (scene_surface){.kind = SURFACE_TRIANGLE, .shader = shader, .v0 = v[0], .v1 = v[1], .v2 = v[2]});
}

/* The mirror ray turns about the shading normal sp->n, which a later chapter
 * tilts away from the geometric one (chapter 10 interpolates it): here the
 * mirror's point with sp->n tilted 20 degrees from hit.normal, and a probe
 * (radius 0.5, 2 away) along reflect(d, sp->n).  The mirror direction about
 * hit.normal is 40 degrees from it, well outside the probe's 14.5. */
static void mirror_about_shading_normal(void)
{
    scene desc;
    scene_init(&desc);
    const vec3 n = {0, 1, 0}, centre = {(real)0.5, 0, (real)0.25};
    add_plane(&desc, add_shader(&desc, SHADER_LAMBERTIAN, color_make(0, 0, 0), color_make(1, 1, 1)), centre, n, 10);
    const vec3 tilted = {(real)0.34202014332566873, (real)0.93969262078590838, 0}; /* (sin 20, cos 20, 0) */
    const ray eye_ray = {vec3_add(centre, vec3_make(-1, 3, (real)0.5)), vec3_make(1, -3, (real)-0.5)};
    const vec3 r = reflect(eye_ray.d, tilted), r_geometric = reflect(eye_ray.d, n);
    probe_shader = add_shader(&desc, SHADER_LAMBERTIAN, color_make(1, 1, 1), color_make(0, 0, 0));
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = probe_shader,
                                             .center = vec3_add(centre, vec3_scale(vec3_normalize(r), 2)),
                                             .radius = 0.5});
    path_knobs knobs = knobs_of(PATH_DEFAULT_DEPTH, PATH_DEFAULT_MIN_WEIGHT);
    const stage_knobs aimed = aimed_at(&knobs);
    shading_point sp;
    shading_view *view = suite_shading_point(&desc, &aimed, eye_ray, &sp);
    sp.n = tilted;
    view->tr.shade = probe_shade;
    probe.n = 0;
    uint64_t rays[RAY_KINDS] = {0};
    mirror_radiance(&view->tr, &sp, color_make(1, 1, 1), 0, rays);
    shading_release(view);
    const char *input = "mirror_radiance at a floor point whose shading normal sp->n is tilted 20 degrees from "
                        "hit.normal (as chapter 10 tilts it), a probe along reflect(sp->r.d, sp->n)";
    check_count(1, probe.n, input, "rays that reached the probe",
                "the mirror direction about hit.normal: reflect about the shading normal, reflect(sp->r.d, sp->n)");
    /* the direction of the probe's ray: a few roundings of unit vectors */
    const suspect_vec3 sd[] = {{vec3_normalize(r_geometric), "reflected about hit.normal: use the shading normal sp->n"}};
    assert_vec3_why(vec3_normalize(r), vec3_normalize(probe.r[0].d), TOL(8), describe("%s: its direction", input),
                    "reflect(sp->r.d, sp->n)", sd, 1);
    probe_shader = -1;
    scene_free(&desc);
}

/* A tilted mirror far from the origin and a probe where the mirror direction
 * goes: the probe receives one ray, from the mirror's point, at depth 1,
 * along reflect(d, n), carrying the weight k_m; the eye sees k_m times the
 * probe's colour (black diffuse, no lights).  One reflected ray is counted. */
static void test_mirror_ray_reaches_probe(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    desc.back_color = color_make((real)0.9, (real)0.9, (real)0.9);
    vec3 n = vec3_normalize(vec3_make(1, 4, -2));
    color k_m = {0.8, 0.5, 0.25};
    add_plane(&desc, add_shader(&desc, SHADER_LAMBERTIAN, color_make(0, 0, 0), k_m), far_point, n, 10);
    vec3 eye = vec3_add(far_point, vec3_make(-3, 5, 2));
    vec3 d = vec3_sub(far_point, eye);
    vec3 r = reflect(d, n); /* checked by test_reflect_known */
    probe_shader =
        add_shader(&desc, SHADER_LAMBERTIAN, color_make((real)0.2, (real)0.4, (real)0.6), color_make(0, 0, 0));
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = probe_shader,
                                             .center = vec3_add(far_point, vec3_scale(r, 2)), .radius = 0.5});
    path_knobs knobs = knobs_of(PATH_DEFAULT_DEPTH, PATH_DEFAULT_MIN_WEIGHT);
    uint64_t rays[RAY_KINDS] = {0};
    color L = trace_one(&desc, &knobs, (ray){eye, d}, rays);
    const char *input = "an eye ray onto a tilted mirror (k_m = (0.8, 0.5, 0.25)), a probe sphere in its mirror direction";
    check_count(1, (long long)rays[RAY_REFLECTED], input, "reflected rays counted",
                "count each mirror ray once: ++rays[RAY_REFLECTED]");
    check_count(1, probe.n, input, "rays that reached the probe",
                probe.n == 0 ? "no mirror ray, or not along reflect(sp->r.d, sp->n), or not traced"
                             : "the mirror ray was traced more than once");
    check_count(1, probe.depth[0], input, "depth of the ray that reached the probe",
                "trace(&next, ray, 0, REAL_INFINITY, depth + 1, rays): one level deeper");
    assert_int_equal(0, rays[RAY_SHADOW]); /* no lights */
    /* from the mirror's point (60 from the origin: the offset is tiny), along r */
    assert_vec3_close(far_point, probe.r[0].p, 1e4 * REAL_EPSILON * 60);
    assert_close(0, vec3_length(vec3_cross(vec3_normalize(probe.r[0].d), vec3_normalize(r))), TOL(8));
    check_bound(false, 0, vec3_dot(probe.r[0].d, r), input, "the probe's ray direction . r",
                "the mirror ray goes back along -r: r = d - 2 (d . n) n, not 2 (d . n) n - d (README, \"The mirror "
                "direction\")");
    const suspect_vec3 sw[] = {
        {{1, 1, 1}, "the path's weight was not carried: trace with next, not tr"},
        {{1, 1, 1}, "path_next asked with 1 instead of k_m: path_next(tr, depth, k_m, &next) multiplies the path's "
                    "weight by k_m"},
    };
    assert_vec3_why(vec3_make(0.8, 0.5, 0.25), vec3_make(probe.weight[0].r, probe.weight[0].g, probe.weight[0].b),
                    TOL(1), describe("%s: the weight of the probe's ray", input),
                    "trace with next, the tracer path_next filled in: it carries the path's weight", sw, 2);
    const suspect sl[] = {{0.2, "L_m not multiplied by k_m: the glazed term is k_m L_m"},
                          {0.8 * 0.8 * 0.2, "k_m applied twice"}};
    assert_close_why(0.8 * 0.2, L.r, TOL(1), describe("%s: the radiance the eye sees, red", input),
                     "k_m times the probe's colour 0.2 (black diffuse, no lights)", sl, 2);
    assert_close(0.5 * 0.4, L.g, TOL(1));
    assert_close(0.25 * 0.6, L.b, TOL(1));
    /* A radiance has no upper bound (a bright light, a low exposure): only the display clamps.  A probe of
     * colour (2.5, 1.25, 6) seen in the mirror gives k_m times it, (2, 0.625, 1.5), each one product of
     * values below 6 from the data: TOL(6). */
    desc.shaders[probe_shader].diffuse_color = color_make((real)2.5, (real)1.25, 6);
    uint64_t bright_rays[RAY_KINDS] = {0};
    L = trace_one(&desc, &knobs, (ray){eye, d}, bright_rays);
    const char *bright = "an eye ray onto a tilted mirror (k_m = (0.8, 0.5, 0.25)), a probe of colour (2.5, 1.25, 6) "
                         "in its mirror direction";
    const char *unbounded = "L_m is whatever radiance the mirror ray brings back, above 1 too: it is not clamped "
                            "on the way (only the display clamps, after the exposure); the glazed term is k_m L_m "
                            "(README, \"Calling trace again\")";
    const suspect sb[] = {{0.8, "L_m clamped to 1 before k_m: the radiance is not clamped on the way, only the "
                                "display clamps (README, \"Calling trace again\")"}};
    assert_close_why(0.8 * 2.5, L.r, TOL(6), describe("%s: the radiance the eye sees, red", bright), unbounded, sb, 1);
    assert_close_why(0.25 * 6, L.b, TOL(6), describe("%s: the radiance the eye sees, blue", bright), unbounded,
                     NULL, 0);
    /* A mirror of blue alone, k_m = (0, 0, 0.5): red and green reflect nothing, blue does, 0.5 * 6 = 3 */
    desc.shaders[desc.surfaces[0].shader].mirror_coefficient = color_make(0, 0, (real)0.5);
    uint64_t blue_rays[RAY_KINDS] = {0};
    L = trace_one(&desc, &knobs, (ray){eye, d}, blue_rays);
    assert_close_why(0.5 * 6, L.b, TOL(6),
                     "an eye ray onto a tilted mirror of blue alone (k_m = (0, 0, 0.5)), a probe of colour "
                     "(2.5, 1.25, 6) in its mirror direction: the radiance the eye sees, blue",
                     "a shader is a mirror when any channel of k_m is above 0, and a path goes on while the largest "
                     "channel of its weight is (README, \"The glazed surface\" and \"Calling trace again\")",
                     NULL, 0);
    /* The same mirror under --min-weight 0.2: the path's weight (0, 0, 0.5) has its largest channel 0.5 above
     * 0.2, so the ray is cast, though the channels' mean 1/6 is below 0.2: blue is again 0.5 x 6 = 3. */
    path_knobs strict = knobs_of(PATH_DEFAULT_DEPTH, (real)0.2);
    uint64_t strict_rays[RAY_KINDS] = {0};
    L = trace_one(&desc, &strict, (ray){eye, d}, strict_rays);
    assert_close_why(0.5 * 6, L.b, TOL(6),
                     "an eye ray onto a tilted mirror of blue alone (k_m = (0, 0, 0.5)), min_weight 0.2, a probe of "
                     "colour (2.5, 1.25, 6) in its mirror direction: the radiance the eye sees, blue",
                     "path_next compares the largest channel of the path's weight, max(w_r, w_g, w_b), with "
                     "min_weight, not the channels' mean: a ray is dropped only when its weight is below min_weight in "
                     "every channel (README, --min-weight)",
                     NULL, 0);
    scene_free(&desc);

    /* The mirror ray's window is (0, infinity): a probe as far away as a sky, centred 1e32 r away (radius 1e31,
     * hit near t = 1e32 with this d), is reached as the near one was; a window that ends at a large number of
     * one's own (1e30 for infinity) loses it, and the eye sees the background. */
    scene_init(&desc);
    desc.back_color = color_make((real)0.9, (real)0.9, (real)0.9);
    add_plane(&desc, add_shader(&desc, SHADER_LAMBERTIAN, color_make(0, 0, 0), k_m), far_point, n, 10);
    probe_shader =
        add_shader(&desc, SHADER_LAMBERTIAN, color_make((real)0.2, (real)0.4, (real)0.6), color_make(0, 0, 0));
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = probe_shader,
                                             .center = vec3_add(far_point, vec3_scale(r, (real)1e32)),
                                             .radius = (real)1e31});
    uint64_t sky_rays[RAY_KINDS] = {0};
    (void)trace_one(&desc, &knobs, (ray){eye, d}, sky_rays);
    check_count(1, probe.n, "an eye ray onto a tilted mirror, a probe sphere of radius 1e31 1e32 away in its mirror "
                            "direction",
                "rays that reached the probe",
                "the mirror ray goes as far as an eye ray: its window is (0, infinity), not up to a large number "
                "of one's own (README, \"Where the mirror ray starts\")");
    probe_shader = -1;
    scene_free(&desc);
    mirror_about_shading_normal();
}

/* Once spawn_ray has moved its start off the surface, the mirror ray is
 * traced from t = 0: a surface just beyond the offset is seen.  A floor
 * mirror at y = 0 and a probe, a lid at height h = 2^13 REAL_EPSILON that
 * covers only the side the mirror ray leaves to (x > h / 2): the eye ray at
 * 45 degrees down to (0.5, 0, 0.25) crosses y = h at x = 0.5 - h, beside the
 * lid, and the mirror ray at x = 0.5 + h, under it, at t = h (|d| = sqrt 2:
 * a distance of sqrt 2 h).  The bound policy's offset, 32 REAL_EPSILON times
 * coordinates of at most 3 along the normal, is 0.012 h. */
static void close_surface_seen(void)
{
    scene desc;
    scene_init(&desc);
    const vec3 centre = {(real)0.5, 0, (real)0.25};
    add_plane(&desc, add_shader(&desc, SHADER_LAMBERTIAN, color_make(0, 0, 0), color_make(1, 1, 1)), centre,
              vec3_make(0, 1, 0), 10);
    const real h = (real)ldexp(REAL_EPSILON, 13), x = centre.x + h / 2;
    probe_shader = add_shader(&desc, SHADER_LAMBERTIAN, color_make(1, 1, 1), color_make(0, 0, 0));
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_TRIANGLE, .shader = probe_shader,
                                             .v0 = vec3_make(x, h, centre.z - 1), .v1 = vec3_make(x, h, centre.z + 1),
                                             .v2 = vec3_make(x + 2, h, centre.z)});
    path_knobs knobs = knobs_of(PATH_DEFAULT_DEPTH, PATH_DEFAULT_MIN_WEIGHT);
    uint64_t rays[RAY_KINDS] = {0};
    trace_one(&desc, &knobs, (ray){vec3_add(centre, vec3_make(-2, 2, 0)), vec3_make(1, -1, 0)}, rays);
    const vec3 r = reflect(vec3_make(1, -1, 0), vec3_make(0, 1, 0)); /* exact: (1, 1, 0) */
    check_count(1, probe.n,
                describe("a floor mirror and a lid %g above it on the mirror ray's side (t = %g along it)", (double)h,
                         (double)h),
                "rays that reached the lid",
                r.x == 1 && r.y == 1 && r.z == 0
                    ? "the mirror ray traced from a t_min above 0 (or a fixed epsilon) skipped a close surface: "
                      "spawn_ray already moved its start off the surface, trace from t = 0"
                    : "reflect((1, -1, 0), (0, 1, 0)) is not (1, 1, 0): the mirror direction (test_reflect_known)");
    probe_shader = -1;
    scene_free(&desc);
}

/* The mirror ray leaves the surface as the tracer's --shadow-eps policy says
 * (chapter 06's spawn_ray with tracer_eps(tr)): with fixed it starts 1e-3
 * along the mirror direction, with bound an error bound off the surface.
 * The tilted mirror and probe of the test above; the probe records where
 * the ray started. */
static void test_mirror_ray_policy_from_knobs(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    vec3 n = vec3_normalize(vec3_make(1, 4, -2));
    add_plane(&desc, add_shader(&desc, SHADER_LAMBERTIAN, color_make(0, 0, 0), color_make(1, 1, 1)), far_point, n,
              10);
    vec3 eye = vec3_add(far_point, vec3_make(-3, 5, 2));
    ray eye_ray = {eye, vec3_sub(far_point, eye)};
    vec3 r = reflect(eye_ray.d, n);
    probe_shader = add_shader(&desc, SHADER_LAMBERTIAN, color_make(1, 1, 1), color_make(0, 0, 0));
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = probe_shader,
                                             .center = vec3_add(far_point, vec3_scale(r, 2)), .radius = 0.5});
    const eps_policy policies[] = {EPS_FIXED, EPS_BOUND};
    for (int k = 0; k < 2; k++) {
        path_knobs knobs = knobs_of(PATH_DEFAULT_DEPTH, PATH_DEFAULT_MIN_WEIGHT);
        knobs.phong.spawn.eps = policies[k];
        shading_point sp; /* the mirror's point, as the shade function is given it */
        const stage_knobs aimed = aimed_at(&knobs);
        shading_release(suite_shading_point(&desc, &aimed, eye_ray, &sp));
        vec3 expected = spawn_ray(&sp, reflect(sp.r.d, sp.n), policies[k]).p;
        uint64_t rays[RAY_KINDS] = {0};
        trace_one(&desc, &knobs, eye_ray, rays);
        const char *input = describe("a mirror ray with --shadow-eps=%s: its origin", eps_policy_names[policies[k]]);
        check_count(1, probe.n, input, "rays that reached the probe", "one mirror ray along reflect(sp->r.d, sp->n)");
        vec3 none = sp.hit.point, fixed = spawn_ray(&sp, r, EPS_FIXED).p, bound = spawn_ray(&sp, r, EPS_BOUND).p;
        const suspect_vec3 so[] = {
            {fixed, "the fixed policy whatever the knob: spawn_ray(sp, direction, tracer_eps(tr))"},
            {bound, "the bound policy whatever the knob: spawn_ray(sp, direction, tracer_eps(tr))"},
            {none, "started at the point itself: leave the surface through spawn_ray(sp, direction, tracer_eps(tr))"},
        };
        /* the point's coordinates are up to 60: the origin is the point plus
         * the offset, a few roundings at the spacing of reals near 60, well
         * inside TOL(64) = 2048 REAL_EPSILON (2.4e-4 in float, a quarter of
         * the fixed offset 1e-3, so the policies stay apart) */
        assert_vec3_why(expected, probe.r[0].p, TOL(64), input,
                        "spawn_ray(sp, reflect(sp->r.d, sp->n), tracer_eps(tr)): the tracer's policy", so,
                        sizeof so / sizeof so[0]);
    }
    probe_shader = -1;
    scene_free(&desc);
    close_surface_seen();
}

/* The glazed surface is chapter 07's result plus k_m L_m: with k_m = 0 it is
 * chapter 07's exactly and casts no mirror ray; with k_m it adds k_m times
 * what the mirror ray finds (here the backColor). */
static void test_glazed_adds_to_chapter_07(void **state)
{
    (void)state;
    for (int mirror = 0; mirror < 2; mirror++) {
        scene desc;
        scene_init(&desc);
        desc.back_color = color_make((real)0.3, (real)0.2, (real)0.1);
        desc.ambient = color_make((real)0.01, (real)0.02, (real)0.03);
        color k_m = mirror ? color_make((real)0.5, (real)0.25, (real)0.125) : color_make(0, 0, 0);
        scene_shader phong = scene_default_shader(SHADER_PHONG);
        phong.diffuse_color = color_make((real)0.2, (real)0.3, (real)0.1);
        phong.specular_color = color_make((real)0.4, (real)0.4, (real)0.4);
        phong.exponent = 20;
        phong.mirror_coefficient = k_m;
        vec3 n = vec3_normalize(vec3_make(-1, 3, 1));
        add_plane(&desc, scene_add_shader(&desc, phong), far_point, n, 10);
        scene_add_light(&desc,
                        (scene_light){.position = vec3_add(far_point, vec3_make(1, 4, 2)), .intensity = {5, 6, 7}});
        vec3 eye = vec3_add(far_point, vec3_make(2, 3, -1));
        path_knobs knobs = knobs_of(PATH_DEFAULT_DEPTH, PATH_DEFAULT_MIN_WEIGHT);
        uint64_t rays[RAY_KINDS] = {0}, rays_07[RAY_KINDS] = {0};
        probe_shader = -1;
        color L = trace_one(&desc, &knobs, (ray){eye, vec3_sub(far_point, eye)}, rays);
        /* chapter 07 alone on the same point */
        const stage_knobs aimed_07 = {.spawn = &knobs.phong.spawn, .phong = &knobs.phong};
        color L_07 = suite_trace(&desc, shade_phong, &aimed_07, (ray){eye, vec3_sub(far_point, eye)}, rays_07);
        const char *input = describe("a glazed Phong plane, k_m = %s, one light, the backColor in the mirror direction",
                                     mirror ? "(0.5, 0.25, 0.125)" : "0");
        check_bound(false, 0.01, L_07.r, input,
                    "chapter 07's shade_phong alone, red (lit: the light is on the viewer's side)",
                    "the test's expected value is chapter 07's shading, L_a + L_r, which the glazed surface adds "
                    "k_m L_m to: chapter 07's shade_phong (run test_07_blinn_phong)");
        check_count(mirror, (long long)rays[RAY_REFLECTED], input, "reflected rays",
                    "one mirror ray when k_m is not 0, counted once");
        check_count((long long)rays_07[RAY_SHADOW], (long long)rays[RAY_SHADOW], input, "shadow rays",
                    "the glazed surface is chapter 07's shading plus k_m L_m: the same shadow rays");
        const suspect sg[] = {{L_07.r + 0.3, "L_m not multiplied by k_m: the glazed term is k_m L_m"},
                              {k_m.r * 0.3, "chapter 07's L_a + L_r left out: L = L_a + L_r + k_m L_m"}};
        assert_close_why(L_07.r + k_m.r * 0.3, L.r, TOL(1), describe("%s: red", input),
                         "L = L_a + L_r (chapter 07) + k_m L_m", sg, 2);
        assert_close(L_07.g + k_m.g * 0.2, L.g, TOL(1));
        assert_close(L_07.b + k_m.b * 0.1, L.b, TOL(1));
        scene_free(&desc);
    }
}

/* Two facing mirrors, k_m = 0.5, black diffuse, ambient a: an eye ray
 * between them, along their normal, bounces back and forth.  At depth D
 * the eye sees a (1 + k + ... + k^D) = a (1 - k^(D+1)) / (1 - k), with D
 * reflected rays; with --min-weight 0.1 no ray of weight k^4 = 0.0625 is
 * cast: 3 reflected rays, whatever the depth. */
static void test_facing_mirrors_depth_and_weight(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    desc.ambient = color_make((real)0.1, (real)0.2, (real)0.4);
    desc.back_color = color_make(1, 1, 1); /* never seen */
    vec3 n = vec3_normalize(vec3_make(2, 1, -2)); /* (2, 1, -2) / 3 */
    int s = add_shader(&desc, SHADER_LAMBERTIAN, color_make(0, 0, 0), color_make(0.5, 0.5, 0.5));
    add_plane(&desc, s, far_point, n, 50);                                   /* facing +n */
    add_plane(&desc, s, vec3_add(far_point, vec3_scale(n, 3)), vec3_neg(n), 50); /* 3 away, facing -n */
    ray eye = {vec3_add(far_point, vec3_scale(n, 1)), vec3_scale(n, -1)};
    const int depths[] = {0, 1, 3, 10};
    for (int k = 0; k < 4; k++) {
        path_knobs knobs = knobs_of(depths[k], 0);
        uint64_t rays[RAY_KINDS] = {0};
        probe_shader = -1;
        color L = trace_one(&desc, &knobs, eye, rays);
        double sum = (1 - pow(0.5, depths[k] + 1)) / 0.5;
        const char *input = describe("two facing mirrors (k_m = 0.5), an eye ray between them, --depth %d", depths[k]);
        /* one ray too many or too few: the count or the depth path_next is asked with, off by one */
        long long got = (long long)rays[RAY_REFLECTED];
        const char *why = got == depths[k] + 1 ? "a mirror ray counted though path_next did not cast it: ask "
                                                 "path_next first, and count the ray only when it says yes"
                          : got == depths[k] - 1 ? "one level short: ask path_next(tr, depth, k_m, &next) with the "
                                                   "depth this call was given, and trace the ray with depth + 1"
                                                 : "one mirror ray per level, depth + 1 passed on, path_next asked "
                                                   "before each";
        check_count(depths[k], got, input, "reflected rays", why);
        const suspect sf[] = {{0.1, "no mirror ray traced: only the first surface's ambient"}};
        assert_close_why(0.1 * sum, L.r, TOL(1), describe("%s: red", input),
                         "a (1 + k + ... + k^D): each bounce adds k_m times what it sees", sf, 1);
        assert_close(0.4 * sum, L.b, TOL(2));
    }
    path_knobs knobs = knobs_of(PATH_DEFAULT_DEPTH, (real)0.1);
    uint64_t rays[RAY_KINDS] = {0};
    color L = trace_one(&desc, &knobs, eye, rays);
    check_count(3, (long long)rays[RAY_REFLECTED], "two facing mirrors (k_m = 0.5), --min-weight 0.1",
                "reflected rays", "ask path_next(tr, depth, k_m, &next) and trace with next: it stops a path "
                                  "whose weight falls below min_weight");
    assert_close(0.1 * 1.875, L.r, TOL(1));
    scene_free(&desc);
}

/* ---- a convex mirror never sees itself ------------------------------------------------------- */

/* A mirror sphere (k_m = 1, black diffuse) of radius s at s (3.7, 2.9,
 * -4.3), scales 1e-4 to 1e4, looked at from 3 s away by a grid of eye rays
 * that covers it to its rim.  Every eye ray that hits it casts exactly one
 * mirror ray, which must escape to the background: a mirror ray that hit the
 * sphere again would cast a second one.  So reflected rays = hits, and every
 * hit shows k_m times the backColor exactly. */
static void test_convex_mirror_never_sees_itself(void **state)
{
    (void)state;
    const real scales[] = {(real)1e-4, (real)1e-2, 1, (real)1e2, (real)1e4};
    for (int k = 0; k < 5; k++) {
        real s = scales[k];
        vec3 c = vec3_scale(vec3_make((real)3.7, (real)2.9, (real)-4.3), s);
        scene desc;
        scene_init(&desc);
        desc.back_color = color_make((real)0.25, (real)0.5, (real)0.75);
        int m = add_shader(&desc, SHADER_LAMBERTIAN, color_make(0, 0, 0), color_make(1, 1, 1));
        scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = m, .center = c, .radius = s});
        path_knobs knobs = knobs_of(PATH_DEFAULT_DEPTH, PATH_DEFAULT_MIN_WEIGHT);
        probe_shader = -1;
        const stage_knobs aimed = aimed_at(&knobs);
        shading_view *view = suite_view(&desc, probe_shade, &aimed);
        vec3 eye = vec3_add(c, vec3_scale(vec3_make(1, 2, 2), s)); /* 3 s from the centre */
        vec3 to_c = vec3_normalize(vec3_sub(c, eye));
        vec3 u = vec3_normalize(vec3_cross(to_c, vec3_make(0, 1, 0))), w = vec3_cross(u, to_c);
        uint64_t rays[RAY_KINDS] = {0};
        long hits = 0;
        const int n = 81;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++) {
                /* the sphere subtends asin(1/3): tan = 0.3536; the grid reaches 0.36 */
                real a = (real)0.36 * (2 * (real)i / (n - 1) - 1), b = (real)0.36 * (2 * (real)j / (n - 1) - 1);
                ray r = {eye, vec3_add(to_c, vec3_add(vec3_scale(u, a), vec3_scale(w, b)))};
                uint64_t before = rays[RAY_REFLECTED];
                color L = trace(&view->tr, r, 0, REAL_INFINITY, 0, rays);
                if (rays[RAY_REFLECTED] == before)
                    continue; /* missed the sphere */
                hits++;
                if (rays[RAY_REFLECTED] != before + 1 || L.g != desc.back_color.g)
                    fail_msg("scale %g, ray (%d, %d): %d mirror rays, L = %g (the mirror saw itself)", (double)s, i, j,
                             (int)(rays[RAY_REFLECTED] - before), (double)L.g);
            }
        if (!(hits > n * n / 2)) /* most of the grid is on the sphere */
            fail_msg("scale %g: mirror rays were counted for %ld of %d eye rays, expected more than half\n"
                     "    likely mistake: count each mirror ray once: ++rays[RAY_REFLECTED]",
                     (double)s, hits, n * n);
        shading_release(view);
        scene_free(&desc);
    }
}

/* ---- whole images ---------------------------------------------------------------------------- */

/* Renders desc at w x h with the glazed shader and knobs. */
static render_stats render_glazed(const scene *desc, const path_knobs *knobs, image *img, int w, int h)
{
    const stage_knobs aimed = aimed_at(knobs);
    return suite_render(desc, shade_glazed, &aimed, img, w, h);
}

/* The furnace: a mirror sphere (k_m = 1, black diffuse) in a uniform
 * background, no lights, fills the view's middle: it is invisible, every
 * pixel within 2/255 of the background, at the default depth.  At depth 0 it
 * is a black disc (the mirror term is not traced). */
static void test_furnace_mirror_sphere(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    desc.has_camera = true;
    desc.camera = (scene_camera){.kind = CAMERA_PERSPECTIVE, .view_point = {30.5, -20.25, 41}, .view_dir = {0, 0, -1},
                                 .view_up = {0, 1, 0}, .proj_distance = 1, .view_width = 1, .view_height = 1};
    desc.back_color = color_make((real)0.5, (real)0.5, (real)0.5);
    int m = add_shader(&desc, SHADER_LAMBERTIAN, color_make(0, 0, 0), color_make(1, 1, 1));
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = m, .center = {30.5, -20.25, 37},
                                             .radius = 1.5});
    const int side = 96;
    path_knobs knobs = knobs_of(PATH_DEFAULT_DEPTH, PATH_DEFAULT_MIN_WEIGHT);
    image img;
    render_stats stats = render_glazed(&desc, &knobs, &img, side, side);
    const char *furnace = "the mirror furnace: a mirror sphere (k_m = 1, black diffuse), a uniform background 0.5, no "
                          "lights, 96 x 96 at the default --depth";
    check_bound(true, 2, suite_worst_byte(&img, desc.back_color.g), furnace,
                "the largest difference from the background, in display bytes (green)",
                "the mirror must vanish (README, \"The furnace\"): each mirror ray leaves by spawn_ray(sp, "
                "reflect(sp->r.d, sp->n), tracer_eps(tr)) and is traced with next at depth + 1, its radiance "
                "returned; a black disc is a mirror term that brings nothing back (no ray traced, or its radiance "
                "dropped), black speckles a mirror that sees itself");
    check_bound(false, (double)((uint64_t)side * side / 4), (double)stats.by_kind[RAY_REFLECTED], furnace,
                "reflected rays (the sphere is big in the view)",
                "each eye ray on the sphere casts one mirror ray: count it, ++rays[RAY_REFLECTED], once path_next "
                "says yes");
    image_free(&img);
    knobs.depth = 0;
    stats = render_glazed(&desc, &knobs, &img, side, side);
    check_count(0, (long long)stats.by_kind[RAY_REFLECTED], "a mirror sphere rendered with --depth 0",
                "reflected rays", "a mirror ray counted though path_next did not cast it: ask path_next first, and "
                                  "count the ray only when it says yes");
    assert_close(0, img.pixels[side / 2 * side + side / 2].g, 0); /* the centre: a black disc */
    image_free(&img);
    scene_free(&desc);
}

/* The built-in scene: the glazed floor and the mirror ball cast mirror rays,
 * the other shaders none; every pixel finite and non-negative.  The
 * weight cut-off only ever removes rays. */
static void test_builtin_scene_rays(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    assert_int_equal(0, mirror_scene(&desc));
    path_knobs knobs = knobs_of(PATH_DEFAULT_DEPTH, PATH_DEFAULT_MIN_WEIGHT);
    image img;
    render_stats cut = render_glazed(&desc, &knobs, &img, 32, 32);
    for (int k = 0; k < 32 * 32; k++)
        assert_true_why(img.pixels[k].r >= 0 && isfinite(img.pixels[k].r),
                        "the built-in scene (mirror_scene) at 32 x 32, the default --depth and --min-weight: pixel "
                        "(i, j) = (%d, %d) (j from the bottom), red\n    expected finite and >= 0\n    got      %g\n"
                        "    likely mistake: L_m is black (0, 0, 0) when path_next casts no ray, never left unset, and "
                        "the glazed surface adds k_m L_m (README, \"Calling trace again\")",
                        k % 32, k / 32, (double)img.pixels[k].r);
    image_free(&img);
    knobs.min_weight = 0;
    render_stats all = render_glazed(&desc, &knobs, &img, 32, 32);
    image_free(&img);
    assert_int_equal(32 * 32, all.by_kind[RAY_EYE]);
    assert_int_equal(0, all.by_kind[RAY_REFRACTED]);
    check_bound(false, 32 * 32 / 4, (double)all.by_kind[RAY_REFLECTED],
                "the built-in scene (mirror_scene) at 32 x 32, --min-weight 0",
                "reflected rays (the glazed floor fills the lower half)",
                "each eye ray on the glazed floor (k_m = 0.3) casts a mirror ray: count it, ++rays[RAY_REFLECTED], "
                "once path_next says yes");
    check_bound(true, (double)all.by_kind[RAY_REFLECTED], (double)cut.by_kind[RAY_REFLECTED],
                "the built-in scene (mirror_scene) at 32 x 32, the default --min-weight 1e-3",
                "reflected rays, against those with --min-weight 0",
                "the weight cut-off only removes rays: ask path_next(tr, depth, k_m, &next), which applies "
                "--min-weight, and trace with next, which carries the path's weight");
    scene_free(&desc);
}

static const graded_test tests[] = {
    GRADED(test_reflect_known, 3),
    GRADED(test_reflect_random, 2),
    GRADED(test_mirror_ray_reaches_probe, 3),
    GRADED(test_mirror_ray_policy_from_knobs, 2),
    GRADED(test_glazed_adds_to_chapter_07, 2),
    GRADED(test_facing_mirrors_depth_and_weight, 3),
    GRADED(test_convex_mirror_never_sees_itself, 3),
    GRADED(test_furnace_mirror_sphere, 2),
    GRADED(test_builtin_scene_rays, 1),
};

SUITE_MAIN("08_mirrors", tests)
