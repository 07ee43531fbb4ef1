/* Chapter 09: Snell's law, total internal reflection, Fresnel, glass in scenes, the furnace. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "08_mirrors/scenes/mirror_scene.h"
#include "09_refraction/fresnel.h"
#include "09_refraction/scenes/glass_scene.h"
#include "09_refraction/refract.h"
#include "09_refraction/shade_glass.h"
#include "probe_shader.h"
#include "scene_build.h"
#include "shading_suite.h"
#include "suite.h"

/* A few roundings of values of size about 1 (see test_05_lambert.c). */
#define TOL(size) (32 * REAL_EPSILON * (size))

static const double pi = 3.14159265358979323846;

/* Why refract reports total internal reflection where a ray gets through. */
static const char *const tir = "total internal reflection exactly when |S_t|^2 > 1, S_t = (eta_i / eta_t) S_i";

/* Why a scene with glass casts no (or too few) refracted rays. */
static const char *const no_transmitted = "the transmitted ray not traced: whenever glass_at says it transmits and "
                                          "1 - R > 0, trace it along e.T with weight 1 - R (README, \"The glass "
                                          "shader\")";

/* refract(d, n, eta_i, eta_t, T, cos_t) transmits (`where` says at what
 * angle); a failure names `why`. */
static void expect_transmits(vec3 d, vec3 n, real eta_i, real eta_t, const char *where, const char *why, vec3 *T,
                             real *cos_t)
{
    assert_true_why(
        refract(d, n, eta_i, eta_t, T, cos_t),
        "refract %s, from eta %g into %g: d = (%.9g, %.9g, %.9g), n = (%.9g, %.9g, %.9g)\n    expected true "
        "(a transmitted ray)\n    got      false (total internal reflection)\n    likely mistake: %s",
        where, (double)eta_i, (double)eta_t, (double)d.x, (double)d.y, (double)d.z, (double)n.x, (double)n.y,
        (double)n.z, why);
}

/* R (of `input`) is above `bound`: R climbs to 1 at the critical angle. */
static void expect_R_above(real R, real bound, const char *input, const char *why)
{
    assert_true_why(
        R > bound,
        "%s\n    expected R above %.9g (R climbs continuously to 1 at the critical angle)\n    got      %.17g\n"
        "    likely mistake: %s",
        input, (double)bound, (double)R, why);
}

/* What keeps Fresnel's and Schlick's R continuous up to 1 at the critical angle. */
static const char *const exact_at_critical = "R = (r_s^2 + r_p^2) / 2 is 1 where cos_t = 0 (r_s = r_p = 1): "
                                             "r_s and r_p as in the README, \"How much is reflected: Fresnel\"";
static const char *const schlick_at_critical = "out of glass the cosine is cos_t (the side of the smaller index), "
                                               "which goes to 0 at the critical angle: with cos_i, R is about 0.04 "
                                               "there and jumps to 1";

static unsigned long rng = 977; /* suite_uniform's state */

/* A unit vector perpendicular to the unit vector n. */
static vec3 tangent_of(vec3 n)
{
    vec3 a = real_abs(n.x) < (real)0.6 ? vec3_make(1, 0, 0) : vec3_make(0, 1, 0);
    return vec3_normalize(vec3_sub(a, vec3_scale(n, vec3_dot(a, n))));
}

/* The unit direction that meets the surface with unit normal n (on its side)
 * at angle theta: sin(theta) along the tangent t, -cos(theta) along n. */
static vec3 incoming(vec3 n, vec3 t, double theta)
{
    return vec3_add(vec3_scale(t, (real)sin(theta)), vec3_scale(n, (real)-cos(theta)));
}

/* ---- the transmitted direction --------------------------------------------------------------- */

/* Head on, nothing bends, both ways: T = d and cos(theta_t) = 1. */
static void test_refract_normal_incidence(void **state)
{
    (void)state;
    for (int k = 0; k < 20; k++) {
        vec3 n = suite_random_unit(&rng);
        vec3 d = vec3_neg(n);
        const real etas[][2] = {{1, 1.5}, {1.5, 1}, {1, 2.42}, {1.33, 1.5}};
        for (int e = 0; e < 4; e++) {
            vec3 T = {0, 0, 0};
            real cos_t = -1;
            expect_transmits(d, n, etas[e][0], etas[e][1], "head on (d = -n)",
                             "head on |S_i| = 0, so |S_t|^2 = 0: the test for total internal reflection is "
                             "|S_t|^2 > 1 (cos^2(theta_t) < 0), not the other way round",
                             &T, &cos_t);
            assert_vec3_close(d, T, TOL(1));
            assert_close(1, cos_t, TOL(1));
        }
    }
}

/* Equal indices on both sides: T = d at every angle, up to grazing.  With
 * r = eta_i / eta_t = 1, cos^2(theta_t) = (1 - r^2) + r^2 cos^2(theta_i) is
 * cos^2(theta_i) and r cos(theta_i) - cos(theta_t) is 0, so T = d (and
 * cos(theta_t) = cos(theta_i)) to a rounding or two of values of size 1:
 * 4 REAL_EPSILON.  The angles go to within 1e-6 rad of grazing, and include
 * cos(theta_i) = 1.3e-4, where a float |S_i|^2 taken from the vector rounds
 * to 1 and 1 - |S_i|^2 is lost. */
static void test_refract_equal_indices(void **state)
{
    (void)state;
    const real etas[] = {1, (real)1.33, (real)1.5};
    for (int k = 0; k < 600; k++) {
        vec3 n = suite_random_unit(&rng), t = tangent_of(n);
        double cos_theta = k < 300 ? suite_uniform(&rng) : pow(10, -2 - 4 * suite_uniform(&rng)); /* 1e-2 to 1e-6 */
        if (k == 300)
            cos_theta = 1.3e-4;
        double theta = acos(cos_theta);
        vec3 d = incoming(n, t, theta);
        real eta = etas[k % 3], cos_i = -vec3_dot(d, n);
        vec3 T = {0, 0, 0};
        real cos_t = -1;
        const char *input = describe("refract at cos(theta_i) = %.3g, eta %g on both sides", cos_theta, (double)eta);
        if (!refract(d, n, eta, eta, &T, &cos_t))
            fail_msg("%s\n    expected true (no surface: the ray goes straight on)\n    got      false\n"
                     "    likely mistake: |S_t|^2 computed from the vector d + cos(theta_i) n rounds to 1 or more near "
                     "grazing; take cos^2(theta_t) = (1 - r^2) + r^2 cos^2(theta_i), r = eta_i / eta_t, from the "
                     "cosine",
                     input);
        /* both are off when cos(theta_t) is not exactly cos(theta_i) */
        const char *grouping = "T = r d + (r cos(theta_i) - cos(theta_t)) n is d for r = 1 only when cos(theta_t) "
                               "comes out as cos(theta_i) exactly: take cos^2(theta_t) = (1 - r^2) + r^2 "
                               "cos^2(theta_i), grouped so; not 1 - r^2 (1 - cos^2(theta_i)), which rounds "
                               "1 - cos^2(theta_i) and back, nor 1 - |S_t|^2 with |S_t|^2 from the vector d + "
                               "cos(theta_i) n, which loses 1 - |S_t|^2 near grazing";
        assert_vec3_why(d, T, 4 * REAL_EPSILON, input, grouping, NULL, 0);
        assert_close_why(cos_i, cos_t, 4 * REAL_EPSILON * cos_i, describe("%s: cos_t", input), grouping, NULL, 0);
    }
    /* Exactly grazing, d . n = 0 (axis vectors, so the dot product is exactly 0): r = 1 gives
     * cos^2(theta_t) = 0 + 1 x 0 = 0 exactly, not below 0, so the ray transmits (refract.h) along
     * T = d + (0 - 0) n = d, with cos(theta_t) = sqrt(0) = 0: every operation is exact, yet allow the
     * loop's 4 REAL_EPSILON. */
    vec3 d = vec3_make(1, 0, 0), n = vec3_make(0, 1, 0), T = {0, 0, 0};
    real cos_t = -1;
    const char *const at_zero = "total internal reflection is cos^2(theta_t) < 0, strictly: here cos^2(theta_t) = "
                                "(1 - r^2) + r^2 cos^2(theta_i) = 0 and the ray goes straight on (T = d), so the "
                                "test <= 0 reports a transmitted ray reflected";
    expect_transmits(d, n, (real)1.5, (real)1.5, "exactly grazing (d . n = 0)", at_zero, &T, &cos_t);
    const char *const grazing = "refract exactly grazing, d = (1, 0, 0), n = (0, 1, 0), eta 1.5 on both sides";
    assert_vec3_why(d, T, 4 * REAL_EPSILON, grazing, at_zero, NULL, 0);
    assert_close_why(0, cos_t, 4 * REAL_EPSILON, describe("%s: cos_t", grazing), at_zero, NULL, 0);
}

