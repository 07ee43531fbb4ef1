/* Chapter 07: the half vector, the specular term, ambient light and many lights. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "05_lambert/lambert.h"
#include "06_shadows/shadow.h"
#include "07_blinn_phong/phong.h"
#include "07_blinn_phong/shade_phong.h"
#include "scene_build.h"
#include "shading_suite.h"
#include "suite.h"

/* A few roundings of values of size about 1 (see test_05_lambert.c). */
#define TOL(size) (32 * REAL_EPSILON * (size))
/* Positions near |point| ~ 54 put up to 54 REAL_EPSILON / r into l and r^2;
 * a power p multiplies the relative error of n . h by p. */
#define FAR_TOL(size, r) (TOL(size) * (1 + 54 / (r)))

static const double pi = 3.14159265358979323846;
static const vec3 point = {37.25, -12.5, 53.125};
static vec3 unit_normal(void) { return vec3_normalize(vec3_make(2, -3, 6)); }

/* A unit vector at angle theta from n, in the plane of n and `towards`. */
static vec3 at_angle(vec3 n, vec3 towards, double theta)
{
    vec3 side = vec3_normalize(vec3_sub(towards, vec3_scale(n, vec3_dot(n, towards))));
    return vec3_add(vec3_scale(n, (real)cos(theta)), vec3_scale(side, (real)sin(theta)));
}

/* got < bound (below) or got > bound, or the test fails naming the input,
 * the bound, the value got and the likely mistake (a NaN is neither). */
static void check_order(double got, bool below, double bound, const char *input, const char *mistake)
{
    assert_true_why(below ? got < bound : got > bound,
                    "%s\n    expected %s %.17g\n    got      %.17g\n    likely mistake: %s", input,
                    below ? "less than" : "more than", bound, got, mistake);
}

/* ---- the half vector, inside the term ------------------------------------------------------ */

/* k_s max(0, n . h)^p I / r^2 for k_s = 0.9, I = 10, r = 2.5 (k_s I / r^2 = 1.44), with n . h = c. */
static double specular_of(double c, double p) { return 0.9 * 10 / 6.25 * pow(fmax(0, c), p); }

/* In the mirror configuration (the viewer at l mirrored about n) the half
 * vector is n, so every exponent gives k_s I / r^2.  The light is 2.5 away at
 * theta from n, the viewer at -theta.  A half vector that is not the unit
 * bisector of the two unit vectors v and l gives another n . h. */