/* r d + c n: the form of T, with a coefficient c of n right or wrong. */
static vec3 bent(vec3 d, vec3 n, double r, double c)
{
    return vec3_add(vec3_scale(d, (real)r), vec3_scale(n, (real)c));
}

/* Snell's law at random angles, into glass and out of it below the critical
 * angle: T is a unit vector in the plane of d and n, on the far side, and
 * eta_i sin(theta_i) = eta_t sin(theta_t). */
static void test_snell_law(void **state)
{
    (void)state;
    const real etas[][2] = {{1, 1.5}, {1.5, 1}, {1.33, 1}, {1, 1.7}};
    for (int k = 0; k < 1000; k++) {
        real eta_i = etas[k % 4][0], eta_t = etas[k % 4][1];
        double limit = eta_i > eta_t ? asin((double)(eta_t / eta_i)) : pi / 2;
        double theta_i = 0.98 * limit * suite_uniform(&rng);
        vec3 n = suite_random_unit(&rng), t = tangent_of(n);
        vec3 d = incoming(n, t, theta_i), T;
        real cos_t;
        const char *input = describe("refract at theta_i = %.2f degrees from eta %g into %g", theta_i * 180 / pi,
                                     (double)eta_i, (double)eta_t);
        if (!refract(d, n, eta_i, eta_t, &T, &cos_t))
            fail_msg("%s (below any critical angle)\n    expected true (a transmitted ray)\n    got      false\n"
                     "    likely mistake: total internal reflection only when |S_t|^2 > 1, with S_t = (eta_i / eta_t) "
                     "S_i; an upside-down ratio, or a test on |S_i|, reports it here",
                     input);
        double theta_t = asin(eta_i * sin(theta_i) / eta_t); /* the law, in double */
        vec3 expected = vec3_add(vec3_scale(t, (real)sin(theta_t)), vec3_scale(n, (real)-cos(theta_t)));
        if (k < 8) { /* the first few with the likely mistakes named */
            double inverted = asin(fmin(1, eta_t * sin(theta_i) / eta_i));
            /* T = r d + (r cos(theta_i) - cos(theta_t)) n with one of its parts wrong */
            double r = eta_i / eta_t, c_i = cos(theta_i), c_t = cos(theta_t);
            double c_t_r = sqrt(fmax(0, (1 - r) + r * c_i * c_i)); /* cos^2(theta_t) with r for r^2 */
            const suspect_vec3 sT[] = {
                {vec3_add(vec3_scale(t, (real)sin(inverted)), vec3_scale(n, (real)-cos(inverted))),
                 "S_t = (eta_t / eta_i) S_i: the ratio is upside down (eta_i sin(theta_i) = eta_t sin(theta_t))"},
                {vec3_add(vec3_scale(t, (real)sin(theta_t)), vec3_scale(n, (real)cos(theta_t))),
                 "C_t = +cos(theta_t) n: the transmitted ray goes on to the far side, against n"},
                {d, "T = d: Snell's law bends the ray"},
                {vec3_add(d, vec3_scale(n, (real)(eta_i / eta_t * cos(theta_i) - cos(theta_t)))),
                 "d not scaled by r: S_t = r S_i, so T = r d + (r cos(theta_i) - cos(theta_t)) n"},
                {bent(d, n, r, -r * c_i - c_t),
                 "cos(theta_i) = d . n has the wrong sign: d points into the surface, so cos(theta_i) = -d . n"},
                {bent(d, n, r, r * c_i - c_t * c_t), "cos(theta_t) = sqrt(cos^2(theta_t)): the square root left out"},
                {bent(d, n, r, r * c_i - c_t_r), "cos^2(theta_t) = (1 - r^2) + r^2 cos^2(theta_i): r^2, not r"},
                {bent(d, n, r, c_i - c_t),
                 "n's coefficient without r: S_t = r (d + cos(theta_i) n), so T = r d + (r cos(theta_i) - "
                 "cos(theta_t)) n"},
                {bent(d, n, r, r * c_i - c_i),
                 "cos(theta_t) taken as cos(theta_i): cos^2(theta_t) = (1 - r^2) + r^2 cos^2(theta_i)"},
            };
            assert_vec3_why(expected, T, TOL(8), input,
                            "S_t = (eta_i / eta_t) S_i, C_t = -cos(theta_t) n, T = C_t + S_t", sT,
                            sizeof sT / sizeof sT[0]);
        }
        assert_close(1, vec3_length(T), TOL(2));
        const suspect sc[] = {
            {cos(theta_i), "*cos_t = cos(theta_i): it is the transmitted ray's cosine, sqrt(1 - |S_t|^2)"},
            {-cos(theta_t), "*cos_t is the cosine of theta_t, positive, not T . n"},
        };
        assert_close_why(cos(theta_t), cos_t, TOL(8), describe("%s: cos_t", input),
                         "*cos_t = cos(theta_t) = sqrt(1 - |S_t|^2)", sc, sizeof sc / sizeof sc[0]);
        assert_close(-cos(theta_t), vec3_dot(T, n), TOL(8)); /* on the far side */
        assert_close(sin(theta_t), vec3_dot(T, t), TOL(8));  /* bent in the plane of d and n */
        assert_close(0, vec3_dot(T, vec3_cross(n, t)), TOL(4));
    }
}

/* The shading point of a ray d meeting a glass surface whose outward
 * geometric normal is n_out. */
static shading_point glass_point(vec3 d, vec3 n_out)
{
    shading_point sp = {.r = {{0, 0, 0}, d}};
    sp.hit.normal = n_out;
    sp.hit.point = vec3_make(0, 0, 0);
    sp.v = vec3_neg(vec3_normalize(d));
    sp.n = normal_towards_viewer(n_out, d);
    return sp;
}

/* glass_at's input k ulps of the sine from the critical angle out of glass, for a message. */
static const char *critical_input(int k, int mode)
{
    return describe("glass_at, out of glass (1.5 into 1), sin(theta_i) = 1/1.5 %+d ulps, --fresnel=%s", k,
                    fresnel_mode_names[mode]);
}

/* The critical angle out of glass (eta 1.5), theta_c = asin(1 / 1.5): a
 * direction whose sine is 1/1.5 give or take 64 ulps of it.  Below it the
 * light is transmitted (almost along the surface) and R is nearly 1, past
 * it refract() says no and R = 1; never a NaN.  Well below (0.999 theta_c) it
 * transmits, well past (1.001 theta_c) it does not. */
static void test_critical_angle(void **state)
{
    (void)state;
    vec3 n_out = vec3_normalize(vec3_make(2, -3, 6)); /* the glass's outward normal */
    vec3 n = vec3_neg(n_out);                          /* on the incoming (inner) side */
    vec3 t = tangent_of(n);
    real s_c = (real)1 / (real)1.5;
    int transmitted = 0, reflected = 0;
    for (int k = -64; k <= 64; k++) {
        real s = s_c + (real)k * REAL_EPSILON * s_c;
        vec3 d = vec3_add(vec3_scale(t, s), vec3_scale(n, -real_sqrt(1 - s * s)));
        for (int mode = 0; mode < 2; mode++) {
            shading_point sp = glass_point(d, n_out);
            glass_event e = glass_at(&sp, (real)1.5, (fresnel_mode)mode);
            assert_close(1.5, e.eta_i, 0); /* leaving the glass */
            assert_close(1, e.eta_t, 0);
            if (!(isfinite(e.R) && e.R >= 0 && e.R <= 1))
                fail_msg("glass_at, out of glass (1.5 into 1), sin(theta_i) = 1/1.5 %+d ulps, --fresnel=%s: R\n"
                         "    expected a number in [0, 1]\n    got      %.17g\n    likely mistake: %s",
                         k, fresnel_mode_names[mode], (double)e.R,
                         mode == FRESNEL_SCHLICK && e.R > 1
                             ? "Schlick's R above 1: R = R_0 + (1 - R_0) (1 - cos)^5, the factor 1 - R_0 keeps it "
                               "at most 1"
                             : "the total internal reflection test is |S_t|^2 > 1 on the refracted sine; past it "
                               "sqrt(1 - |S_t|^2) is NaN");
            if (e.transmits) {
                /* 64 ulps below theta_c, sin^2(theta_t) is 1 less about 2 x 1.5 x 64 ulps: cos_t is
                 * at most sqrt(1024 REAL_EPSILON), and R falls from 1 by a few times cos_t */
                real near = real_sqrt(1024 * REAL_EPSILON);
                assert_true_why(
                    vec3_is_finite(e.T) && isfinite(e.cos_t),
                    "%s, transmitted: T and cos_t\n    expected finite\n    got      T = (%g, %g, %g), cos_t = "
                    "%g\n    likely mistake: the test |S_t|^2 > 1 (cos^2(theta_t) < 0) made before the square "
                    "root returns false past the critical angle; another test lets sqrt(1 - |S_t|^2) of a "
                    "negative number through (README, \"Total internal reflection\")",
                    critical_input(k, mode), (double)e.T.x, (double)e.T.y, (double)e.T.z, (double)e.cos_t);
                assert_true_why(
                    e.cos_t >= 0 && e.cos_t < near,
                    "%s, transmitted: cos_t\n    expected 0 <= cos_t < %.3g (T runs almost along the surface)\n"
                    "    got      %.17g\n    likely mistake: %s",
                    critical_input(k, mode), (double)near, (double)e.cos_t,
                    e.cos_t < 0 ? "*cos_t is cos(theta_t) = sqrt(cos^2(theta_t)), positive, not T . n"
                                : "cos^2(theta_t) = (1 - r^2) + r^2 cos^2(theta_i) with r = eta_i / eta_t = 1.5 "
                                  "here is 0 at the critical angle: an upside-down ratio, or cos(theta_t) "
                                  "taken as cos(theta_i), stays far from 0");
                assert_close(1, vec3_length(e.T), TOL(2));
                /* R is continuous: it reaches 1 at theta_c */
                expect_R_above(e.R, 1 - 8 * near, describe("%s, transmitted: R", critical_input(k, mode)),
                               mode == FRESNEL_SCHLICK ? schlick_at_critical : exact_at_critical);
                transmitted++;
            } else {
                assert_close(1, e.R, 0);
                reflected++;
            }
        }
    }
    assert_true_why(
        transmitted > 0 && reflected > 0,
        "glass_at, out of glass (1.5 into 1), sin(theta_i) = 1/1.5 from -64 to +64 ulps, both --fresnel modes\n"
        "    expected some directions transmitted (below theta_c) and some totally reflected (past it)\n"
        "    got      %d transmitted, %d totally reflected\n    likely mistake: %s",
        transmitted, reflected,
        reflected == 0 ? "past the critical angle refract returns false (|S_t|^2 > 1, cos^2(theta_t) < 0), "
                         "whatever the rounding: a negative cos^2(theta_t) clamped to 0 transmits along the "
                         "surface instead"
                       : "refract reports total internal reflection below the critical angle: the test is "
                         "exactly |S_t|^2 > 1, cos^2(theta_t) = (1 - r^2) + r^2 cos^2(theta_i) < 0; a margin "
                         "in it, or >= 1, stops too early");
    double theta_c = asin(1 / 1.5);
    vec3 T;
    real cos_t;
    if (!refract(incoming(n, t, 0.999 * theta_c), n, (real)1.5, 1, &T, &cos_t))
        fail_msg("refract out of glass (1.5 into 1) at 0.999 theta_c\n    expected true (transmitted)\n"
                 "    got      false\n    likely mistake: %s",
                 tir);
    /* refract.h: under total internal reflection *T and *cos_t are left as they were */
    T = vec3_make(-7, -7, -7);
    cos_t = -7;
    if (refract(incoming(n, t, 1.001 * theta_c), n, (real)1.5, 1, &T, &cos_t))
        fail_msg("refract out of glass (1.5 into 1) at 1.001 theta_c\n    expected false (total internal "
                 "reflection)\n    got      true\n    likely mistake: %s",
                 tir);
    if (!(T.x == -7 && T.y == -7 && T.z == -7 && cos_t == -7))
        fail_msg("refract out of glass (1.5 into 1) at 1.001 theta_c: total internal reflection\n    expected *T "
                 "and *cos_t untouched (-7)\n    got      *T = (%g, %g, %g), *cos_t = %g\n    likely mistake: "
                 "*T or *cos_t written before the test |S_t|^2 > 1: return false first, write them only on "
                 "the way out of a transmission",
                 (double)T.x, (double)T.y, (double)T.z, (double)cos_t);
    /* into glass there is no critical angle: 89.9 degrees still transmits */
    expect_transmits(incoming(n_out, tangent_of(n_out), 89.9 * pi / 180), n_out, 1, (real)1.5,
                     "into glass at 89.9 degrees",
                     "into glass there is no critical angle: r = eta_i / eta_t is below 1, so |S_t| < |S_i| <= 1; an "
                     "upside-down ratio (eta_t / eta_i) reports total internal reflection here",
                     &T, &cos_t);
    /* Out of other media into air, refract itself 512 ulps of cos(theta_i) either side of the critical
     * cosine sqrt(1 - 1 / r^2): a transmission has a finite T and cos_t >= 0, whatever the rounding (the
     * test is made on the cos^2(theta_t) that goes into the square root, not on another expression of it) */
    const real etas[] = {(real)1.4, (real)1.33, (real)1.7, (real)2.42, (real)1.1};
    const vec3 up = {0, 0, 1};
    for (size_t j = 0; j < sizeof etas / sizeof etas[0]; j++) {
        const real c_c = real_sqrt(1 - 1 / (etas[j] * etas[j]));
        for (int k = -512; k <= 512; k++) {
            const real c = c_c + (real)k * REAL_EPSILON * c_c;
            const vec3 d = {real_sqrt(1 - c * c), 0, -c};
            T = vec3_make(-7, -7, -7);
            cos_t = -7;
            if (refract(d, up, etas[j], 1, &T, &cos_t) && !(vec3_is_finite(T) && cos_t >= 0))
                fail_msg("refract(d = (%.17g, 0, %.17g), n = (0, 0, 1), eta_i = %g, eta_t = 1), cos(theta_i) %+d "
                         "ulps from the critical cosine\n    expected false, or true with T finite and cos_t >= 0\n"
                         "    got      true, T = (%g, %g, %g), cos_t = %g\n    likely mistake: the total internal "
                         "reflection test made on another expression than the cos^2(theta_t) = (1 - r^2) + r^2 "
                         "cos^2(theta_i) whose square root is taken: rounded differently, it lets a negative one "
                         "through (README, \"Total internal reflection\")",
                         (double)d.x, (double)d.z, (double)etas[j], k, (double)T.x, (double)T.y, (double)T.z,
                         (double)cos_t);
        }
    }
}

/* ---- Fresnel -------------------------------------------------------------------------------- */

/* Head on, glass of index 1.5 reflects ((1.5 - 1) / (1.5 + 1))^2 = 0.04
 * either way, by Fresnel's equations and by Schlick's. */
static void test_fresnel_normal_incidence(void **state)
{
    (void)state;
    const suspect s0[] = {
        {0.08, "r_s^2 + r_p^2 is twice R: unpolarised light is the average of the two, (r_s^2 + r_p^2) / 2"},
        {-0.2, "r_s is an amplitude: R is its square"},
        {0.2, "r_s is an amplitude: R is its square"},
        {0.0, "R = 0 head on: r_s = (eta_i cos_i - eta_t cos_t) / (eta_i cos_i + eta_t cos_t)"},
        {0.0, "the amplitudes averaged (or not squared): head on r_p = -r_s, so (r_s + r_p) / 2 is 0; R averages "
              "the squares, (r_s^2 + r_p^2) / 2"},
    };
    assert_close_why(0.04, fresnel_exact(1, 1, 1, (real)1.5), TOL(1), "fresnel_exact(cos_i = 1, cos_t = 1, 1, 1.5)",
                     "R = (r_s^2 + r_p^2) / 2 = ((1 - 1.5) / (1 + 1.5))^2 head on", s0, sizeof s0 / sizeof s0[0]);
    assert_close(0.04, fresnel_exact(1, 1, (real)1.5, 1), TOL(1));
    const suspect s0_schlick[] = {
        {1, "cos^5: the power is of 1 - cos, which is 0 head on, so that R = R_0"},
        {1 / 9.0, "r = (eta_i - eta_t) / eta_t: the sum eta_i + eta_t goes below"},
    };
    assert_close_why(0.04, fresnel_schlick(1, 1, 1, (real)1.5), TOL(1), "fresnel_schlick(cos_i = 1, cos_t = 1, 1, 1.5)",
                     "R = R_0 = ((1 - 1.5) / (1 + 1.5))^2 head on", s0_schlick,
                     sizeof s0_schlick / sizeof s0_schlick[0]);
    assert_close(0.04, fresnel_schlick(1, 1, (real)1.5, 1), TOL(1));
    /* water: (0.33 / 2.33)^2 */
    assert_close(0.33 * 0.33 / (2.33 * 2.33), fresnel_exact(1, 1, (real)1.33, 1), TOL(1));
    /* water into glass and back, neither side air: R_0 = ((eta_i - eta_t) / (eta_i + eta_t))^2 =
     * (0.17 / 2.83)^2, about 0.0036, not the 0.04 of glass against air.  Expected in double from
     * the indices as the function gets them ((real)1.33 is inexact); eta_i - eta_t is then exact
     * (the two are within a factor 2), and the rest is a handful of roundings, each relative to R:
     * below 0.02 REAL_EPSILON in all.  TOL(0.01) = 0.32 REAL_EPSILON, far below the 0.036 that a
     * mistaken R_0 is off by */
    const double eta_w = (real)1.33, R_wg = (eta_w - 1.5) / (eta_w + 1.5) * ((eta_w - 1.5) / (eta_w + 1.5));
    const suspect s_wg[] = {
        {0.04, "R_0 from the glass's index against air, ((1.5 - 1) / (1.5 + 1))^2: both indices enter, "
               "R_0 = ((eta_i - eta_t) / (eta_i + eta_t))^2"},
        {0.33 * 0.33 / (2.33 * 2.33), "R_0 from the water's index against air, ((1.33 - 1) / (1.33 + 1))^2: both "
                                      "indices enter, R_0 = ((eta_i - eta_t) / (eta_i + eta_t))^2"},
    };
    assert_close_why(R_wg, fresnel_schlick(1, 1, (real)1.33, (real)1.5), TOL(0.01),
                     "fresnel_schlick(cos_i = 1, cos_t = 1, 1.33, 1.5)",
                     "R = R_0 = ((eta_i - eta_t) / (eta_i + eta_t))^2 head on", s_wg, sizeof s_wg / sizeof s_wg[0]);
    assert_close_why(R_wg, fresnel_schlick(1, 1, (real)1.5, (real)1.33), TOL(0.01),
                     "fresnel_schlick(cos_i = 1, cos_t = 1, 1.5, 1.33)",
                     "R = R_0 = ((eta_i - eta_t) / (eta_i + eta_t))^2 head on", s_wg, sizeof s_wg / sizeof s_wg[0]);
    assert_close_why(R_wg, fresnel_exact(1, 1, (real)1.33, (real)1.5), TOL(0.01),
                     "fresnel_exact(cos_i = 1, cos_t = 1, 1.33, 1.5)",
                     "R = (r_s^2 + r_p^2) / 2 = ((eta_i - eta_t) / (eta_i + eta_t))^2 head on", s_wg,
                     sizeof s_wg / sizeof s_wg[0]);
}