static void test_half_vector(void **state)
{
    (void)state;
    vec3 n = unit_normal(), side = {1, 0.25, 0};
    color k_s = {0.9, 0.7, 0.3};
    const double p = 20;
    for (double deg = 5; deg < 90; deg += 21) {
        vec3 l = at_angle(n, side, deg * pi / 180), v = at_angle(n, side, -deg * pi / 180);
        scene_light light = {.position = vec3_add(point, vec3_scale(l, 2.5)), .intensity = {10, 10, 10}};
        color L = blinn_phong_specular(k_s, (real)p, point, n, v, &light, PHONG_COURSE);
        double c = cos(deg * pi / 180);
        const suspect sh[] = {
            {specular_of(2 * c, p), "h not normalized: h = (v + l) / |v + l|, a unit vector"},
            {specular_of(c, p), "n . h is cos(theta), not 1: h halved ((v + l) / 2 is not a unit vector), or h "
                                "taken as l or v; h is the unit bisector (v + l) / |v + l|"},
            {specular_of(vec3_dot(n, vec3_normalize(vec3_add(v, vec3_scale(l, 2.5)))), p),
             "l not normalized before the bisector: l = (light.pos - point) / r"},
            {0, "no highlight in the mirror configuration: l points from the point towards the light, and h is "
                "the sum v + l, not the difference"},
            {specular_of(1, p) / 10, "the light's intensity I missing: k_s max(0, n . h)^p I / r^2"},
            {specular_of(1, p) * p, "p as a factor: p is the exponent, max(0, n . h)^p"},
        };
        assert_close_why(specular_of(1, p), L.r, FAR_TOL(1.44, 2.5) * p,
                         describe("blinn_phong_specular(k_s.r = 0.9, p = 20, I = 10, r = 2.5, course form, the viewer "
                                  "at the mirror of the light, %g degrees from n): red", deg),
                         "k_s max(0, n . h)^p I / r^2 with h = (v + l) / |v + l|, which is n here", sh,
                         sizeof sh / sizeof sh[0]);
    }
    /* A fractional exponent: the viewer 20 degrees further from the mirror, so n . h = cos(10 degrees), and
     * p = 12.5: cos(10 deg)^12.5, not the 12th or 13th power (0.6 % apart). */
    vec3 l = at_angle(n, side, 40 * pi / 180), v = at_angle(n, side, -60 * pi / 180);
    scene_light light = {.position = vec3_add(point, vec3_scale(l, 2.5)), .intensity = {10, 10, 10}};
    double c = cos(10 * pi / 180);
    const suspect sp[] = {
        {specular_of(c, 12), "an integer power: p = 12.5 is not an integer; real_pow(x, p)"},
        {specular_of(c, 13), "an integer power rounded up: p = 12.5 is not an integer; real_pow(x, p)"},
        {specular_of(cos(20 * pi / 180), 12.5), "Phong's (r . v)^p, with r the mirror of l: Blinn-Phong's is "
                                                "(n . h)^p with the half vector h = (v + l) / |v + l|"},
    };
    assert_close_why(specular_of(c, 12.5),
                     blinn_phong_specular(k_s, (real)12.5, point, n, v, &light, PHONG_COURSE).r,
                     FAR_TOL(1.44, 2.5) * 12.5,
                     "blinn_phong_specular(k_s.r = 0.9, p = 12.5, I = 10, r = 2.5, course form, n . h = cos(10 "
                     "degrees)): red",
                     "k_s max(0, n . h)^p I / r^2 for a fractional p", sp, sizeof sp / sizeof sp[0]);
    /* Far from the origin: the point about 4.7e4 away, n = +y, the light at point + (1.5, 2, 0) (r = 2.5) and the
     * viewer at the mirror of l, (-0.6, 0.8, 0).  Adding 1.5 and 2 to the point's coordinates changes no
     * exponent, so the light's position is exact and light.pos - point = (1.5, 2, 0), r^2 = 6.25 come out exact
     * in both builds; h is n up to a rounding, and the term is k_s I / r^2 = 1.44 for every p, within
     * TOL(1.44) p.  r^2 taken as |L|^2 - 2 L . x + |x|^2 instead subtracts rounded numbers of 2.3e9: an error
     * of 1e-6 here (1.5e-7 of r^2) in double, as large as r^2 in float. */
    const vec3 far_point = {(real)15964.471884897, (real)-31769.995687733, (real)31263.587313206}, up = {0, 1, 0};
    const scene_light far_light = {.position = vec3_add(far_point, vec3_make((real)1.5, 2, 0)),
                                   .intensity = {10, 10, 10}};
    const color far_L = blinn_phong_specular(k_s, (real)p, far_point, up, vec3_make((real)-0.6, (real)0.8, 0),
                                             &far_light, PHONG_COURSE);
    assert_close_why(specular_of(1, p), far_L.r, TOL(1.44) * p,
                     "blinn_phong_specular(k_s.r = 0.9, p = 20, I = 10, r = 2.5, course form, the viewer at the mirror "
                     "of the light, the point (15964.47, -31770.00, 31263.59)): red",
                     "k_s max(0, n . h)^p I / r^2 with l and r^2 from the difference light.pos - point, which is "
                     "exact here; r^2 = |light.pos - point|^2 (not |L|^2 - 2 L . x + |x|^2, which cancels far from "
                     "the origin)",
                     NULL, 0);
}

/* ---- the specular term ------------------------------------------------------------------- */

/* The light 2.5 away at 40 degrees from n; the viewer at 40 + 2 alpha on the
 * other side, so that n . h = cos(alpha).  At the mirror configuration
 * (alpha = 0) every exponent gives k_s I / r^2; off it, cos(alpha)^p: a larger
 * p gives a narrower highlight. */