/* Fresnel's equations against their sine-and-tangent form, computed in
 * double from the angles: r_s = -sin(i - t) / sin(i + t), r_p = tan(i - t) /
 * tan(i + t); and Brewster's angle atan(eta_t / eta_i), where r_p = 0. */
static void test_fresnel_exact_values(void **state)
{
    (void)state;
    const double etas[][2] = {{1, 1.5}, {1.5, 1}, {1, 1.33}};
    for (int e = 0; e < 3; e++) {
        double eta_i = etas[e][0], eta_t = etas[e][1];
        double limit = eta_i > eta_t ? asin(eta_t / eta_i) : pi / 2;
        for (int k = 1; k < 20; k++) {
            double i = limit * k / 20.5, t = asin(eta_i * sin(i) / eta_t);
            double r_s = -sin(i - t) / sin(i + t), r_p = tan(i - t) / tan(i + t);
            double R = (r_s * r_s + r_p * r_p) / 2;
            double r_p_wrong = (eta_i * cos(i) - eta_t * cos(t)) / (eta_i * cos(i) + eta_t * cos(t));
            double r_p_swapped = (eta_t * cos(t) - eta_i * cos(i)) / (eta_t * cos(t) + eta_i * cos(i));
            const suspect sR[] = {
                {r_s * r_s, "only r_s: R averages the two polarisations, (r_s^2 + r_p^2) / 2"},
                {r_p * r_p, "only r_p: R averages the two polarisations, (r_s^2 + r_p^2) / 2"},
                {r_s * r_s + r_p * r_p, "r_s^2 + r_p^2 without the / 2"},
                {(r_s * r_s + r_p_wrong * r_p_wrong) / 2, "r_p written like r_s: in r_p eta_t goes with cos_i"},
                {(r_s * r_s + r_p_swapped * r_p_swapped) / 2, "r_p with the cosines swapped"},
                {(r_s + r_p) / 2 * ((r_s + r_p) / 2), "the amplitudes averaged, then squared: R averages the squares, "
                                                      "(r_s^2 + r_p^2) / 2"},
                {(r_s + r_p) / 2, "r_s and r_p not squared: they are amplitudes, R = (r_s^2 + r_p^2) / 2"},
            };
            assert_close_why(R, fresnel_exact((real)cos(i), (real)cos(t), (real)eta_i, (real)eta_t), TOL(4),
                             describe("fresnel_exact at theta_i = %.1f degrees from eta %g into %g", i * 180 / pi,
                                      eta_i, eta_t),
                             "r_s = (eta_i cos_i - eta_t cos_t) / (...), r_p = (eta_t cos_i - eta_i cos_t) / (...)", sR,
                             sizeof sR / sizeof sR[0]);
        }
        double brewster = atan(eta_t / eta_i), t = asin(eta_i * sin(brewster) / eta_t);
        double r_s = (eta_i * cos(brewster) - eta_t * cos(t)) / (eta_i * cos(brewster) + eta_t * cos(t));
        assert_close(r_s * r_s / 2, fresnel_exact((real)cos(brewster), (real)cos(t), (real)eta_i, (real)eta_t),
                     TOL(4));
    }
    /* grazing into glass: everything is reflected */
    assert_close(1, fresnel_exact(0, (real)sqrt(1 - 1 / 2.25), 1, (real)1.5), TOL(1));
}

/* R + T = 1: the transmitted fraction computed on its own, from Fresnel's
 * transmission amplitudes and the change of beam width and speed,
 * T = (eta_t cos_t) / (eta_i cos_i) (t_s^2 + t_p^2) / 2, adds up with R to 1
 * at every angle, both ways. */
static void test_r_plus_t(void **state)
{
    (void)state;
    const real etas[][2] = {{1, 1.5}, {1.5, 1}};
    int checked = 0;
    for (int e = 0; e < 2; e++) {
        real eta_i = etas[e][0], eta_t = etas[e][1];
        vec3 n = suite_random_unit(&rng), tan_ = tangent_of(n);
        for (int k = 0; k < 89; k++) {
            vec3 d = incoming(n, tan_, k * pi / 180), T;
            real cos_t, cos_i = -vec3_dot(d, n);
            if (!refract(d, n, eta_i, eta_t, &T, &cos_t))
                continue; /* past the critical angle: R = 1, T = 0 */
            real R = fresnel_exact(cos_i, cos_t, eta_i, eta_t);
            real t_s = 2 * eta_i * cos_i / (eta_i * cos_i + eta_t * cos_t);
            real t_p = 2 * eta_i * cos_i / (eta_t * cos_i + eta_i * cos_t);
            real transmitted = eta_t * cos_t / (eta_i * cos_i) * (t_s * t_s + t_p * t_p) / 2;
            if (!isfinite(R) || !isfinite(transmitted))
                fail_msg("refract and fresnel_exact at theta_i = %d degrees from eta %g into %g\n"
                         "    expected finite R and cos_t\n    got      R = %g, cos_t = %g\n"
                         "    likely mistake: refract transmitted past the critical angle (the test is |S_t|^2 > 1)",
                         k, (double)eta_i, (double)eta_t, (double)R, (double)cos_t);
            const suspect sr[] = {{1 + R, "R is twice too large: (r_s^2 + r_p^2) / 2"}};
            assert_close_why(1, R + transmitted, TOL(8),
                             describe("fresnel_exact at theta_i = %d degrees from eta %g into %g: R + the transmitted "
                                      "fraction",
                                      k, (double)eta_i, (double)eta_t),
                             "energy is conserved: R + T = 1 (r_s, r_p and their average as the lecture's)", sr, 1);
            assert_true_why(R >= 0 && R <= 1,
                            "fresnel_exact at theta_i = %d degrees from eta %g into %g (cos_i = %.9g, cos_t = %.9g)\n"
                            "    expected R in [0, 1]\n    got      %.17g\n    likely mistake: %s",
                            k, (double)eta_i, (double)eta_t, (double)cos_i, (double)cos_t, (double)R,
                            R > 1 ? "r_s^2 + r_p^2 without the / 2: unpolarised light is their average, R = (r_s^2 + "
                                    "r_p^2) / 2"
                                  : "r_s and r_p not squared: they are amplitudes, R = (r_s^2 + r_p^2) / 2");
            checked++;
        }
    }
    assert_int_equal(89 + 42, checked); /* into glass 0-88 degrees, out of it 0-41 (theta_c = 41.8) */
}

/* Schlick's approximation: into glass it is the polynomial in cos_i, out of
 * glass in cos_t, so that it reaches 1 at the critical angle as Fresnel's
 * does (in cos_i it would be about 0.04 there, then jump to 1). */