static void test_exponent_behaviour(void **state)
{
    (void)state;
    vec3 n = unit_normal(), side = {1, 0.25, 0};
    color k_s = {0.9, 0.7, 0.3};
    scene_light light = {.position = vec3_add(point, vec3_scale(at_angle(n, side, 40 * pi / 180), 2.5)),
                         .intensity = {10, 10, 10}};
    /* A scene file may give any exponent: fractional ones catch x^p by an integer loop. */
    const double exponents[] = {1, 2.5, 10, 37.5, 100, 1000};
    const int n_exponents = sizeof exponents / sizeof exponents[0];
    const double alphas[] = {0, 2, 5, 10};
    for (int a = 0; a < 4; a++) {
        vec3 v = at_angle(n, side, -(40 + 2 * alphas[a]) * pi / 180);
        double previous = INFINITY;
        for (int k = 0; k < n_exponents; k++) {
            color L = blinn_phong_specular(k_s, (real)exponents[k], point, n, v, &light, PHONG_COURSE);
            double cos_alpha = cos(alphas[a] * pi / 180), cos_l = cos(40 * pi / 180);
            double expected = 0.9 * 10 / 6.25 * pow(cos_alpha, exponents[k]);
            const suspect ss[] = {
                {expected * cos_l, "times n . l: that is the lecture's form; the course's has no cosine"},
                {0.9 * 10 / 6.25 * cos_alpha, "exponent ignored: (n . h)^p, with p the shader's exponent"},
                {0.9 * 10 * pow(cos_alpha, exponents[k]), "no falloff: divide by r^2"},
                {0.9 * 10 / 2.5 * pow(cos_alpha, exponents[k]), "divided by r, not r^2"},
                {10 / 6.25 * pow(cos_alpha, exponents[k]), "k_s missing"},
                {0.9 * 10 / 6.25 * pow(cos_alpha, ceil(exponents[k])),
                 "the power of a fractional p taken as an integer (a loop of products): p may be any real, "
                 "x^p is real_pow(x, p)"},
                {0.9 * 10 / 6.25 * pow(cos_alpha, floor(exponents[k])),
                 "the power of a fractional p taken as an integer (a loop of products, or p cast to int): p "
                 "may be any real, x^p is real_pow(x, p)"},
                {0.9 * 10 / 6.25 * exponents[k] * cos_alpha, "p as a factor: p is the exponent, max(0, n . h)^p"},
                {0.9 * 10 / 6.25 * pow(cos(2 * alphas[a] * pi / 180), exponents[k]),
                 "Phong's (r . v)^p, with r the mirror of l: Blinn-Phong's is (n . h)^p with the half vector h"},
            };
            /* cos^p has the relative error of cos times p */
            assert_close_why(expected, L.r, FAR_TOL(1.44, 2.5) * (1 + exponents[k] * alphas[a] / 10),
                             describe("blinn_phong_specular(k_s.r = 0.9, p = %g, I = 10, r = 2.5, course form, "
                                      "n . h = cos(%g degrees)): red", exponents[k], alphas[a]),
                             "k_s max(0, n . h)^p I / r^2", ss, sizeof ss / sizeof ss[0]);
            assert_close(L.r * 0.3 / 0.9, L.b, TOL(L.r));
            if (alphas[a] > 0) /* narrower with every larger p */
                check_order(L.r, true, previous,
                            describe("blinn_phong_specular(k_s.r = 0.9, I = 10, r = 2.5, course form, n . h = "
                                     "cos(%g degrees)): red for p = %g, against the smaller p before it",
                                     alphas[a], exponents[k]),
                            "max(0, n . h)^p falls as p grows when n . h < 1 (README, \"Specular shading\": "
                            "increasing p narrows the peak): p is the exponent, real_pow(max(0, n . h), p)");
            previous = L.r;
        }
    }
    /* concrete values: alpha = 5 degrees, p = 100: cos(5 deg)^100 = 0.683003, times k_s I / r^2 = 1.44 */
    vec3 v = at_angle(n, side, -50 * pi / 180);
    assert_close(0.983524, blinn_phong_specular(k_s, 100, point, n, v, &light, PHONG_COURSE).r, 1e-5);
    /* behind the normal's hemisphere (n . h < 0) there is no highlight, not a negative one: v = -n and
     * l = -(the unit vector 40 degrees from n) give n . h = -cos(20 degrees).  An even exponent makes
     * (n . h)^p positive, so clamping after the power is not the same as max(0, n . h)^p; a fractional
     * one makes it NaN. */
    vec3 below = vec3_neg(at_angle(n, side, 40 * pi / 180));
    scene_light under = {.position = vec3_add(point, vec3_scale(below, 2)), .intensity = {1, 1, 1}};
    const double behind_exponents[] = {3, 20, 2.5};
    for (int k = 0; k < 3; k++) {
        double p = behind_exponents[k];
        const suspect sb[] = {
            {-0.7 * pow(cos(20 * pi / 180), p) / 4, "negative: max(0, n . h)^p, clamp n . h before the power"},
            {0.7 * pow(cos(20 * pi / 180), p) / 4,
             "max(0, (n . h)^p): an even p makes a negative n . h positive; clamp n . h before the power"},
        };
        assert_close_why(0, blinn_phong_specular(k_s, (real)p, point, n, vec3_neg(n), &under, PHONG_COURSE).g, 0,
                         describe("blinn_phong_specular(k_s.g = 0.7, p = %g, v = -n, light 2 away below the "
                                  "surface: n . h = -cos(20 degrees)): green", p),
                         "k_s max(0, n . h)^p I / r^2 is 0 when n . h < 0", sb, sizeof sb / sizeof sb[0]);
    }
}

/* Channel by channel: k_s I with a coloured light, in the mirror
 * configuration (n . h = 1) at r = 2.5: k_s.c I.c / 6.25 in each channel c. */