static void test_schlick_cosines(void **state)
{
    (void)state;
    real R_0 = (real)0.04;
    real c = (real)0.6, c_t = (real)0.3;
    /* (eta_i - eta_t) / (eta_i + eta_t) = -0.2 into glass, R_0 its square */
    const suspect s_in[] = {
        {R_0 + (1 - R_0) * pow(1 - 0.3, 5), "into glass the cosine is cos_i, the incoming side's"},
        {R_0 + (1 - R_0) * pow(1 - 0.6, 4), "(1 - cos)^4: Schlick's power is 5"},
        {0.2 + (1 - 0.2) * pow(1 - 0.6, 5), "R_0 not squared: R_0 = ((eta_i - eta_t) / (eta_i + eta_t))^2"},
        {-0.2 + (1 + 0.2) * pow(1 - 0.6, 5), "R_0 not squared: R_0 = ((eta_i - eta_t) / (eta_i + eta_t))^2"},
        {R_0 + pow(1 - 0.6, 5), "(1 - R_0) missing: R = R_0 + (1 - R_0) (1 - cos)^5 reaches 1 at grazing"},
        {R_0 + (1 - R_0) * pow(0.6, 5), "cos^5: the power is of 1 - cos, so that R = R_0 head on"},
        {1 / 9.0 + 8 / 9.0 * pow(1 - 0.6, 5), "r = (eta_i - eta_t) / eta_t: the sum eta_i + eta_t goes below"},
    };
    assert_close_why(R_0 + (1 - R_0) * pow(1 - 0.6, 5), fresnel_schlick(c, c_t, 1, (real)1.5), TOL(1),
                     "fresnel_schlick(cos_i = 0.6, cos_t = 0.3, 1, 1.5)", "R = R_0 + (1 - R_0) (1 - cos)^5", s_in,
                     sizeof s_in / sizeof s_in[0]);
    const suspect s_out[] = {
        {R_0 + (1 - R_0) * pow(1 - 0.6, 5), "out of glass the cosine is cos_t (the side of the smaller index), "
                                             "or R jumps at the critical angle"}};
    assert_close_why(R_0 + (1 - R_0) * pow(1 - 0.3, 5), fresnel_schlick(c, c_t, (real)1.5, 1), TOL(1),
                     "fresnel_schlick(cos_i = 0.6, cos_t = 0.3, 1.5, 1)", "R = R_0 + (1 - R_0) (1 - cos_t)^5", s_out,
                     1);
    /* just below the critical angle on the way out */
    vec3 n = vec3_make(0, 0, 1), t = vec3_make(1, 0, 0), T;
    real cos_t;
    vec3 d = incoming(n, t, 0.9999 * asin(1 / 1.5));
    expect_transmits(d, n, (real)1.5, 1, "out of glass at 0.9999 theta_c", tir, &T, &cos_t);
    real cos_i = -vec3_dot(d, n);
    expect_R_above(fresnel_schlick(cos_i, cos_t, (real)1.5, 1), (real)0.9,
                   describe("fresnel_schlick(cos_i = %.9g, cos_t = %.9g, 1.5, 1), out of glass at 0.9999 theta_c",
                            (double)cos_i, (double)cos_t),
                   schlick_at_critical);
    expect_R_above(fresnel_exact(cos_i, cos_t, (real)1.5, 1), (real)0.9,
                   describe("fresnel_exact(cos_i = %.9g, cos_t = %.9g, 1.5, 1), out of glass at 0.9999 theta_c",
                            (double)cos_i, (double)cos_t),
                   exact_at_critical);
    /* no surface at all: nothing is reflected, whatever the mode */
    assert_close(0, fresnel(FRESNEL_SCHLICK, (real)0.3, (real)0.3, (real)1.2, (real)1.2), 0);
    assert_close(0, fresnel(FRESNEL_EXACT, (real)0.3, (real)0.3, (real)1.2, (real)1.2), 0);
}

/* ---- glass in a scene ----------------------------------------------------------------------- */

/* The probe (probe_shader.h) is white; every other shader is glass. */
static color probe_shade(const tracer *tr, const shading_point *sp, int depth, uint64_t *rays)
{
    if (probe_took(tr, sp, depth))
        return color_make(1, 1, 1);
    return shade_glass(tr, sp, depth, rays);
}

static glass_knobs knobs_of(int depth, real min_weight)
{
    return (glass_knobs){.path = {.phong = PHONG_KNOBS_DEFAULT, .depth = depth, .min_weight = min_weight},
                         .fresnel = FRESNEL_EXACT};
}

/* The tracer's knobs aimed at *k, as chapter 09's renderer aims them. */
static stage_knobs aimed_at(const glass_knobs *k)
{
    const path_knobs *path = &k->path;
    return (stage_knobs){.spawn = &path->phong.spawn, .phong = &path->phong, .path = path, .glass = k};
}

static color trace_one(const scene *desc, const glass_knobs *knobs, ray r, uint64_t *rays)
{
    const stage_knobs aimed = aimed_at(knobs);
    return probe_trace(desc, probe_shade, &aimed, r, rays);
}

static int add_glass(scene *desc, real eta)
{
    scene_shader s = scene_default_shader(SHADER_GLASS);
    s.refractive_index = eta;
    return scene_add_shader(desc, s);
}

/* A probe: a big triangle through `centre`, facing -`along`. */
static void add_probe(scene *desc, vec3 centre, vec3 along)
{
    probe_shader = scene_add_shader(desc, scene_default_shader(SHADER_LAMBERTIAN));
    vec3 a = tangent_of(along), b = vec3_cross(along, a);
    vec3 v0 = vec3_add(centre, vec3_scale(a, 100));
    vec3 v1 = vec3_add(centre, vec3_add(vec3_scale(a, -50), vec3_scale(b, 87)));
    vec3 v2 = vec3_add(centre, vec3_add(vec3_scale(a, -50), vec3_scale(b, -87)));
    scene_add_surface(desc,
                      (scene_surface){.kind = SURFACE_TRIANGLE, .shader = probe_shader, .v0 = v0, .v1 = v1, .v2 = v2});
}

/* The ray that reached the probe at depth 2 (in, out, probe): the only one
 * with --depth 2, since every other path turns back or stays inside. */
static ray probe_ray_at_depth_2(void)
{
    int found = -1;
    for (int k = 0; k < probe.n && k < MAX_PROBES; k++)
        if (probe.depth[k] == 2) {
            assert_int_equal(-1, found);
            found = k;
        }
    assert_true_why(
        found >= 0,
        "the probe behind the glass, --depth 2\n    expected a ray reaching it at depth 2 (into the glass, out "
        "of it, to the probe)\n    got      none\n    likely mistake: the transmitted ray not traced (its weight "
        "1 - R is above 0 here), or depth + 1 given to transmitted_radiance or mirror_radiance: each traces one "
        "level deeper itself (README, \"The glass shader\"); or refract's T turned back to the incoming side: "
        "T = r d + (r cos(theta_i) - cos(theta_t)) n (test_snell_law names refract's mistakes)");
    return probe.r[found];
}

/* A ray through the centre of a glass sphere (far from the origin) meets
 * both surfaces head on and leaves undeviated, on the same line; a ray off
 * the centre is bent, and crosses the axis behind the sphere. */
static void test_sphere_centre_undeviated(void **state)
{
    (void)state;
    const vec3 c = {-41.5, 23.25, 60.75};
    const real radius = 2;
    vec3 along = vec3_normalize(vec3_make(1, -2, 3));
    scene desc;
    scene_init(&desc);
    int glass = add_glass(&desc, (real)1.5);
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = glass, .center = c, .radius = radius});
    add_probe(&desc, vec3_add(c, vec3_scale(along, 10)), along);
    glass_knobs knobs = knobs_of(2, 0);
    vec3 eye = vec3_sub(c, vec3_scale(along, 9));
    uint64_t rays[RAY_KINDS] = {0};
    trace_one(&desc, &knobs, (ray){eye, vec3_scale(along, 3)}, rays);
    ray out = probe_ray_at_depth_2();
    /* the same direction, and the line through the centre: the points far
     * from the origin (|c| ~ 80) are rounded to about 80 REAL_EPSILON, and
     * the offsets of spawn_ray are 32 ulps of that, in and out; 10 away from
     * the exit point, a direction error of TOL(4) adds TOL(40) */
    assert_close(0, vec3_length(vec3_cross(vec3_normalize(out.d), along)), TOL(4));
    assert_true_why(
        vec3_dot(out.d, along) > 0,
        "a ray through the centre of a glass sphere of index 1.5, along d = (%.9g, %.9g, %.9g), leaving it\n"
        "    expected it to go on along d (out.d . d > 0)\n    got      out.d = (%.9g, %.9g, %.9g)\n"
        "    likely mistake: C_t = +cos(theta_t) n turns a head-on ray back: the transmitted ray goes on to the "
        "far side, T = r d + (r cos(theta_i) - cos(theta_t)) n",
        (double)along.x, (double)along.y, (double)along.z, (double)out.d.x, (double)out.d.y, (double)out.d.z);
    vec3 to_c = vec3_sub(c, out.p);
    assert_close(0, vec3_length(vec3_cross(to_c, vec3_normalize(out.d))), TOL(200));
    assert_int_equal(2, rays[RAY_REFRACTED]); /* in, out */
    assert_int_equal(2, rays[RAY_REFLECTED]); /* off the front, and inside off the back */

    /* off the centre by half the radius: bent towards the axis */
    vec3 side = tangent_of(along);
    trace_one(&desc, &knobs, (ray){vec3_add(eye, side), vec3_scale(along, 3)}, rays);
    ray bent = probe_ray_at_depth_2();
    real sideways = vec3_dot(vec3_normalize(bent.d), side);
    if (!(sideways < (real)-0.1)) /* a lens: the ray crosses the axis */
        fail_msg("a ray half a radius off the centre of a glass sphere of index 1.5, leaving it\n"
                 "    expected bent towards the axis (a sideways component below -0.1)\n    got      %g\n"
                 "    likely mistake: the transmitted ray cast along d, not bent: cast it along e.T, the direction "
                 "glass_at refracted",
                 (double)sideways);
    scene_free(&desc);
}