static void test_specular_per_channel(void **state)
{
    (void)state;
    vec3 n = unit_normal(), side = {1, 0.25, 0};
    color k_s = {0.9, 0.7, 0.3};
    scene_light light = {.position = vec3_add(point, vec3_scale(at_angle(n, side, 40 * pi / 180), 2.5)),
                         .intensity = {10, 20, 5}};
    vec3 v = at_angle(n, side, -40 * pi / 180); /* the mirror direction of l */
    color L = blinn_phong_specular(k_s, 20, point, n, v, &light, PHONG_COURSE);
    const char *in = describe("blinn_phong_specular(k_s = (0.9, 0.7, 0.3), p = 20, I = (10, 20, 5), r = 2.5, "
                              "course form, mirror configuration n . h = 1)");
    /* n . h = 1 up to the roundings of l and h (FAR_TOL), times p = 20 through the power */
    const double tol = 20 * FAR_TOL(1, 2.5);
    const suspect sg[] = {
        {0.7 * 10 / 6.25, "I.r used for every channel: multiply channel by channel, color_mul(k_s, I)"},
        {0.7 * 5 / 6.25, "I.b used for every channel: multiply channel by channel, color_mul(k_s, I)"},
        {(0.7 + 20) / 6.25, "k_s added to I: multiply them, channel by channel (color_mul)"},
    };
    const suspect sr[] = {
        {0.9 / 6.25, "the light's intensity I missing: k_s max(0, n . h)^p I / r^2"},
        {10 / 6.25, "k_s missing: the highlight is k_s of the light"},
    };
    assert_close_why(0.9 * 10 / 6.25, L.r, tol * 1.44, describe("%s: red", in), "k_s.r I.r / r^2", sr,
                     sizeof sr / sizeof sr[0]);
    assert_close_why(0.7 * 20 / 6.25, L.g, tol * 2.24, describe("%s: green", in),
                     "each channel: k_s.g I.g, not another channel's", sg, sizeof sg / sizeof sg[0]);
    const suspect sb[] = {
        {0.3 * 10 / 6.25, "I.r used for every channel: multiply channel by channel, color_mul(k_s, I)"},
        {0.3 * 20 / 6.25, "I.g used for every channel: multiply channel by channel, color_mul(k_s, I)"},
    };
    assert_close_why(0.3 * 5 / 6.25, L.b, tol * 0.24, describe("%s: blue", in),
                     "each channel: k_s.b I.b, not another channel's", sb, sizeof sb / sizeof sb[0]);
}

/* The lecture's modified Blinn-Phong is the course's term times max(0, n . l):
 * at a grazing light (n . l = cos 78 degrees = 0.2079) the highlight is a
 * fifth of the course's. */
static void test_course_and_lecture_forms(void **state)
{
    (void)state;
    vec3 n = unit_normal(), side = {0, 1, 1};
    color k_s = {1, 1, 0};
    const double degrees[] = {0, 30, 78, 89};
    for (int k = 0; k < 4; k++) {
        double theta = degrees[k] * pi / 180;
        scene_light light = {.position = vec3_add(point, vec3_scale(at_angle(n, side, theta), 3)),
                             .intensity = {9, 9, 9}};
        vec3 v = at_angle(n, side, -theta + 0.05); /* near the mirror direction */
        color course = blinn_phong_specular(k_s, 50, point, n, v, &light, PHONG_COURSE);
        color lecture = blinn_phong_specular(k_s, 50, point, n, v, &light, PHONG_LECTURE);
        check_order(course.r, false, 0,
                    describe("blinn_phong_specular(k_s = (1, 1, 0), p = 50, I = 9, r = 3, light at %g degrees from "
                             "n, the viewer near its mirror direction), course form: red",
                             degrees[k]),
                    "no highlight near the mirror direction, where n . h is near 1: l points from the point towards "
                    "the light and h = (v + l) / |v + l|, the sum, not the difference, so k_s max(0, n . h)^p I / "
                    "r^2 > 0");
        const suspect sf[] = {
            {course.r, "the lecture's form is the course's times max(0, n . l); it was left out"},
            {course.r * cos(theta) * cos(theta), "n . l applied twice"},
        };
        assert_close_why(course.r * cos(theta), lecture.r, FAR_TOL(course.r, 3) * 50,
                         describe("blinn_phong_specular(p = 50, light at %g degrees from n), lecture form", degrees[k]),
                         "lecture: k_s max(0, n . h)^p max(0, n . l) I / r^2", sf, sizeof sf / sizeof sf[0]);
        assert_close(0, course.b, 0); /* k_s has no blue */
    }
    /* A light just below the surface (95 degrees from n: n . l = -0.087) and a
     * viewer 60 degrees from n on the other side: n . h = 0.954 > 0, so the
     * course's form (no cosine) has a highlight, and the lecture's is 0
     * exactly: max(0, n . l) = 0, never a negative radiance. */
    scene_light low = {.position = vec3_add(point, vec3_scale(at_angle(n, side, 95 * pi / 180), 3)),
                       .intensity = {9, 9, 9}};
    vec3 v = at_angle(n, side, -60 * pi / 180);
    color course = blinn_phong_specular(k_s, 50, point, n, v, &low, PHONG_COURSE);
    color lecture = blinn_phong_specular(k_s, 50, point, n, v, &low, PHONG_LECTURE);
    check_order(course.r, false, 0,
                "blinn_phong_specular(k_s = (1, 1, 0), p = 50, I = 9, light 3 away at 95 degrees from n, viewer at "
                "60 degrees on the other side: n . h = 0.954), course form: red",
                "the course's form has no cosine: k_s max(0, n . h)^p I / r^2 is positive here though n . l < 0; "
                "max(0, n . l) belongs to the lecture's form only (README, \"Specular shading\", the table of "
                "--phong)");
    const suspect sn[] = {
        {course.r * cos(95 * pi / 180), "negative: the lecture's cosine is max(0, n . l), clamped at 0"},
        {course.r, "the lecture's form is the course's times max(0, n . l); it was left out"},
        {-course.r * cos(95 * pi / 180), "|n . l|: the cosine is max(0, n . l), 0 for a light below the surface"},
    };
    assert_close_why(0, lecture.r, 0,
                     "blinn_phong_specular(p = 50, light 3 away at 95 degrees from n, viewer at 60 degrees on the "
                     "other side), lecture form: red",
                     "lecture: k_s max(0, n . h)^p max(0, n . l) I / r^2 is 0 when n . l < 0", sn,
                     sizeof sn / sizeof sn[0]);
}