/* A slab with parallel faces (a glass box, far from the origin) returns the
 * entry direction, shifted sideways by h sin(theta_i - theta_t) / cos(theta_t)
 * for thickness h. */
static void test_slab_returns_entry_direction(void **state)
{
    (void)state;
    const vec3 lo = {30.5, -12.25, 17}, hi = {50.5, -11.75, 37}; /* h = 0.5 along y */
    scene desc;
    scene_init(&desc);
    int glass = add_glass(&desc, (real)1.5);
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_BOX, .shader = glass, .min_pt = lo, .max_pt = hi});
    add_probe(&desc, vec3_make(40, -15, 27), vec3_make(0, -1, 0));
    const double angles[] = {10, 40, 70};
    for (int k = 0; k < 3; k++) {
        double theta_i = angles[k] * pi / 180, theta_t = asin(sin(theta_i) / 1.5);
        vec3 d = vec3_normalize(vec3_make((real)(sin(theta_i) * 0.6), (real)-cos(theta_i), (real)(sin(theta_i) * 0.8)));
        vec3 entry = {39.25, -11.75, 26.5};
        glass_knobs knobs = knobs_of(2, 0);
        uint64_t rays[RAY_KINDS] = {0};
        trace_one(&desc, &knobs, (ray){vec3_sub(entry, vec3_scale(d, 3)), d}, rays);
        ray out = probe_ray_at_depth_2();
        assert_vec3_close(d, vec3_normalize(out.d), TOL(8));
        /* the shift: from the straight line through the entry point */
        real shift = vec3_length(vec3_cross(vec3_sub(out.p, entry), d));
        /* the points are ~50 from the origin: the hits and the offsets of
         * spawn_ray, in and out, are a few times 32 ulps of 50 */
        const suspect straight[] = {{0, "the transmitted ray cast along d, not bent: cast it along e.T, the "
                                          "direction glass_at refracted"}};
        assert_close_why(0.5 * sin(theta_i - theta_t) / cos(theta_t), shift, TOL(400),
                         describe("a ray through a glass slab 0.5 thick at %g degrees: its sideways shift", angles[k]),
                         "h sin(theta_i - theta_t) / cos(theta_t)", straight, 1);
    }
    scene_free(&desc);
}

/* Inside a glass block, a ray meets the top face below and past the
 * critical angle: below, one reflected and one refracted ray; past, the
 * reflected ray only (TIR), carrying everything. */
static void test_total_internal_reflection_rays(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    desc.back_color = color_make((real)0.25, (real)0.5, (real)0.75);
    int glass = add_glass(&desc, (real)1.5);
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_BOX, .shader = glass, .min_pt = {-10.5, -20, 3},
                                             .max_pt = {10.5, 2.25, 25}});
    vec3 n = {0, 1, 0}, t = {0.6, 0, 0.8};
    vec3 inside = {0.5, 1.25, 14};
    glass_knobs knobs = knobs_of(1, 0); /* the first event's rays only */
    double theta_c = asin(1 / 1.5) * 180 / pi;
    const double angles[] = {30, theta_c - 1, theta_c + 1, 60, 85};
    for (int k = 0; k < 5; k++) {
        vec3 d = incoming(vec3_neg(n), t, angles[k] * pi / 180); /* going up, at the angle from -n */
        uint64_t rays[RAY_KINDS] = {0};
        probe_shader = -1;
        color L = trace_one(&desc, &knobs, (ray){inside, d}, rays);
        bool tir = angles[k] > theta_c;
        assert_int_equal(1, rays[RAY_REFLECTED]);
        assert_int_equal(tir ? 0 : 1, rays[RAY_REFRACTED]);
        /* the refracted ray leaves to the backColor; the reflected one goes
         * down to the far side of the block and stops there (depth 1): black */
        if (tir)
            assert_close(0, L.g, 0);
        else
            assert_true_why(L.g > 0 && L.g < desc.back_color.g,
                            "shade_glass, a ray from inside a glass block at %.1f degrees (below the critical angle "
                            "%.1f), --depth 1, background %g: L.g\n    expected between 0 and the background ((1 - R) "
                            "B: the refracted ray leaves to the background, the reflected one brings black)\n"
                            "    got      %.17g\n    likely mistake: %s",
                            angles[k], theta_c, (double)desc.back_color.g, (double)L.g,
                            L.g > 0 ? "L_transmitted not multiplied by 1 - R: L = R L_reflected + (1 - R) "
                                      "L_transmitted"
                                    : "the refracted ray (it was cast) brought nothing: its L not added (L = R "
                                      "L_reflected + (1 - R) L_transmitted), or refract's T turned back into the "
                                      "glass: T = r d + (r cos(theta_i) - cos(theta_t)) n goes on to the far side "
                                      "(test_snell_law names refract's mistakes)");
    }
    scene_free(&desc);
}

/* The glass shader's weights, one event at a time (--depth 1: a ray it casts
 * that leaves the glass brings the background B, one that stays inside
 * brings black).  Head on into or out of glass of index 1.5, R = 0.04: from
 * outside L = R B (the reflected ray leaves, the transmitted one stays inside),
 * from inside L = (1 - R) B.  Each is R or 1 - R times B = 0.5 after a few
 * roundings of values of size 1: TOL(1).  Past the critical angle no
 * transmitted ray is cast; with --min-weight above both weights no ray at all
 * (path_next is given each ray's weight); with index 1 (R = 0) no reflected
 * ray. */
static void test_glass_weights(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    desc.back_color = color_make((real)0.25, (real)0.5, (real)0.75);
    const vec3 lo = {-10.5, -20, 3}, hi = {10.5, 2.25, 25};
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_BOX, .shader = add_glass(&desc, (real)1.5), .min_pt = lo,
                                             .max_pt = hi});
    probe_shader = -1;
    const double B = 0.5, R = 0.04;
    const vec3 outside = {0.5, 6.25, 14}, inside = {0.5, 1.25, 14}, down = {0, -1, 0}, up = {0, 1, 0};
    const struct {
        const char *where;
        vec3 from, d;
        double expected, swapped, unweighted;
        const char *unweighted_mistake, *missing_mistake;
    } cases[] = {
        {"a ray from outside, head on into glass of index 1.5 (R = 0.04, the transmitted ray stays inside)", outside,
         down, R * B, (1 - R) * B, B, "L_reflected not multiplied by R", "no reflected ray traced, or its L not added"},
        {"a ray from inside, head on out of glass of index 1.5 (R = 0.04, the reflected ray stays inside)", inside, up,
         (1 - R) * B, R * B, B, "L_transmitted not multiplied by 1 - R", "no transmitted ray traced, or its L not added"},
    };
    for (int k = 0; k < 2; k++) {
        glass_knobs knobs = knobs_of(1, 0);
        uint64_t rays[RAY_KINDS] = {0};
        color L = trace_one(&desc, &knobs, (ray){cases[k].from, cases[k].d}, rays);
        const suspect suspects[] = {
            {cases[k].swapped, "the weights R and 1 - R swapped"},
            {cases[k].unweighted, cases[k].unweighted_mistake},
            {0, cases[k].missing_mistake},
            {0, "depth + 1 given to mirror_radiance or transmitted_radiance: each traces one level deeper itself, "
                "give it depth (with --depth 1 path_next then refuses the ray)"},
        };
        assert_close_why(cases[k].expected, L.g, TOL(1),
                         describe("shade_glass, %s, background %g: L", cases[k].where, B),
                         "L = R L_reflected + (1 - R) L_transmitted (README, \"The glass shader\")", suspects,
                         sizeof suspects / sizeof suspects[0]);
        if (rays[RAY_REFLECTED] != 1 || rays[RAY_REFRACTED] != 1)
            fail_msg("shade_glass, %s\n    expected 1 reflected and 1 refracted ray\n    got      %d and %d\n"
                     "    likely mistake: a ray not traced though its weight (R or 1 - R) is above 0",
                     cases[k].where, (int)rays[RAY_REFLECTED], (int)rays[RAY_REFRACTED]);
    }
    /* A radiance has no upper bound: behind the glass a background of (2.5, 5, 7.5), B = 5 in green, gives
     * from outside L = R B = 0.2 and from inside L = (1 - R) B = 4.8, each R or 1 - R times B after a few
     * roundings of values of size 5: TOL(5).  Clamped to 1 on the way, the ray from inside brings 1 or 0.96. */
    desc.back_color = color_make((real)2.5, 5, (real)7.5);
    for (int k = 0; k < 2; k++) {
        glass_knobs knobs = knobs_of(1, 0);
        uint64_t rays[RAY_KINDS] = {0};
        color L = trace_one(&desc, &knobs, (ray){cases[k].from, cases[k].d}, rays);
        const suspect suspects[] = {{1, "L clamped to 1: a radiance is not clamped on the way, only the display "
                                        "clamps (README, \"The glass shader\")"},
                                    {(1 - R) * 1, "L_transmitted clamped to 1 before its weight: a radiance is not "
                                                  "clamped on the way, only the display clamps (README, \"The "
                                                  "glass shader\")"}};
        assert_close_why(cases[k].expected / B * 5, L.g, TOL(5),
                         describe("shade_glass, %s, background 5: L", cases[k].where),
                         "L = R L_reflected + (1 - R) L_transmitted, whatever their size (README, \"The glass "
                         "shader\")",
                         suspects, sizeof suspects / sizeof suspects[0]);
    }
    desc.back_color = color_make((real)0.25, (real)0.5, (real)0.75);
    /* past the critical angle (60 degrees from inside): the reflected ray only */
    glass_knobs knobs = knobs_of(1, 0);
    uint64_t rays[RAY_KINDS] = {0};
    trace_one(&desc, &knobs, (ray){inside, incoming(down, vec3_make((real)0.6, 0, (real)0.8), 60 * pi / 180)}, rays);
    if (rays[RAY_REFLECTED] != 1 || rays[RAY_REFRACTED] != 0)
        fail_msg("shade_glass, a ray from inside at 60 degrees, past the critical angle of 41.8\n"
                 "    expected 1 reflected ray and no refracted one\n    got      %d and %d\n"
                 "    likely mistake: %s",
                 (int)rays[RAY_REFLECTED], (int)rays[RAY_REFRACTED],
                 rays[RAY_REFRACTED] != 0 ? "a transmitted ray traced past the critical angle (glass_at says it does "
                                            "not transmit: R = 1)"
                                          : "the reflected ray not cast with R = 1: its coefficient is its weight R "
                                            "(mirror_radiance(tr, sp, R, ...)), not 1 - R, which is 0 here");
    /* --min-weight 0.97, above R = 0.04 and 1 - R = 0.96: neither ray is cast */
    knobs = knobs_of(1, (real)0.97);
    uint64_t cut[RAY_KINDS] = {0};
    trace_one(&desc, &knobs, (ray){outside, down}, cut);
    if (cut[RAY_REFLECTED] != 0 || cut[RAY_REFRACTED] != 0)
        fail_msg("shade_glass, a ray from outside, head on, at --min-weight 0.97\n"
                 "    expected no reflected and no refracted ray (weights 0.04 and 0.96)\n    got      %d and %d\n"
                 "    likely mistake: a ray traced with a coefficient other than its weight (R for the reflected "
                 "ray, 1 - R for the transmitted one: path_next compares the path's weight times it with "
                 "--min-weight)",
                 (int)cut[RAY_REFLECTED], (int)cut[RAY_REFRACTED]);
    scene_free(&desc);
    /* index 1: R = 0, no surface to reflect */
    scene_init(&desc);
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_BOX, .shader = add_glass(&desc, 1), .min_pt = lo,
                                             .max_pt = hi});
    probe_shader = -1;
    knobs = knobs_of(1, 0);
    uint64_t none[RAY_KINDS] = {0};
    trace_one(&desc, &knobs, (ray){outside, down}, none);
    if (none[RAY_REFLECTED] != 0 || none[RAY_REFRACTED] != 1)
        fail_msg("shade_glass, a ray from outside, head on into glass of index 1 (R = 0)\n"
                 "    expected no reflected ray and 1 refracted ray\n    got      %d and %d\n"
                 "    likely mistake: a reflected ray traced with R = 0 (it carries nothing)",
                 (int)none[RAY_REFLECTED], (int)none[RAY_REFRACTED]);
    scene_free(&desc);
    /* index 1.02: R = ((1.02 - 1) / (1.02 + 1))^2, about 1e-4, small but above 0, and --min-weight 0: both rays
     * are cast, and L = R B (the transmitted ray stays inside, as for index 1.5).  Which weights are too small
     * is --min-weight's to say (path_next), not a threshold of shade_glass's own. */
    scene_init(&desc);
    desc.back_color = color_make((real)0.25, (real)0.5, (real)0.75);
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_BOX, .shader = add_glass(&desc, (real)1.02), .min_pt = lo,
                                             .max_pt = hi});
    probe_shader = -1;
    knobs = knobs_of(1, 0);
    uint64_t low[RAY_KINDS] = {0};
    const color L_low = trace_one(&desc, &knobs, (ray){outside, down}, low);
    const double eta_low = (double)(real)1.02, R_low = pow((eta_low - 1) / (eta_low + 1), 2);
    if (low[RAY_REFLECTED] != 1 || low[RAY_REFRACTED] != 1)
        fail_msg("shade_glass, a ray from outside, head on into glass of index 1.02 (R = %.3g), at --min-weight 0\n"
                 "    expected 1 reflected and 1 refracted ray\n    got      %d and %d\n"
                 "    likely mistake: a ray skipped because its weight is small (a threshold of shade_glass's own): "
                 "every ray whose weight (R or 1 - R) is above 0 is traced, and path_next alone refuses the ones "
                 "below --min-weight",
                 R_low, (int)low[RAY_REFLECTED], (int)low[RAY_REFRACTED]);
    /* L = R B: R from the cosines 1 and cos(theta_t) = 1 up to a rounding, B exact: well within TOL(1) */
    assert_close_why(R_low * B, L_low.g, TOL(1),
                     describe("shade_glass, a ray from outside, head on into glass of index 1.02 (R = %.3g, the "
                              "transmitted ray stays inside), background %g, --min-weight 0: L",
                              R_low, B),
                     "L = R L_reflected + (1 - R) L_transmitted for every R above 0 (README, \"The glass shader\")",
                     NULL, 0);
    scene_free(&desc);
}

/* ---- whole images ---------------------------------------------------------------------------- */

static render_stats render_glass(const scene *desc, const glass_knobs *knobs, image *img, int w, int h)
{
    const stage_knobs aimed = aimed_at(knobs);
    return suite_render(desc, shade_glass, &aimed, img, w, h);
}

/* The furnace: a glass sphere (eta 1.5) in a uniform background, no lights:
 * nothing is absorbed, every path ends in the background, so at the default
 * depth every pixel is within 2/255 of it.  At depth 2 the rim, where light
 * bounces inside many times, is darker. */
/* The furnace: a glass sphere (eta 1.5) of radius 1 filling most of the view,
 * in a uniform background of `back` in every channel, no lights. */
static void furnace_scene(scene *desc, real back)
{
    scene_init(desc);
    desc->has_camera = true;
    desc->camera = (scene_camera){.kind = CAMERA_PERSPECTIVE, .view_point = {-20.5, 30.25, 14},
                                  .view_dir = {0, 0, -1}, .view_up = {0, 1, 0}, .proj_distance = 1,
                                  .view_width = (real)0.7, .view_height = (real)0.7};
    desc->back_color = color_make(back, back, back);
    scene_add_surface(desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = add_glass(desc, (real)1.5),
                                            .center = {-20.5, 30.25, 10}, .radius = 1});
}

static void test_furnace_glass_sphere(void **state)
{
    (void)state;
    scene desc;
    furnace_scene(&desc, (real)0.5);
    const int side = 128;
    glass_knobs knobs = knobs_of(PATH_DEFAULT_DEPTH, PATH_DEFAULT_MIN_WEIGHT);
    for (int mode = 0; mode < 2; mode++) {
        knobs.fresnel = mode;
        image img;
        render_stats stats = render_glass(&desc, &knobs, &img, side, side);
        int worst = suite_worst_byte(&img, (real)0.5);
        if (worst > 2)
            fail_msg("--fresnel=%s: a pixel %d/255 off the background", fresnel_mode_names[mode], worst);
        assert_true_why(
            stats.by_kind[RAY_REFRACTED] > (uint64_t)side * side / 4,
            "the glass furnace (a glass sphere of index 1.5 filling most of the view) at %dx%d, --fresnel=%s\n"
            "    expected more than %d refracted rays\n    got      %llu\n    likely mistake: %s",
            side, side, fresnel_mode_names[mode], side * side / 4, (unsigned long long)stats.by_kind[RAY_REFRACTED],
            no_transmitted);
        image_free(&img);
    }
    knobs = knobs_of(2, PATH_DEFAULT_MIN_WEIGHT);
    image img;
    render_glass(&desc, &knobs, &img, side, side);
    int worst = suite_worst_byte(&img, (real)0.5);
    assert_true_why(
        worst > 2,
        "the glass furnace at --depth 2, %dx%d\n    expected a pixel more than 2/255 off the background (a path "
        "that stays inside longer brings black at the depth's end)\n    got      at most %d/255 off\n"
        "    likely mistake: the rays traced at a depth other than the point's own: give mirror_radiance and "
        "transmitted_radiance depth as it is; each traces one level deeper, and path_next refuses a ray past "
        "--depth",
        side, side, worst);
    image_free(&img);
    scene_free(&desc);
}