/* ---- ambient light and the loop over the lights ------------------------------------------------- */

/* A Phong floor (y = 2, far from the origin) seen from above, the scene's
 * ambient, and lights; the shade function is called on the floor point the
 * eye ray finds. */
static const vec3 floor_centre = {20.25, 2, -10.5};
static const vec3 eye = {21.75, 9.5, -6.25};
static const vec3 spot = {20.625, 2, -11.375};

static void make_floor_scene(scene *desc, shader_kind kind)
{
    scene_init(desc);
    desc->ambient = color_make((real)0.02, (real)0.03, (real)0.04);
    scene_shader s = scene_default_shader(kind);
    s.diffuse_color = color_make((real)0.2, (real)0.3, (real)0.1);
    s.specular_color = color_make((real)0.5, (real)0.5, (real)0.5);
    s.exponent = 20;
    int shader = scene_add_shader(desc, s);
    suite_add_floor(desc, shader, floor_centre);
}

/* Shades the floor point with shade_phong; counts its rays into `rays`. */
static color shade_spot(const scene *desc, phong_form form, uint64_t *rays, shading_point *sp)
{
    static phong_knobs knobs;
    knobs = (phong_knobs){.spawn = {.eps = EPS_BOUND}, .form = form};
    const stage_knobs aimed = {.spawn = &knobs.spawn, .phong = &knobs};
    shading_view *view = suite_shading_point(desc, &aimed, (ray){eye, vec3_sub(spot, eye)}, sp);
    color c = shade_phong(&view->tr, sp, 0, rays);
    shading_release(view);
    return c;
}

/* What one unblocked light adds at sp with the floor's shader (the first):
 * Lambert plus the course's specular term. */
static color light_term(const scene *desc, const shading_point *sp, const scene_light *light)
{
    const scene_shader *s = &desc->shaders[0];
    return color_add(lambert(s->diffuse_color, sp->hit.point, sp->n, light),
                     blinn_phong_specular(s->specular_color, s->exponent, sp->hit.point, sp->n, sp->v, light,
                                          PHONG_COURSE));
}

/* The tests' expected radiance is built from light_term, which runs
 * blinn_phong_specular (and chapter 05's lambert): `light` lights the floor
 * point, which must get more than 0.01 in red from it. */
static void check_lit(color L, const char *light)
{
    check_order(L.r, false, 0.01,
                describe("light_term(%s) at the floor point, the test's expected contribution: lambert (chapter 05) + "
                         "blinn_phong_specular (course form): red",
                         light),
                "a light in front gives a positive term: blinn_phong_specular is never negative or NaN (max(0, n . h) "
                "clamped before the power: test_exponent_behaviour), or chapter 05's lambert (run test_05_lambert)");
}

/* The number of shadow rays shade_phong cast, checked after the radiance so
 * that a wrong sum is reported by what it is missing. */