/* The furnace against white, where the display shows the light the weight
 * cut-off drops in its top level (chapter 08's README, "The defaults,
 * measured": at 512x512, 212 pixels off by at most 2/255 at the default).
 * At 128x128 the default --min-weight leaves at most 2/255 (measured: 1 in
 * double, 0 in float, as with --min-weight=0, where the depth of 32 cuts), and
 * a tenfold cut (1e-2) shows: at least 3/255 off (measured 11 and 5). */
static void test_furnace_on_white(void **state)
{
    (void)state;
    scene desc;
    furnace_scene(&desc, 1);
    const int side = 128;
    const real weights[] = {PATH_DEFAULT_MIN_WEIGHT, (real)1e-2};
    const int at_most[] = {2, 255}, at_least[] = {0, 3};
    for (int k = 0; k < 2; k++) {
        glass_knobs knobs = knobs_of(PATH_DEFAULT_DEPTH, weights[k]);
        image img;
        render_glass(&desc, &knobs, &img, side, side);
        int worst = suite_worst_byte(&img, 1);
        if (worst > at_most[k] || worst < at_least[k])
            fail_msg("the glass furnace against white at --min-weight=%g: the worst pixel %d/255 off white\n"
                     "    expected %d to %d",
                     (double)weights[k], worst, at_least[k], at_most[k]);
        image_free(&img);
    }
    scene_free(&desc);
}

/* A glass sphere of index 1 in front of a lit scene changes nothing: at
 * least 99.9 % of the pixels are byte for byte those of the scene without
 * it.  (The light is placed so that the sphere casts no shadow in view:
 * shadow rays do not look through glass.) */
static void test_index_one_sphere_invisible(void **state)
{
    (void)state;
    scene desc;
    scene_init(&desc);
    desc.has_camera = true;
    desc.camera = (scene_camera){.kind = CAMERA_PERSPECTIVE, .view_point = {12.5, 3.25, 18}, .view_dir = {0, -0.2, -1},
                                 .view_up = {0, 1, 0}, .proj_distance = 1, .view_width = 1, .view_height = 1};
    desc.back_color = color_make((real)0.1, (real)0.15, (real)0.3);
    desc.ambient = color_make((real)0.02, (real)0.02, (real)0.02);
    scene_shader red = scene_default_shader(SHADER_PHONG);
    red.diffuse_color = color_make((real)0.3, (real)0.05, (real)0.05);
    red.exponent = 40;
    red.specular_color = color_make((real)0.5, (real)0.5, (real)0.5);
    scene_shader floor = scene_default_shader(SHADER_LAMBERTIAN);
    floor.diffuse_color = color_make((real)0.2, (real)0.2, (real)0.15);
    int s_red = scene_add_shader(&desc, red), s_floor = scene_add_shader(&desc, floor);
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_BOX, .shader = s_floor, .min_pt = {2.5, 0, -10},
                                             .max_pt = {22.5, 0.2, 10}});
    scene_add_surface(&desc,
                      (scene_surface){.kind = SURFACE_SPHERE, .shader = s_red, .center = {12, 1.2, 1}, .radius = 1});
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = s_red, .center = {14.5, 0.9, -1.5},
                                             .radius = 0.7});
    scene_add_light(&desc, (scene_light){.position = {16, 9, -6}, .intensity = {60, 60, 60}});
    glass_knobs knobs = knobs_of(PATH_DEFAULT_DEPTH, PATH_DEFAULT_MIN_WEIGHT);
    const int side = 128;
    image without, with;
    render_glass(&desc, &knobs, &without, side, side);
    /* the glass sphere between the eye and the scene, filling the middle of the view */
    scene_add_surface(&desc, (scene_surface){.kind = SURFACE_SPHERE, .shader = add_glass(&desc, 1),
                                             .center = {12.4, 2.4, 12}, .radius = (real)1.5});
    render_stats stats = render_glass(&desc, &knobs, &with, side, side);
    assert_true_why(stats.by_kind[RAY_REFRACTED] > (uint64_t)side * side / 8, /* it is in view */
                    "a glass sphere of index 1 (R = 0) filling the middle of a %dx%d view\n    expected more than %d "
                    "refracted rays\n    got      %llu\n    likely mistake: %s",
                    side, side, side * side / 8, (unsigned long long)stats.by_kind[RAY_REFRACTED], no_transmitted);
    assert_int_equal(0, stats.by_kind[RAY_REFLECTED]);                    /* R = 0 exactly: no mirror ray */
    long same = 0;
    for (long k = 0; k < (long)side * side; k++) {
        color a = without.pixels[k], b = with.pixels[k];
        same += display_encode(a.r, 1) == display_encode(b.r, 1) && display_encode(a.g, 1) == display_encode(b.g, 1) &&
                display_encode(a.b, 1) == display_encode(b.b, 1);
    }
    if (same < (long)(0.999 * side * side))
        fail_msg("only %ld of %d pixels are the same", same, side * side);
    image_free(&without);
    image_free(&with);
    scene_free(&desc);
}

/* Only what the scene requires: chapter 08's built-in scene (no glass)
 * casts no refracted ray through the glass stage; the glass scene does. */
static void test_rays_only_where_needed(void **state)
{
    (void)state;
    glass_knobs knobs = knobs_of(PATH_DEFAULT_DEPTH, PATH_DEFAULT_MIN_WEIGHT);
    scene desc;
    scene_init(&desc);
    assert_int_equal(0, mirror_scene(&desc));
    image img;
    render_stats stats = render_glass(&desc, &knobs, &img, 32, 32);
    assert_int_equal(0, stats.by_kind[RAY_REFRACTED]);
    assert_true(stats.by_kind[RAY_REFLECTED] > 0);
    image_free(&img);
    scene_free(&desc);
    scene_init(&desc);
    assert_int_equal(0, glass_scene(&desc));
    stats = render_glass(&desc, &knobs, &img, 32, 32);
    assert_true_why(
        stats.by_kind[RAY_REFRACTED] > 0,
        "the glass scene (a glass sphere over a floor) at 32x32\n    expected refracted rays\n    got      none\n"
        "    likely mistake: %s",
        no_transmitted);
    for (int k = 0; k < 32 * 32; k++)
        assert_true_why(
            img.pixels[k].r >= 0 && isfinite(img.pixels[k].r),
            "the glass scene at 32x32, pixel (%d, %d): red\n    expected a finite value >= 0\n    got      "
            "%.17g\n    likely mistake: a weight outside [0, 1] (R from fresnel, 1 - R for the transmitted ray) "
            "or a NaN from refract (the test |S_t|^2 > 1 comes before the square root)",
            k % 32, k / 32, (double)img.pixels[k].r);
    image_free(&img);
    scene_free(&desc);
}

/* The course's later assignment writes <light type="PointLight">: read as a
 * point light; another type is an error naming the line. */
static void test_point_light_type(void **state)
{
    (void)state;
    char path[] = "/tmp/rt_test_09_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "w");
    fputs("<scene>\n<light type=\"PointLight\"><position>1 2 3</position></light>\n"
          "<shader name=\"g\" type=\"Glass\"><refractiveIndex>1.33</refractiveIndex></shader>\n</scene>\n",
          f);
    fclose(f);
    scene s;
    char err[256] = "";
    assert_int_equal(0, scene_load(path, &s, err, sizeof err));
    assert_int_equal(1, s.n_lights);
    assert_close(2, s.lights[0].position.y, 0);
    assert_close(1.33, s.shaders[0].refractive_index, TOL(1));
    scene_free(&s);
    f = fopen(path, "w");
    fputs("<scene>\n<light type=\"SpotLight\"/>\n</scene>\n", f);
    fclose(f);
    assert_int_equal(-1, scene_load(path, &s, err, sizeof err));
    assert_non_null(strstr(err, ":2: unknown light type 'SpotLight'"));
    remove(path);
}

static const graded_test tests[] = {
    GRADED(test_refract_normal_incidence, 2),
    GRADED(test_refract_equal_indices, 2),
    GRADED(test_snell_law, 3),
    GRADED(test_critical_angle, 3),
    GRADED(test_fresnel_normal_incidence, 2),
    GRADED(test_fresnel_exact_values, 3),
    GRADED(test_r_plus_t, 2),
    GRADED(test_schlick_cosines, 2),
    GRADED(test_sphere_centre_undeviated, 3),
    GRADED(test_slab_returns_entry_direction, 3),
    GRADED(test_total_internal_reflection_rays, 2),
    GRADED(test_glass_weights, 3),
    GRADED(test_furnace_glass_sphere, 2),
    GRADED(test_furnace_on_white, 0),
    GRADED(test_index_one_sphere_invisible, 2),
    GRADED(test_rays_only_where_needed, 1),
    GRADED(test_point_light_type, 0), /* the scene reader, handed out complete: no points */
};

SUITE_MAIN("09_refraction", tests)