static void check_shadow_rays(uint64_t expected, uint64_t got, const char *input, const char *mistake)
{
    if (got != expected)
        fail_msg("%s: shadow rays\n    expected %llu\n    got      %llu\n    likely mistake: %s", input,
                 (unsigned long long)expected, (unsigned long long)got, mistake);
}

/* Two lights add: ambient + (Lambert + specular) of each; a sphere that
 * blocks one of them leaves ambient + the other; one shadow ray per light. */
static void test_two_lights_add(void **state)
{
    (void)state;
    scene desc;
    make_floor_scene(&desc, SHADER_PHONG);
    scene_light a = {.position = vec3_add(spot, vec3_make(1.5, 4, -2)), .intensity = {20, 15, 10}};
    scene_light b = {.position = vec3_add(spot, vec3_make(-3, 2.5, 1)), .intensity = {5, 6, 7}};
    scene_add_light(&desc, a);
    scene_add_light(&desc, b);
    uint64_t rays[RAY_KINDS] = {0};
    shading_point sp;
    color both = shade_spot(&desc, PHONG_COURSE, rays, &sp);
    color La = light_term(&desc, &sp, &a), Lb = light_term(&desc, &sp, &b);
    check_lit(La, "light a: (20, 15, 10) at (1.5, 4, -2) from the point");
    check_lit(Lb, "light b: (5, 6, 7) at (-3, 2.5, 1) from the point");
    const suspect sl[] = {
        {desc.ambient.r, "no light added: loop over tr->desc->lights and add each unblocked one's contribution"},
        {desc.ambient.r + La.r, "only the first light: loop over all n_lights"},
        {desc.ambient.r + Lb.r, "only the last light: the loop starts at k = 0, and adds (+=) each contribution to "
                                "result, not replacing it"},
        {La.r + Lb.r, "ambient missing: start from result = ambient"},
        {2 * desc.ambient.r + La.r + Lb.r, "ambient added with each light: it is added once"},
        {3 * desc.ambient.r + La.r + Lb.r, "ambient added again with each light: it is added once, before the loop"},
    };
    assert_close_why(desc.ambient.r + La.r + Lb.r, both.r, TOL(1),
                     describe("shade_phong: a Phong floor point, ambient 0.02, two lights in front, nothing between"),
                     "result = ambient + the sum over the unblocked lights of light_contribution", sl,
                     sizeof sl / sizeof sl[0]);
    assert_close(0.03 + La.g + Lb.g, both.g, TOL(1));
    assert_close(0.04 + La.b + Lb.b, both.b, TOL(1));
    uint64_t shadow_both = rays[RAY_SHADOW]; /* checked below, after the blocked light's radiance */

    /* a sphere half-way to light a blocks it */
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = 0,
                                             .center = vec3_add(spot, vec3_make(0.75, 2, -1)), .radius = 0.3});
    rays[RAY_SHADOW] = 0;
    color one = shade_spot(&desc, PHONG_COURSE, rays, &sp);
    const suspect sb[] = {
        {desc.ambient.r + La.r + Lb.r, "the blocked light was added: ask light_blocked first"},
        {desc.ambient.r, "the loop stopped at the blocked first light: skip a blocked light, the lights after it "
                         "still count"},
    };
    assert_close_why(desc.ambient.r + Lb.r, one.r, TOL(1),
                     describe("shade_phong: the same point, a sphere between it and the first light"),
                     "a light whose shadow ray is blocked adds nothing", sb, sizeof sb / sizeof sb[0]);
    assert_close(0.04 + Lb.b, one.b, TOL(1));
    check_shadow_rays(2, shadow_both, "shade_phong: two lights in front of the floor point",
                      "one shadow ray per light in front, through light_blocked; none cast twice");
    check_shadow_rays(2, rays[RAY_SHADOW], "shade_phong: two lights in front, the first one blocked",
                      "one shadow ray per light in front: the loop goes on past a blocked light");
    scene_free(&desc);
}

/* Lights behind the surface add nothing and cast no shadow ray; the ambient
 * term is all that is left.  A Lambertian shader gets no highlight, even in
 * the mirror configuration. */
static void test_ambient_and_lights_behind(void **state)
{
    (void)state;
    scene desc;
    make_floor_scene(&desc, SHADER_LAMBERTIAN);
    uint64_t rays[RAY_KINDS] = {0};
    shading_point sp;
    /* No light in the scene at all: the ambient term alone, exactly, and no shadow ray. */
    color c = shade_spot(&desc, PHONG_LECTURE, rays, &sp);
    const suspect s0[] = {{0, "no ambient when the scene has no light: an early return for no lights (or a result "
                              "that starts at 0) skips it; start from result = ambient, then add each light"},
                          {desc.ambient.r * desc.shaders[0].diffuse_color.r,
                           "ambient times k_d: the course's ambient is a colour added as it is"}};
    assert_close_why(desc.ambient.r, c.r, 0, describe("shade_phong: ambient (0.02, 0.03, 0.04), no light in the scene"),
                     "result = ambient, plus each light of the scene (none here)", s0, sizeof s0 / sizeof s0[0]);
    assert_close(desc.ambient.g, c.g, 0);
    assert_close(desc.ambient.b, c.b, 0);
    check_shadow_rays(0, rays[RAY_SHADOW], "shade_phong: no light in the scene", "no light, no shadow ray");
    scene_add_light(&desc, (scene_light){.position = vec3_add(spot, vec3_make(1, -2, 0)), .intensity = {50, 50, 50}});
    scene_add_light(&desc, (scene_light){.position = vec3_add(spot, vec3_make(-1, -0.5, 2)), .intensity = {9, 9, 9}});
    c = shade_spot(&desc, PHONG_LECTURE, rays, &sp);
    /* Nothing is added to the ambient term: it comes back exactly. */
    const suspect sa[] = {{0, "ambient missing: start from result = ambient"},
                          {desc.ambient.r * desc.shaders[0].diffuse_color.r,
                           "ambient times k_d: the course's ambient is a colour added as it is"},
                          {2 * desc.ambient.r, "ambient added per light: add it once, before the loop"}};
    assert_close_why(desc.ambient.r, c.r, 0,
                     describe("shade_phong: ambient (0.02, 0.03, 0.04), both lights behind the floor"),
                     "result = ambient when no light is in front", sa, sizeof sa / sizeof sa[0]);
    assert_close(desc.ambient.g, c.g, 0);
    assert_close(desc.ambient.b, c.b, 0);
    check_shadow_rays(0, rays[RAY_SHADOW], "shade_phong: both lights behind the floor",
                      "a light behind the surface casts no shadow ray: ask light_blocked, which answers it without one");

    /* a light in the mirror direction of the eye: Lambert only, one shadow ray */
    vec3 mirror = vec3_sub(eye, spot);
    mirror.y = -mirror.y;
    scene_light m = {.position = vec3_sub(spot, mirror), .intensity = {30, 30, 30}};
    scene_add_light(&desc, m);
    c = shade_spot(&desc, PHONG_COURSE, rays, &sp);
    const suspect sm[] = {{0.02, "the light in front was not added"},
                          {0.02, "the loop stopped at a light behind the surface (light_blocked says blocked): skip "
                                 "it, the lights after it still count"}};
    assert_close_why(0.02 + lambert(desc.shaders[0].diffuse_color, sp.hit.point, sp.n, &m).r, c.r, TOL(1),
                     describe("shade_phong: a Lambertian floor, two lights behind it, then a light in the mirror "
                              "direction of the eye"),
                     "ambient + Lambert: a Lambertian shader has no highlight", sm, 2);
    check_shadow_rays(1, rays[RAY_SHADOW], "shade_phong: two lights behind the floor, one in front",
                      "a shadow ray for the light in front only");
    scene_free(&desc);
}

/* The floor seen from below, its back face: the shading normal n is turned
 * towards the viewer (-y), so a light below the floor lights the point and a
 * light above it is behind the surface: no shadow ray, nothing added (chapter
 * 05's rule, through light_blocked, which looks at n, not the geometric
 * normal +y). */
static void test_back_face_lights(void **state)
{
    (void)state;
    scene desc;
    make_floor_scene(&desc, SHADER_PHONG);
    scene_light under = {.position = vec3_add(spot, vec3_make(-1.5, -4, 2)), .intensity = {20, 15, 10}};
    scene_light over = {.position = vec3_add(spot, vec3_make(1, 3, -1)), .intensity = {30, 30, 30}};
    scene_add_light(&desc, over);
    scene_add_light(&desc, under);
    static phong_knobs knobs = PHONG_KNOBS_DEFAULT;
    const vec3 eye_below = vec3_add(spot, vec3_make(1.125, -7.5, 5.125));
    shading_point sp;
    const stage_knobs aimed = {.spawn = &knobs.spawn, .phong = &knobs};
    shading_view *view = suite_shading_point(&desc, &aimed, (ray){eye_below, vec3_sub(spot, eye_below)}, &sp);
    assert_vec3_close(vec3_make(0, 1, 0), sp.hit.normal, TOL(1)); /* geometric: the floor's +y */
    assert_vec3_close(vec3_make(0, -1, 0), sp.n, TOL(1));         /* shading: towards the viewer below */
    uint64_t rays[RAY_KINDS] = {0};
    color c = shade_phong(&view->tr, &sp, 0, rays);
    shading_release(view);
    color L = light_term(&desc, &sp, &under);
    check_lit(L, "the light below the floor, seen from below: n = -y");
    const suspect sf[] = {
        {desc.ambient.r, "the light below was skipped: in front means n . l > 0 for the shading normal n "
                         "(light_blocked judges it so), not the geometric normal hit.normal"},
        {desc.ambient.r, "the loop stopped at the light above, which light_blocked calls blocked (behind the "
                         "surface): skip it, the lights after it still count"},
    };
    assert_close_why(desc.ambient.r + L.r, c.r, TOL(1),
                     describe("shade_phong: the back of a Phong floor seen from below, one light below it, one "
                              "above it"),
                     "result = ambient + the contribution of the light on the viewer's side", sf,
                     sizeof sf / sizeof sf[0]);
    assert_close(desc.ambient.b + L.b, c.b, TOL(1));
    check_shadow_rays(1, rays[RAY_SHADOW], "shade_phong: the back of the floor, one light below it, one above it",
                      "a shadow ray for the light in front of the shading normal only (light_blocked judges it so)");
    scene_free(&desc);
}

/* The --shadow-eps policy of the tracer's knobs reaches the shadow rays: a
 * small sphere (radius 2e-4) sits on the segment from the floor point to the
 * light, 5e-4 from the point.  The policies none and bound start the shadow
 * ray before it: blocked, the ambient term only.  The policy fixed starts it
 * 1e-3 along the ray, beyond the sphere (the leak of chapter 06): lit. */
static void test_shadow_policy_from_knobs(void **state)
{
    (void)state;
    scene desc;
    make_floor_scene(&desc, SHADER_PHONG);
    scene_light light = {.position = vec3_add(spot, vec3_make(-3, 6, -2)), .intensity = {49, 49, 49}}; /* r = 7 */
    scene_add_light(&desc, light);
    vec3 l = vec3_make((real)(-3.0 / 7), (real)(6.0 / 7), (real)(-2.0 / 7));
    /* 60 degrees from the eye ray's direction: the eye ray passes 4.3e-4 from its centre */
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = 0,
                                             .center = vec3_add(spot, vec3_scale(l, (real)5e-4)), .radius = 2e-4});
    for (int p = 0; p < 3; p++) {
        static phong_knobs knobs;
        knobs = (phong_knobs){.spawn = {.eps = p}, .form = PHONG_COURSE};
        shading_point sp;
        const stage_knobs aimed = {.spawn = &knobs.spawn, .phong = &knobs};
        shading_view *view = suite_shading_point(&desc, &aimed, (ray){eye, vec3_sub(spot, eye)}, &sp);
        assert_vec3_close(vec3_make(0, 1, 0), sp.hit.normal, TOL(1)); /* the floor, not the sphere */
        uint64_t rays[RAY_KINDS] = {0};
        color c = shade_phong(&view->tr, &sp, 0, rays);
        shading_release(view);
        color L = light_term(&desc, &sp, &light);
        check_lit(L, "the light (49, 49, 49), 7 away");
        bool lit = p == EPS_FIXED;
        const suspect sk[] = {
            {lit ? desc.ambient.r : desc.ambient.r + L.r,
             "the policy was not the tracer's: pass tracer_eps(tr) to light_blocked, not a policy of your own"},
        };
        assert_close_why(desc.ambient.r + (lit ? L.r : 0), c.r, TOL(1),
                         describe("shade_phong with --shadow-eps=%s: a sphere of radius 2e-4 on the shadow ray, "
                                  "5e-4 from the floor point (%s)",
                                  eps_policy_names[p], lit ? "the ray starts beyond it" : "it blocks the light"),
                         lit ? "fixed starts the shadow ray 1e-3 along it, beyond the sphere: the light is added"
                             : "the shadow ray starts before the sphere: blocked, the ambient term only",
                         sk, sizeof sk / sizeof sk[0]);
        check_shadow_rays(1, rays[RAY_SHADOW], describe("shade_phong with --shadow-eps=%s", eps_policy_names[p]),
                          "one shadow ray per light in front");
    }
    scene_free(&desc);
}

static const graded_test tests[] = {
    GRADED(test_half_vector, 2),
    GRADED(test_exponent_behaviour, 3),
    GRADED(test_course_and_lecture_forms, 2),
    GRADED(test_specular_per_channel, 2),
    GRADED(test_two_lights_add, 3),
    GRADED(test_ambient_and_lights_behind, 2),
    GRADED(test_back_face_lights, 2),
    GRADED(test_shadow_policy_from_knobs, 2),
};

SUITE_MAIN("07_blinn_phong", tests)
