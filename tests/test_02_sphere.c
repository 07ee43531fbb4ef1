/* test_02_sphere.c - chapter 02: the ray-sphere intersection.
 *
 * Concrete cases first (each checks a hit next to every miss, so that an
 * unfinished function that always says "no hit" fails them), then a sweep of
 * far, small spheres where the robust formula must stay right.  Tolerances
 * are in units of REAL_EPSILON, so the float build runs the same tests.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "02_sphere/sphere.h"
#include "suite.h"

/* Simple cases (t exact in a few operations): a handful of roundings. */
#define TOL(x) (8 * REAL_EPSILON * (x))
#define N(a) (sizeof(a) / sizeof((a)[0]))

static const sphere unit = {{0, 0, 0}, 1};

static ray make_ray(real px, real py, real pz, real dx, real dy, real dz)
{
    return (ray){vec3_make(px, py, pz), vec3_make(dx, dy, dz)};
}

static const char *describe_ray(const sphere *s, ray r);
static const char *describe_intersect(const sphere *s, ray r, real t_min, real t_max, sphere_formula f);
static const char *formula_name(sphere_formula f);

/* What *t holds before sphere_intersect: a hit that leaves it so is named, not printed as a t got. */
#define UNWRITTEN ((real)12345)

static const char *describe_t_got(real t)
{
    return t == UNWRITTEN ? "true, but *t not written" : describe("t = %.17g", (double)t);
}

#define NO_HIT_HINT "the roots (run test_roots_*), or the window: the nearest root with t_min < t < t_max (test_nearest_root)"

/* Asserts a hit at t_expected with normal n_expected; no_hit names the likely
 * mistake when there is none. */
static void expect_hit_why(const sphere *s, ray r, real t_min, real t_max, sphere_formula formula, real t_expected,
                           vec3 n_expected, const char *no_hit)
{
    real t = -1;
    vec3 n = {0, 0, 0};
    const char *in = describe_intersect(s, r, t_min, t_max, formula);
    if (!sphere_intersect(s, r, t_min, t_max, formula, &t, &n))
        fail_msg("%s\n    expected a hit at t = %.17g\n    got      no hit\n    likely mistake: %s", in,
                 (double)t_expected, no_hit);
    assert_close_why(t_expected, t, TOL(t_expected), describe("%s: t", in),
                     "the roots (test_roots_*) or the choice of root (test_nearest_root)", NULL, 0);
    const suspect_vec3 inward[] = {{vec3_neg(n_expected), "the normal points inwards: n = (x - c) / |x - c|"}};
    assert_vec3_why(n_expected, n, TOL(1), describe("%s: n", in), "n = (x - c) / |x - c|", inward, 1);
}

static void expect_hit(const sphere *s, ray r, real t_min, real t_max, sphere_formula formula, real t_expected,
                       vec3 n_expected)
{
    expect_hit_why(s, r, t_min, t_max, formula, t_expected, n_expected, NO_HIT_HINT);
}

static void expect_miss(const sphere *s, ray r, real t_min, real t_max, sphere_formula formula)
{
    real t = UNWRITTEN;
    vec3 n = {0, 0, 0};
    if (sphere_intersect(s, r, t_min, t_max, formula, &t, &n))
        fail_msg("%s\n    expected no hit\n    got      %s\n"
                 "    likely mistake: a negative discriminant is a miss, and a root at or outside (t_min, t_max) is "
                 "no hit",
                 describe_intersect(s, r, t_min, t_max, formula), describe_t_got(t));
}

/* The root sphere_intersect should take in (t_min, inf): (2) in long double
 * on the same data, for messages only; NaN when the line misses. */
static double root_expected(const sphere *s, ray r, real t_min)
{
    long double fx = (long double)r.p.x - s->center.x, fy = (long double)r.p.y - s->center.y,
                fz = (long double)r.p.z - s->center.z;
    long double A = (long double)r.d.x * r.d.x + (long double)r.d.y * r.d.y + (long double)r.d.z * r.d.z;
    long double B = r.d.x * fx + r.d.y * fy + r.d.z * fz;
    long double C = fx * fx + fy * fy + fz * fz - (long double)s->radius * s->radius;
    long double disc = B * B - A * C;
    if (!(disc >= 0))
        return NAN;
    long double near = (-B - sqrtl(disc)) / A, far = (-B + sqrtl(disc)) / A;
    return (double)(near > t_min ? near : far);
}

/* assert_true(sphere_intersect(s, r, 0, inf, f, t, n)), the same record; a
 * miss fails naming the input, the hit expected and the likely mistake
 * no_hit.  Returns the input, for the checks of the hit. */
static const char *intersect_hit(const sphere *s, ray r, sphere_formula f, const char *no_hit, real *t, vec3 *n)
{
    const char *in = describe_intersect(s, r, 0, REAL_INFINITY, f);
    assert_true_why(sphere_intersect(s, r, 0, REAL_INFINITY, f, t, n),
                    "%s\n    expected a hit at t = %.17g\n    got      no hit\n    likely mistake: %s", in,
                    root_expected(s, r, 0), no_hit);
    return in;
}

/* n is a unit vector: |n| = 1 within 4 eps. */
static void expect_unit_normal(const char *in, vec3 n, real radius)
{
    const suspect unnormalized[] = {{radius, "not normalized: n = (x - c) / |x - c|, and |x - c| = R here"}};
    assert_close_why(1, vec3_length(n), 4 * REAL_EPSILON, describe("%s: |n|", in),
                     "n must be a unit vector: divide x - c by its computed length |x - c|", unnormalized,
                     N(unnormalized));
}

/* ---- the cases, for either formula ---------------------------------------- */

/* From (0,0,5) straight at the unit sphere: t = 5 - 1, n = +z. */
static void hit_case(sphere_formula f) { expect_hit(&unit, make_ray(0, 0, 5, 0, 0, -1), 0, REAL_INFINITY, f, 4, vec3_make(0, 0, 1)); }

/* Two units off the axis misses; the zero direction is no ray and no hit. */
static void miss_case(sphere_formula f)
{
    expect_miss(&unit, make_ray(0, 2, 5, 0, 0, -1), 0, REAL_INFINITY, f);
    expect_miss(&unit, make_ray(0, 0, 5, 0, 0, 0), 0, REAL_INFINITY, f);
    expect_hit(&unit, make_ray(0, 0, 5, 0, 0, -1), 0, REAL_INFINITY, f, 4, vec3_make(0, 0, 1));
}

/* x = 1 grazes the sphere at (1,0,0), t = 5 (a double root, counted as a hit);
 * 2^-10 further out misses, 2^-10 further in hits. */
static void tangent_case(sphere_formula f)
{
    /* f = (1, 0, 5): A = 1, B = -5, C = f.f - R^2 = 25, so B^2 - A C is exactly 0 */
    expect_hit_why(&unit, make_ray(1, 0, 5, 0, 0, -1), 0, REAL_INFINITY, f, 5, vec3_make(1, 0, 0),
                   f == SPHERE_TEXTBOOK ? "a tangent ray is a hit: its discriminant is exactly 0 (a double root), so "
                                          "the test is disc >= 0, not disc > 0"
                                        : NO_HIT_HINT);
    expect_miss(&unit, make_ray(1 + (real)0x1p-10, 0, 5, 0, 0, -1), 0, REAL_INFINITY, f);
    real t, x = 1 - (real)0x1p-10;
    vec3 n;
    const char *in = intersect_hit(&unit, make_ray(x, 0, 5, 0, 0, -1), f,
                                   "the ray passes 2^-10 inside the silhouette, so disc = 1 - x^2 = 0.00195 > 0 "
                                   "((2), or (4) with l.l = x^2): a hit; a fixed epsilon on the discriminant refuses "
                                   "it, the miss test is !(disc >= 0)",
                                   &t, &n);
    /* Near a tangent the root is sensitive: an error e in the discriminant
     * moves t by e / (2 sqrt(disc)).  Both formulas' discriminants err by at
     * most about 4 eps (B^2 + |A C|) = 4 eps (25 + 25) here. */
    real disc = 1 - x * x;
    const suspect far[] = {{5 + real_sqrt(disc), "took the far root: the nearest root inside the window is the hit"}};
    assert_close_why(5 - real_sqrt(disc), t, TOL(5) + 200 * REAL_EPSILON / (2 * real_sqrt(disc)), describe("%s: t", in),
                     f == SPHERE_TEXTBOOK ? "the near root (-B - sqrt(disc)) / A of (2), disc = B^2 - A C"
                                          : "the discriminant A (R^2 - l.l) of (3)-(4) and the stable pair (5)",
                     far, N(far));
}

/* From the centre the near root is t = -1, behind p: the hit is the far root
 * t = 1, and the outward normal points along d. */
static void inside_case(sphere_formula f)
{
    expect_hit(&unit, make_ray(0, 0, 0, 0, 0, -1), 0, REAL_INFINITY, f, 1, vec3_make(0, 0, -1));
    expect_hit(&unit, make_ray(0.5, 0, 0, 1, 0, 0), 0, REAL_INFINITY, f, 0.5, vec3_make(1, 0, 0));
}

/* Both roots negative: the sphere is behind p.  The reversed ray hits. */
static void behind_case(sphere_formula f)
{
    expect_miss(&unit, make_ray(0, 0, 5, 0, 0, 1), 0, REAL_INFINITY, f);
    expect_hit(&unit, make_ray(0, 0, 5, 0, 0, -1), 0, REAL_INFINITY, f, 4, vec3_make(0, 0, 1));
}

/* The roots are t = 4 and t = 6; the window (t_min, t_max) is open. */
static void window_case(sphere_formula f)
{
    ray r = make_ray(0, 0, 5, 0, 0, -1);
    expect_hit(&unit, r, 0, 10, f, 4, vec3_make(0, 0, 1));
    expect_miss(&unit, r, 0, 3, f);                                   /* both beyond t_max */
    expect_miss(&unit, r, 0, 4, f);                                   /* t = 4 is not < 4 */
    expect_hit(&unit, r, 4, 10, f, 6, vec3_make(0, 0, -1));           /* t = 4 is not > 4: the far root */
    expect_hit(&unit, r, 4.5, REAL_INFINITY, f, 6, vec3_make(0, 0, -1));
    expect_miss(&unit, r, 6, REAL_INFINITY, f);                       /* both at or before t_min */
    expect_miss(&unit, r, 4.5, 5.5, f);                               /* between the roots */
}

/* The likely mistake behind a miss of a ray whose d is not a unit vector. */
static const char *non_unit_d(vec3 d)
{
    return describe("d is not a unit vector here (|d| = %g): A = d.d (not 1) in (1) and (2), t_m = -B / A in (3), "
                    "disc = A (R^2 - l.l) in (4); or a fixed epsilon on the discriminant, which scales with |d|^2",
                    (double)vec3_length(d));
}

/* d -> alpha d is the same ray with t -> t / alpha (lecture, "Ray: a half line"). */
static void scaled_case(sphere_formula f)
{
    const sphere s = {{1, -2, 0.5}, 1.5};
    const vec3 p = {4, 1, 3}, d = {-0.6, -0.7, -0.4};
    real t1;
    vec3 n1;
    intersect_hit(&s, (ray){p, d}, f, non_unit_d(d), &t1, &n1);
    const real alphas[] = {(real)1e-3, (real)0.37, 2, (real)1e3};
    for (int k = 0; k < 4; k++) {
        real t;
        vec3 n;
        const vec3 scaled = vec3_scale(d, alphas[k]);
        const char *in = intersect_hit(&s, (ray){p, scaled}, f, non_unit_d(scaled), &t, &n);
        const char *against = describe("%s, d = %g times the d of t1 = %.17g", in, (double)alphas[k], (double)t1);
        const suspect unscaled[] = {{t1 * alphas[k], "t did not change with d: p + t d is the hit point, so t is in "
                                                     "units of |d|; A = d.d in (1) is not 1 (do not normalize d)"}};
        /* a few roundings in each of t and t1 */
        assert_close_why(t1, t * alphas[k], 16 * REAL_EPSILON * t1, describe("%s: t alpha", against),
                         "d -> alpha d is the same ray with t -> t / alpha: A = d.d and B = d.f of (1) carry alpha^2 "
                         "and alpha, and every root is divided by A ((2), or q / A and C / q in (5))",
                         unscaled, N(unscaled));
        assert_vec3_why(n1, n, 16 * REAL_EPSILON, describe("%s: n, against n1", against),
                        "n = (x - c) / |x - c| depends on the hit point x only, not on the length of d", NULL, 0);
    }
}

/* ---- the parts, each alone ---------------------------------------------------
 *
 * sphere_roots, sphere_nearest_root and sphere_normal are tested on their
 * own, so that a mistake in one costs its own tests.  A failure names the
 * input, the expected value, the value got and the likely mistake. */

static const char *formula_name(sphere_formula f) { return f == SPHERE_TEXTBOOK ? "textbook" : "robust"; }

static const char *describe_ray(const sphere *s, ray r)
{
    return describe("sphere c = (%g, %g, %g), R = %g; ray p = (%g, %g, %g), d = (%g, %g, %g)", (double)s->center.x,
                    (double)s->center.y, (double)s->center.z, (double)s->radius, (double)r.p.x, (double)r.p.y,
                    (double)r.p.z, (double)r.d.x, (double)r.d.y, (double)r.d.z);
}

static const char *describe_intersect(const sphere *s, ray r, real t_min, real t_max, sphere_formula f)
{
    return describe("sphere_intersect(%s, (%g, %g), %s)", describe_ray(s, r), (double)t_min, (double)t_max,
                    formula_name(f));
}

/* The textbook roots (-b -+ sqrt(disc)) / a of a discriminant, right or
 * wrong, as (near, far, 0), or (NaN, NaN, 0) when it is negative. */
static vec3 roots_from(long double a, long double b, long double disc)
{
    if (!(disc >= 0))
        return vec3_make(((real)NAN), ((real)NAN), 0);
    long double root = sqrtl(disc);
    long double t0 = (-b - root) / a, t1 = (-b + root) / a;
    return vec3_make((real)fminl(t0, t1), (real)fmaxl(t0, t1), 0);
}

/* The roots of a*t^2 + 2*b*t + c = 0 as (near, far, 0), by the quadratic
 * formula in long double, or (NaN, NaN, 0) when there are none: how the
 * likely mistakes below would come out. */
static vec3 pair(long double a, long double b, long double c) { return roots_from(a, b, b * b - a * c); }

/* The stable pair (5) from A, B, C and a discriminant, sorted as
 * (near, far, 0): with a wrong discriminant, how a mistake comes out. */
static vec3 stable(long double A, long double B, long double C, long double disc)
{
    if (!(disc >= 0))
        return vec3_make(((real)NAN), ((real)NAN), 0);
    long double q = -(B + (B < 0 ? -1 : 1) * sqrtl(disc));
    long double t0 = q / A, t1 = C / q;
    return vec3_make((real)fminl(t0, t1), (real)fmaxl(t0, t1), 0);
}

/* sphere_roots(s, r) sorted as (near, far, 0); *found: what it returned. */
static vec3 roots_got(const sphere *s, ray r, sphere_formula f, bool *found)
{
    real t0 = ((real)NAN), t1 = ((real)NAN);
    *found = sphere_roots(s, r, f, &t0, &t1);
    return vec3_make(real_fmin(t0, t1), real_fmax(t0, t1), 0);
}

/* The roots of (1) from the test's own long double arithmetic on the same
 * inputs, and the values the usual mistakes give. */
static void expect_roots(const sphere *s, ray r, sphere_formula f, double tolerance)
{
    long double fx = (long double)r.p.x - s->center.x, fy = (long double)r.p.y - s->center.y,
                fz = (long double)r.p.z - s->center.z;
    long double A = (long double)r.d.x * r.d.x + (long double)r.d.y * r.d.y + (long double)r.d.z * r.d.z;
    long double B = r.d.x * fx + r.d.y * fy + r.d.z * fz;
    long double R2 = (long double)s->radius * s->radius;
    long double C = fx * fx + fy * fy + fz * fz - R2;
    vec3 expected = pair(A, B, C);
    long double q = -(B + (B < 0 ? -1 : 1) * sqrtl(B * B - A * C));
    long double c_over_a = C / A; /* t1 = C / A, then through the bound (6) as the solution's code does */
    if (c_over_a * c_over_a * A > fabsl(C))
        c_over_a = copysignl(sqrtl(fabsl(C) / A), c_over_a);
    const suspect_vec3 mistakes[] = {
        {stable(A, B, C, (B * B - A * C) / A), "disc = A (R^2 - l.l): the factor A is missing"},
        {stable(A, B, C, -A * C - 3 * B * B), "l = f + t_m d with t_m = -B / A: the sign of t_m is wrong"},
        {stable(A, B, C, -A * C + (2 - A) * A * B * B),
         "l = f - B d: t_m = -B / A, divided by A = d.d (d is not a unit vector)"},
        {vec3_make((real)fminl(q / A, q / C), (real)fmaxl(q / A, q / C), 0),
         "t1 = C / q (the product of the roots is C / A), not q / C"},
        {vec3_make((real)(q / A), (real)(q / A), 0), "t1 not computed: t1 = C / q"},
        {pair(A, -B, C), "the roots are negated: f = p - c (not c - p), and t = (-B -+ sqrt(B^2 - A C)) / A"},
        {pair(1, B, C), "A left out: d is not a unit vector here, A = d.d (the lecture: \"we won't assume this\")"},
        {pair(A, B, C + R2 - s->radius), "C = f.f - R^2, not f.f - R"},
        {pair(A, B / 2, C / 4), "the factor 2 of B mixed up: with B = d.f the equation is A t^2 + 2 B t + C = 0"},
        {vec3_scale(expected, (real)0.5), "divided by 2A: with B = d.f (half the usual b) the roots are (-B -+ sqrt(disc)) / A"},
        {pair(A, B, C * A), "disc = A (R^2 - l.l): R^2 - l.l times A, not C times A"},
        {vec3_make(0, 0, 0), "no real roots reported as a double root at 0, or roots not written"},
        {vec3_scale(expected, (real)A), "the roots not divided by A = d.d: t = (-B -+ sqrt(disc)) / A"},
        {roots_from(sqrtl(A), B, B * B - sqrtl(A) * C), "A = d.d, the squared length of d, not |d|"},
        {pair(A, 2 * B, C), "B = d.f, not 2 d.f: the equation A t^2 + 2 B t + C = 0 holds the 2 already"},
        {roots_from(A, B, B * B - C), "disc = B^2 - A C: the factor A is missing (d is not a unit vector here)"},
        {stable(A, B, C, B * B - A * (C + R2 - s->radius)), "disc = A (R^2 - l.l): R squared, not R"},
        {vec3_make((real)fminl(q / A, c_over_a), (real)fmaxl(q / A, c_over_a), 0),
         "t1 = C / q, not C / A: C / A is the product t0 t1 of the two roots"},
        {vec3_make((real)fminl(-q / A, C / q), (real)fmaxl(-q / A, C / q), 0),
         "t0 = q / A: the minus sign is inside q = -(B + sign(B) sqrt(disc)) already"},
    };
    const char *in = describe("sphere_roots(%s, %s) as (near, far, 0)", describe_ray(s, r), formula_name(f));
    bool found;
    vec3 got = roots_got(s, r, f, &found);
    if (expected.x != expected.x) {
        if (found)
            fail_msg("%s\n    expected false: no real root (the line misses)\n    got      true, roots %.17g and %.17g\n"
                     "    likely mistake: a negative or NaN discriminant means a miss: return false when "
                     "!(disc >= 0), which a NaN fails too (disc < 0 lets a NaN through)",
                     in, (double)got.x, (double)got.y);
        return;
    }
    if (!found) {
        /* no roots where there are two: the discriminant's mistakes that make it negative here, the robust
         * form's (the first three above) or the textbook's */
        const suspect_vec3 textbook[] = {
            {pair(A, B, C + 2 * R2), "C = f.f - R^2: R^2 is subtracted, not added"},
            {pair(A, B, 4 * C), "disc = B^2 - A C: with B = d.f (half the usual b) there is no factor 4"},
        };
        const suspect_vec3 *no_root = f == SPHERE_ROBUST ? mistakes : textbook;
        char why[600] = "";
        /* the same ray past a sphere of a thousandth the radius, which its line misses by more than twice that
         * radius: roots there and none here is a discriminant of the wrong sign */
        const sphere tiny = {s->center, s->radius / 1024};
        real u0, u1;
        const bool reversed = C + R2 - B * B / A > 4 * R2 / (1024.0L * 1024) && sphere_roots(&tiny, r, f, &u0, &u1);
        if (reversed)
            snprintf(why, sizeof why, "the discriminant's sign reversed: a line through the sphere has l.l < R^2, "
                                      "so disc = A (R^2 - l.l) (robust) or B^2 - A C (textbook) is positive");
        for (size_t k = 0; k < (f == SPHERE_ROBUST ? 3 : N(textbook)) && !reversed; k++)
            if (no_root[k].value.x != no_root[k].value.x)
                snprintf(why + strlen(why), sizeof why - strlen(why), "%s%s", *why ? "; or " : "", no_root[k].mistake);
        fail_msg("%s\n    expected roots %.17g and %.17g\n    got      false (no roots)\n    likely mistake: %s", in,
                 (double)expected.x, (double)expected.y,
                 *why ? why : "the discriminant's sign: disc = B^2 - A C (textbook) or A (R^2 - l.l) (robust)");
    }
    assert_vec3_why(expected, got, tolerance, in, "A = d.d, B = d.f, C = f.f - R^2 with f = p - c", mistakes,
                    N(mistakes));
}

/* Rays in general position, off the origin, with a non-unit d: roots within
 * 16 eps of the largest quantity involved (|f|/|d| about 6 here). */
static void roots_case(sphere_formula f)
{
    const sphere s = {{(real)1.25, (real)-2.5, (real)0.75}, (real)1.5};
    const ray rays[] = {
        {{4, 1, 3}, {(real)-0.6, (real)-0.7, (real)-0.4}},      /* from outside, through */
        {{(real)1.5, (real)-2, 1}, {(real)0.3, (real)0.8, (real)-0.5}}, /* from inside */
        {{4, 1, 3}, {(real)0.6, (real)0.7, (real)0.4}},          /* away: both roots negative */
        {{4, 1, 3}, {(real)-0.6, (real)0.7, (real)-0.4}},        /* a miss */
        {{(real)-7, (real)5, (real)-3}, {(real)2.5, (real)-2.25, 1}},
        {{((real)NAN), 1, 3}, {(real)-0.6, (real)-0.7, (real)-0.4}}, /* a NaN coordinate: a NaN discriminant, no root */
    };
    for (size_t k = 0; k < N(rays); k++)
        expect_roots(&s, rays[k], f, 16 * REAL_EPSILON * 8);
}

static void test_roots_robust(void **state) { (void)state; roots_case(SPHERE_ROBUST); }
static void test_roots_textbook(void **state) { (void)state; roots_case(SPHERE_TEXTBOOK); }

/* B = d.f = 0: the ray's origin is the point of its line closest to c.
 * Every number here is exact: f = (0.5, 0.25, 0), d = (-0.25, 0.5, 3),
 * d.f = 0, A = 9.3125, C = -1.9375, roots +-sqrt(1.9375 / 9.3125). */
static void test_b_zero_sign(void **state)
{
    (void)state;
    const sphere s = {{(real)0.25, (real)-0.5, 1}, (real)1.5};
    const ray r = {{(real)0.75, (real)-0.25, 1}, {(real)-0.25, (real)0.5, 3}};
    const double tau = sqrt(1.9375 / 9.3125);
    const suspect_vec3 sign_zero[] = {
        {vec3_make(-REAL_INFINITY, 0, 0), "sign(0) = 0: with B = 0, q = -(B + sign(B) sqrt(disc)) is 0 and t1 = C / q "
                                          "divides by zero; take sign(B) = +1 when B = 0"},
        {vec3_make(0, REAL_INFINITY, 0), "sign(0) = 0: with B = 0, q is 0 and C / q divides by zero; take sign(0) = +1"},
        {vec3_make(0, 0, 0), "sign(0) = 0: with B = 0, q is 0 (and t1 = t0 = 0); take sign(B) = +1 when B = 0"},
    };
    const char *in = describe("sphere_roots(%s, robust) as (near, far, 0), where B = d.f = 0", describe_ray(&s, r));
    /* sqrt and two divisions: a few roundings of tau */
    bool found;
    vec3 got = roots_got(&s, r, SPHERE_ROBUST, &found);
    if (!found)
        fail_msg("%s\n    expected roots -+%.17g\n    got      false (no roots)\n    likely mistake: "
                 "disc = A (R^2 - l.l) with l = f + t_m d, t_m = -B / A: here t_m = 0 and l = f",
                 in, tau);
    assert_vec3_why(vec3_make((real)-tau, (real)tau, 0), got, 8 * REAL_EPSILON * tau, in,
                    "q = -(B + sign(B) sqrt(disc)), t0 = q / A, t1 = C / q", sign_zero, N(sign_zero));
    real t = 0;
    vec3 n;
    bool hit = sphere_intersect(&s, r, 0, REAL_INFINITY, SPHERE_ROBUST, &t, &n);
    const char *whole = describe_intersect(&s, r, 0, REAL_INFINITY, SPHERE_ROBUST);
    if (!hit)
        fail_msg("%s\n    expected a hit at t = %.17g\n    got      no hit\n    likely mistake: the roots -+%.17g "
                 "above are right, so the choice of root: p is inside (C < 0), the near root is before t_min = 0 "
                 "and the far one is the hit (sphere_nearest_root, README \"The code\")",
                 whole, tau, tau);
    const suspect none[] = {{0, "sign(0) = 0 gave no usable root: take sign(B) = +1 when B = 0"}};
    assert_close_why(tau, t, 8 * REAL_EPSILON * tau, describe("%s: t", whole), "the far root, t = sqrt(-C / A)", none,
                     1);

    /* B = 0 and disc = 0: a ray that starts at its point of tangency.  Again
     * exact: f = (1.5, 0, 0) = R (1, 0, 0), d = (0, 0.5, 3) is perpendicular
     * to it, so B = 0, l = f, disc = A (R^2 - l.l) = 0 and C = 0.  The double
     * root is t = 0: q = -(B + sign(B) sqrt(disc)) = 0, and C / q would be
     * 0 / 0; the exercise takes t1 = t0 then.  Both roots exactly 0. */
    const ray tangent = {{(real)1.75, (real)-0.5, 1}, {0, (real)0.5, 3}};
    const char *at = describe("sphere_roots(%s, robust), where B = 0 and disc = 0", describe_ray(&s, tangent));
    real t0 = ((real)NAN), t1 = ((real)NAN);
    if (!sphere_roots(&s, tangent, SPHERE_ROBUST, &t0, &t1))
        fail_msg("%s\n    expected the double root t = 0\n    got      false (no roots)\n    likely mistake: "
                 "disc = 0 is a root (a tangent ray): the miss test is !(disc >= 0)",
                 at);
    const suspect zero_by_zero[] = {
        {((real)NAN), "t1 = C / q with q = 0 is 0 / 0 = NaN: when q = 0 both roots are 0, take t1 = t0"},
        {REAL_INFINITY, "t1 = C / q with q = 0 divides by zero: when q = 0 both roots are 0, take t1 = t0"},
        {-REAL_INFINITY, "t1 = C / q with q = 0 divides by zero: when q = 0 both roots are 0, take t1 = t0"},
    };
    assert_close_why(0, t0, 0, describe("%s: t0", at), "t0 = q / A with q = 0", zero_by_zero, N(zero_by_zero));
    assert_close_why(0, t1, 0, describe("%s: t1", at), "t1 = t0 = 0 when q = 0", zero_by_zero, N(zero_by_zero));
}

/* A ray that starts near the sphere has one small root.  The stable pair
 * keeps its digits; (-B + sqrt(disc)) / A subtracts two nearly equal
 * numbers and loses them.  Here f = (1, 1.5, 3 + 2^-10), so C = f.f - R^2 =
 * 6 2^-10 + 2^-20 exactly (24 significant bits: exact in float too), and
 * the small root is about C / 2|B|.  The stable root errs by a few roundings
 * of itself (B, disc, q, C / q): 16 eps relative. */
static void test_small_root_near_surface(void **state)
{
    (void)state;
    const sphere s = {{(real)0.25, (real)-0.5, 1}, (real)3.5};
    const vec3 f = {1, (real)1.5, 3 + (real)0x1p-10};
    const vec3 p = vec3_add(s.center, f);
    const vec3 dirs[] = {{(real)-0.3, (real)-0.2, (real)-0.9}, {(real)0.1, (real)-0.9, (real)-0.35},
                         {(real)0.3, (real)0.2, (real)0.9}, {(real)-0.2, (real)-0.5, (real)-0.1}};
    for (size_t k = 0; k < N(dirs); k++) {
        ray r = {p, dirs[k]};
        long double A = (long double)r.d.x * r.d.x + (long double)r.d.y * r.d.y + (long double)r.d.z * r.d.z;
        long double B = (long double)r.d.x * f.x + (long double)r.d.y * f.y + (long double)r.d.z * f.z;
        long double C = 6.0L / 1024 + 1.0L / 1048576;
        long double q = -(B + (B < 0 ? -1 : 1) * sqrtl(B * B - A * C));
        long double small = C / q;
        real t0, t1;
        if (!sphere_roots(&s, r, SPHERE_ROBUST, &t0, &t1))
            fail_msg("sphere_roots(%s, robust): no roots, expected a small root %.17Lg", describe_ray(&s, r), small);
        real got = fabsl((long double)t0) < fabsl((long double)t1) ? t0 : t1;
        const suspect cancel[] = {
            {(double)((-B + (B < 0 ? 1 : -1) * -sqrtl(B * B - A * C)) / A),
             "the small root computed as (-B -+ sqrt(disc)) / A cancels: use t1 = C / q"},
        };
        assert_close_why((double)small, got, 16 * REAL_EPSILON * fabsl(small),
                         describe("sphere_roots(%s, robust): the small root, p just off the sphere (C = %.6g)",
                                  describe_ray(&s, r), (double)C),
                         "the stable pair: q = -(B + sign(B) sqrt(disc)), t0 = q / A, t1 = C / q, so that neither "
                         "root subtracts nearly equal numbers",
                         cancel, N(cancel));
    }
}

/* Rays that leave a point of the sphere along its tangent there: p = c + R u
 * and d perpendicular to u, both rounded.  B, disc and C are then all
 * rounding noise, and C / q can be noise of any size; (6) keeps |t1| within
 * sqrt(|C| / A), its exact bound.  Every root must put its point on the
 * sphere within the README's 16 eps S (S = |p| + |c| + R); the exact roots
 * are both within rounding of t = 0.  20 000 rays of random spheres (radius
 * 1e-2 to 1e3, centres up to 1e3 from the origin), points and tangents. */
static void test_tangent_rays_from_the_surface(void **state)
{
    (void)state;
    unsigned long seed = 2024;
    long bad = 0, with_roots = 0, behind_bad = 0;
    for (int k = 0; k < 20000; k++) {
        const double R = pow(10, 5 * suite_uniform(&seed) - 2), spread = pow(10, 3 * suite_uniform(&seed));
        const vec3 centre = suite_random_unit(&seed);
        const sphere s = {vec3_scale(centre, (real)spread), (real)R};
        const vec3 u = suite_random_unit(&seed), side = suite_random_unit(&seed);
        const real length = (real)pow(10, 4 * suite_uniform(&seed) - 2);
        const vec3 tangent = vec3_cross(u, side);
        if (!(vec3_length(tangent) > (real)0.1))
            continue;
        const ray r = {vec3_add(s.center, vec3_scale(u, s.radius)), vec3_scale(vec3_normalize(tangent), length)};
        real t0, t1;
        /* The same line from 4R further along: its point of tangency is
         * 4R / |d| behind the origin.  Rounding moves the line by about
         * eps S, so it may cross the sphere within sqrt(2 R eps S) of that
         * point (under R / 4 here: R >= 1e-2, S <= 2e3, float eps): both roots
         * stay negative, and a root in front is a sphere behind the ray hit
         * in front of it (when (6) applies, t1 must keep its sign). */
        const ray behind = {vec3_add(r.p, vec3_scale(r.d, 4 * s.radius / length)), r.d};
        if (sphere_roots(&s, behind, SPHERE_ROBUST, &t0, &t1) && !(t0 < 0 && t1 < 0) && behind_bad++ < 3)
            print_message("sphere_roots(%s, robust): a line tangent to the sphere at a point %.9g behind its "
                          "origin\n    expected two negative roots near %.9g\n    got      %.17g and %.17g\n",
                          describe_ray(&s, behind), (double)(4 * s.radius), (double)(-4 * s.radius / length),
                          (double)t0, (double)t1);
        if (!sphere_roots(&s, r, SPHERE_ROBUST, &t0, &t1))
            continue; /* the line misses by rounding: no root is fine */
        with_roots++;
        const long double S = (long double)vec3_length(r.p) + (long double)vec3_length(s.center) + R;
        const real roots[2] = {t0, t1};
        for (int j = 0; j < 2; j++) {
            long double x = (long double)r.p.x + (long double)roots[j] * r.d.x - s.center.x;
            long double y = (long double)r.p.y + (long double)roots[j] * r.d.y - s.center.y;
            long double z = (long double)r.p.z + (long double)roots[j] * r.d.z - s.center.z;
            long double off = fabsl(sqrtl(x * x + y * y + z * z) - (long double)s.radius);
            if (!(off <= 16 * REAL_EPSILON * S) && bad++ < 3)
                print_message("sphere_roots(%s, robust): a tangent ray from the surface; root %.17g puts its "
                              "point %.3Lg from the sphere, %.3Lg eps S\n",
                              describe_ray(&s, r), (double)roots[j], off, off / (REAL_EPSILON * S));
        }
    }
    /* The line touches or misses the sphere by rounding: a little over half
     * of the rays have roots (the reference: 11461 in double, 11457 in float). */
    if (with_roots < 5000)
        fail_msg("sphere_roots(robust) on 20000 tangent rays from a point of the sphere\n    expected roots for about "
                 "half of them (each line touches the sphere up to rounding)\n    got      roots for %ld\n    "
                 "likely mistake: a discriminant that rounds to 0 is a root (!(disc >= 0) is the miss test), "
                 "or the robust formula not written yet",
                 with_roots);
    if (bad)
        fail_msg("sphere_roots(robust) on 20000 tangent rays from a point of the sphere\n    expected every root within "
                 "16 eps S of the sphere\n    got      %ld roots beyond\n    likely mistake: t1 = C / q "
                 "without the bound (6): where B, disc and C are all rounding noise C / q is noise of any size; "
                 "when t1^2 A > |C| take t1 = sign(t1) sqrt(|C| / A)",
                 bad);
    assert_true_why(behind_bad == 0,
                    "sphere_roots(robust) on tangent rays whose point of tangency is 4R behind the origin\n"
                    "    expected two negative roots (the sphere is behind the ray)\n    got      %ld rays with a root "
                    ">= 0\n    likely mistake: the bound (6) without the sign: t1 = sign(t1) sqrt(|C| / A), not "
                    "sqrt(|C| / A)",
                    behind_bad);
}

/* sphere_roots (given) scales data of extreme size by powers of two: a
 * sphere of centre sigma (0.5, 0.25, 4) and radius 0.75 sigma, the ray
 * from sigma (0.5, 0.25, 0) along tau (0, 0, 1) meets it at t = 3.25 sigma /
 * tau and 4.75 sigma / tau, exactly, for sigma and tau from the ends of the
 * exponent range (all data and both roots representable). */
static void test_roots_at_any_scale(void **state)
{
    (void)state;
    const int top = REAL_EPSILON < 1e-10 ? 1000 : 120;
    const int exps[] = {-top, -top / 3, 0, top / 3, top};
    for (size_t i = 0; i < N(exps); i++)
        for (size_t j = 0; j < N(exps); j++) {
            const int e = exps[i] - exps[j]; /* t is 2^e times 3.25 and 4.75 */
            if (e > top || e < -top)
                continue;
            const real sigma = (real)ldexp(1, exps[i]), tau = (real)ldexp(1, exps[j]);
            const sphere s = {vec3_scale(vec3_make((real)0.5, (real)0.25, 4), sigma), (real)0.75 * sigma};
            const ray r = {vec3_scale(vec3_make((real)0.5, (real)0.25, 0), sigma), vec3_make(0, 0, tau)};
            for (int f = 0; f < 2; f++) {
                real t0 = 0, t1 = 0;
                const bool found = sphere_roots(&s, r, f ? SPHERE_TEXTBOOK : SPHERE_ROBUST, &t0, &t1);
                const real near = (real)ldexp(3.25, e), far = (real)ldexp(4.75, e);
                if (!found || real_fmin(t0, t1) != near || real_fmax(t0, t1) != far)
                    fail_msg("sphere_roots(sigma = 2^%d, tau = 2^%d, %s)\n    expected roots %a and %a\n    got      "
                             "%s\n    likely mistake: sphere_roots is given; the products of four lengths "
                             "overflowed or underflowed",
                             exps[i], exps[j], f ? "textbook" : "robust", (double)near, (double)far,
                             found ? describe("%a and %a", (double)t0, (double)t1) : "false (no roots)");
            }
        }
    /* The radius the largest length: a sphere of radius 2^top around the ray's start, which is at the origin,
     * d = (0, 0, 1): the roots are -2^top and 2^top exactly, R^2 is beyond the reals unless R is scaled too */
    const sphere big = {vec3_make(0, 0, 0), (real)ldexp(1, top)};
    const ray from_centre = {vec3_make(0, 0, 0), vec3_make(0, 0, 1)};
    for (int f = 0; f < 2; f++) {
        real t0 = 0, t1 = 0;
        const bool found = sphere_roots(&big, from_centre, f ? SPHERE_TEXTBOOK : SPHERE_ROBUST, &t0, &t1);
        if (!found || real_fmin(t0, t1) != -big.radius || real_fmax(t0, t1) != big.radius)
            fail_msg("sphere_roots(centre (0, 0, 0), radius 2^%d, p (0, 0, 0), d (0, 0, 1), %s)\n    expected roots "
                     "%a and %a\n    got      %s\n    likely mistake: sphere_roots is given; the scale of the "
                     "lengths is that of p, c and R together, the radius too",
                     top, f ? "textbook" : "robust", (double)-big.radius, (double)big.radius,
                     found ? describe("%a and %a", (double)t0, (double)t1) : "false (no roots)");
    }
}

/* ---- the nearest root in the open window ------------------------------------ */

#define NONE ((real)NAN)

static void expect_nearest(real t0, real t1, real t_min, real t_max, real expected, const suspect *mistakes,
                           size_t n)
{
    real t = ((real)NAN);
    bool hit = sphere_nearest_root(t0, t1, t_min, t_max, &t);
    const char *in = describe("sphere_nearest_root(t0 = %.9g, t1 = %.9g, t_min = %.9g, t_max = %.9g)", (double)t0,
                              (double)t1, (double)t_min, (double)t_max);
    const char *why = n ? mistakes[0].mistake : "the window is open: t_min < t < t_max";
    if (expected != expected) {
        if (hit)
            fail_msg("%s\n    expected no hit\n    got      true, t = %.17g\n    likely mistake: %s", in, (double)t,
                     why);
        return;
    }
    if (!hit)
        fail_msg("%s\n    expected t = %.17g\n    got      false (no hit)\n    likely mistake: %s", in,
                 (double)expected, n > 1 ? mistakes[1].mistake : why);
    assert_close_why(expected, t, 0, in, "the nearest root inside (t_min, t_max)", mistakes, n);
}

static void test_nearest_root(void **state)
{
    (void)state;
    const real inf = REAL_INFINITY;
    const suspect far[] = {{6, "took the far root: the nearest root inside the window is the hit"}};
    expect_nearest(4, 6, 0, inf, 4, far, 1);
    const suspect unsorted[] = {{6, "assumed t0 is the nearer root: the formulas do not sort them, take min(t0, t1)"}};
    expect_nearest(6, 4, 0, inf, 4, unsorted, 1);
    const suspect inside[] = {{-1, "took a root before t_min: the near root is behind the ray's origin"},
                              {0, "no hit when the near root is before t_min: then the far root is the hit (p inside)"}};
    expect_nearest(-1, 1, 0, inf, 1, inside, N(inside));
    expect_nearest(1, -1, 0, inf, 1, inside, N(inside));
    const suspect at_min[] = {{4, "accepted t == t_min: the window (t_min, t_max) is open; compare with t_min itself, not 0 or a "
                                   "fixed epsilon"},
                              {0, "no hit: the near root equals t_min, so the far root is the hit"}};
    expect_nearest(4, 6, 4, 10, 6, at_min, N(at_min));
    /* a ray that starts on the sphere going in: roots 0 and 2.5 */
    const suspect start[] = {{0, "accepted t == t_min = 0: a ray that starts on the sphere would hit it where it "
                                 "starts; the window is open"},
                             {0, "no hit: the root 0 is at t_min, the far root 2.5 is the hit"}};
    expect_nearest(0, (real)2.5, 0, inf, (real)2.5, start, N(start));
    expect_nearest((real)2.5, 0, 0, inf, (real)2.5, start, N(start));
    /* ... and going out: roots -2.5 and -0 */
    const suspect out[] = {{0, "accepted t == t_min = 0 (or -0 == 0): a ray leaving the sphere from its surface "
                               "does not hit it; the window is open"}};
    expect_nearest((real)-2.5, -(real)0, 0, inf, NONE, out, 1);
    expect_nearest((real)-2.5, 0, 0, inf, NONE, out, 1);
    const suspect at_max[] = {{0, "accepted t == t_max (or t_max ignored): the window (t_min, t_max) is open"}};
    expect_nearest(4, 6, 0, 4, NONE, at_max, 1);
    /* p inside: the near root before t_min, the far one at t_max (a shadow ray to a light on the sphere) */
    const suspect far_at_max[] = {{1, "accepted the far root at t == t_max: the window is open at both ends for the "
                                      "far root too"}};
    expect_nearest(-1, 1, 0, 1, NONE, far_at_max, 1);
    const suspect beyond[] = {{0, "t_max ignored: a root beyond t_max is no hit (a shadow ray stops at the light)"}};
    expect_nearest(4, 6, 0, 3, NONE, beyond, 1);
    const suspect before[] = {{0, "a root at or before t_min taken: both roots are outside the window"}};
    expect_nearest(4, 6, 6, inf, NONE, before, 1);
    const suspect between[] = {{0, "the window lies between the roots: neither is inside it"}};
    expect_nearest(4, 6, (real)4.5, (real)5.5, NONE, between, 1);
    const suspect tangent[] = {{0, "a double root (a tangent ray) is a hit"}};
    expect_nearest(5, 5, 0, inf, 5, tangent, 1);
    /* NaN roots (the textbook formula's 0 / 0 for d = 0) are no hit */
    const suspect nan_roots[] = {{0, "a NaN root taken: write the window test so that a NaN fails it, "
                                     "t_min < t && t < t_max (!(t <= t_min) && !(t >= t_max) lets it through)"}};
    expect_nearest(NONE, NONE, 0, inf, NONE, nan_roots, 1);
    /* near the ends of the range: a tiny root is still after t_min = 0, a huge one before t_max */
    const suspect fixed[] = {{3, "compared with a fixed epsilon instead of t_min"},
                             {0, "no hit: a tiny positive root is after t_min = 0"}};
    expect_nearest((real)1e-30, 3, 0, inf, (real)1e-30, fixed, N(fixed));
    const suspect huge[] = {{(real)2e30, "took the far root"}, {0, "no hit: both roots are before t_max = inf"}};
    expect_nearest((real)2e30, (real)1e30, 0, inf, (real)1e30, huge, N(huge));
    expect_nearest((real)1e30, (real)2e30, (real)1.5e30, inf, (real)2e30, at_min, 1);
}

/* ---- rays that start on the sphere -------------------------------------------
 *
 * f = p - c is a multiple of (2, 3, 6)/7 or (3, 0, 4)/5 with f.f = R^2
 * exactly, so C = 0 and both formulas give the root t = 0 exactly (the
 * stable pair as C / q, the textbook one as -B + sqrt(B^2) with sqrt(B^2) =
 * |B| exactly).  Going in, the hit is the far root t = -2B/A (a few
 * roundings: 8 eps relative); going out there is none. */
static void surface_case(sphere_formula formula)
{
    const struct {
        vec3 c;
        real R;
        vec3 f;
    } spheres[] = {{{(real)0.25, (real)-0.5, 1}, (real)3.5, {1, (real)1.5, 3}},
                   {{(real)-1e4, (real)2e4, (real)0.5}, (real)2.5, {(real)1.5, 0, 2}}};
    const vec3 dirs[] = {{(real)-0.3, (real)-0.2, (real)-0.9}, {(real)0.6, (real)-0.7, (real)-0.2},
                         {(real)0.3, (real)0.25, (real)0.9}, {(real)-0.5, (real)0.8, (real)0.4}};
    for (size_t k = 0; k < N(spheres); k++) {
        const sphere s = {spheres[k].c, spheres[k].R};
        const vec3 p = vec3_add(s.center, spheres[k].f);
        for (size_t m = 0; m < N(dirs); m++) {
            ray r = {p, dirs[m]};
            real B = vec3_dot(r.d, spheres[k].f), A = vec3_dot(r.d, r.d);
            real t = UNWRITTEN;
            vec3 n;
            bool hit = sphere_intersect(&s, r, 0, REAL_INFINITY, formula, &t, &n);
            const char *in = describe("sphere_intersect(%s, (0, inf), %s), p on the sphere, going %s", describe_ray(&s, r),
                                      formula_name(formula), B < 0 ? "in" : "out");
            if (B > 0) {
                if (hit)
                    fail_msg("%s\n    expected no hit\n    got      %s\n    likely mistake: %s", in, describe_t_got(t),
                             t == 0 ? "accepted t == t_min = 0: the window is open" : "a root before t_min taken");
                continue;
            }
            real expected = -2 * B / A;
            if (!hit)
                fail_msg("%s\n    expected t = %.17g (the far root -2B/A)\n    got      no hit\n    likely mistake: "
                         "no hit: going in, the far root -2B/A is the hit (the root t = 0 is t_min, outside the open "
                         "window; README \"The code\")",
                         in, (double)expected);
            const suspect at_start[] = {
                {0, "accepted the root t = 0 == t_min: the ray would hit the sphere where it starts"}};
            assert_close_why(expected, t, 8 * REAL_EPSILON * expected, in, "the far root -2B/A", at_start, N(at_start));
        }
    }
}

static void test_ray_on_surface(void **state)
{
    (void)state;
    surface_case(SPHERE_ROBUST);
    surface_case(SPHERE_TEXTBOOK);
}

/* ---- the normal ---------------------------------------------------------------- */

/* Points near spheres far from the origin.  A hit point is on the sphere only
 * up to rounding, so |x - c| is R only roughly: here x is put 0.1% off the
 * sphere on purpose, and n must still be a unit vector (dividing by the
 * computed length: 4 eps), pointing out of the sphere. */
static void test_normal_unit_far_from_origin(void **state)
{
    (void)state;
    const sphere spheres[] = {{{(real)300.5, (real)-700.25, (real)500.125}, (real)0.5},
                              {{(real)-2e4, (real)3e4, (real)1e4}, (real)1e3},
                              {{0, 0, 0}, (real)1e-3},
                              /* 2^-56 across, under a fixed epsilon such as REAL_EPSILON (squares still
                               * normal numbers in float) */
                              {{(real)ldexp(3, -57), (real)ldexp(-5, -58), (real)ldexp(1, -56)},
                               (real)ldexp(1, -56)}};
    for (size_t k = 0; k < N(spheres); k++) {
        const sphere *s = &spheres[k];
        /* x = c is no hit point (those are R from c), but the division by
         * |x - c| = 0 there is guarded, so that no NaN leaves sphere_normal:
         * the guarded n is x - c = (0, 0, 0). */
        vec3 n0 = sphere_normal(s, s->center);
        if (!vec3_is_finite(n0))
            fail_msg("sphere_normal(c = (%g, %g, %g), R = %g; x = c)\n    expected a vector without NaN, (0, 0, 0) "
                     "from the guard\n    got      (%.17g, %.17g, %.17g)\n    likely mistake: divided by |x - c| "
                     "= 0: check the length before dividing, as the exercise says",
                     (double)s->center.x, (double)s->center.y, (double)s->center.z, (double)s->radius,
                     (double)n0.x, (double)n0.y, (double)n0.z);
        for (int m = 0; m < 27; m++) {
            if (m == 13)
                continue;
            vec3 e = vec3_normalize(vec3_make((real)(m % 3 - 1), (real)(m / 3 % 3 - 1), (real)(m / 9 - 1)));
            vec3 x = vec3_add(s->center, vec3_scale(e, s->radius * (real)1.001));
            vec3 n = sphere_normal(s, x);
            vec3 m_ = vec3_sub(x, s->center);
            const char *in = describe("sphere_normal(c = (%g, %g, %g), R = %g; x = c + 1.001 R (%.4f, %.4f, %.4f))",
                                      (double)s->center.x, (double)s->center.y, (double)s->center.z,
                                      (double)s->radius, (double)e.x, (double)e.y, (double)e.z);
            const suspect_vec3 wrong[] = {
                {vec3_scale(m_, 1 / s->radius), "divided by R: x is on the sphere only up to rounding, so |x - c| is not "
                                                "exactly R; divide by the computed length |x - c|"},
                {vec3_neg(vec3_normalize(m_)), "the normal points inwards: n = (x - c) / |x - c|, not c - x"},
                {vec3_normalize(x), "the centre forgotten: n = (x - c) / |x - c|, not x / |x|"},
                {m_, s->radius < 1e-10 ? "not normalized on a sphere this small: the guard against |x - c| = 0 "
                                         "is a test against 0, a fixed epsilon takes every point of a small "
                                         "sphere for its centre (README, \"Exercises\", normal)"
                                       : "not normalized: n = (x - c) / |x - c|"},
            };
            /* x - c is exact to within eps |c|; its direction then within 4 eps */
            double tol = 4 * REAL_EPSILON * (1 + vec3_max_abs(s->center) / s->radius);
            assert_vec3_why(vec3_normalize(m_), n, tol, describe("%s: n", in), "n = (x - c) / |x - c|", wrong,
                            N(wrong));
            assert_close_why(1, vec3_length(n), 4 * REAL_EPSILON, describe("%s: |n|", in),
                             "n must be a unit vector: divide by |x - c|", NULL, 0);
        }
    }
    /* Spheres of radius 2^k and 2^-k at the origin, k three quarters of the exponent range (2^768 in
     * double, 2^96 in float), whose hits sphere_roots (given) finds at any size: at x = R (0.75, 1, 0),
     * (x - c).(x - c) overflows to infinity or underflows to 0, while vec3_length (common/vec3.h)
     * divides by the largest component first and gives |x - c| = 1.25 R exactly.  Then n = (0.6, 0.8, 0)
     * within two roundings (1 / |x - c|, and the product): 4 eps, as above. */
    const int k = (REAL_EPSILON < 1e-10 ? 1024 : 128) * 3 / 4;
    for (int j = 0; j < 2; j++) {
        const real R = (real)ldexp(1, j ? k : -k);
        const sphere s = {{0, 0, 0}, R};
        const vec3 x = vec3_make((real)0.75 * R, R, 0);
        const char *in = describe("sphere_normal(c = (0, 0, 0), R = 2^%d; x = R (0.75, 1, 0))", j ? k : -k);
        const suspect_vec3 squared[] = {
            {j ? vec3_make(0, 0, 0) : x,
             j ? "|x - c| as sqrt((x - c).(x - c)): the squares overflowed to infinity and n = (x - c) / inf = 0; "
                 "take |x - c| from vec3_length, which divides by the largest component first"
               : "|x - c| as sqrt((x - c).(x - c)): the squares underflowed to 0 and the guard returned x - c; take "
                 "|x - c| from vec3_length, which divides by the largest component first"}};
        assert_vec3_why(vec3_make((real)0.6, (real)0.8, 0), sphere_normal(&s, x), 4 * REAL_EPSILON,
                        describe("%s: n", in), "n = (x - c) / |x - c|, |x - c| without overflow or underflow",
                        squared, N(squared));
    }
}

/* ---- graded tests --------------------------------------------------------- */

static void test_hit(void **state) { (void)state; hit_case(SPHERE_ROBUST); }
static void test_miss(void **state) { (void)state; miss_case(SPHERE_ROBUST); }
static void test_tangent(void **state) { (void)state; tangent_case(SPHERE_ROBUST); }
static void test_origin_inside(void **state) { (void)state; inside_case(SPHERE_ROBUST); }
static void test_sphere_behind(void **state) { (void)state; behind_case(SPHERE_ROBUST); }
static void test_t_window(void **state) { (void)state; window_case(SPHERE_ROBUST); }
static void test_non_unit_d(void **state) { (void)state; scaled_case(SPHERE_ROBUST); }

/* The textbook formula gives the same answers on all of these ordinary cases. */
static void test_textbook(void **state)
{
    (void)state;
    hit_case(SPHERE_TEXTBOOK);
    miss_case(SPHERE_TEXTBOOK);
    tangent_case(SPHERE_TEXTBOOK);
    inside_case(SPHERE_TEXTBOOK);
    behind_case(SPHERE_TEXTBOOK);
    window_case(SPHERE_TEXTBOOK);
    scaled_case(SPHERE_TEXTBOOK);
}

/* Rays from all around a sphere off the origin: n is a unit vector along
 * x - c, pointing against d from outside and along d from inside. */
static void test_outward_normal(void **state)
{
    (void)state;
    const sphere s = {{1, 2, 3}, 2};
    for (int k = 0; k < 27; k++) {
        if (k == 13)
            continue; /* the 26 neighbours of a cell: directions from c, 5 units out, aimed just off c */
        vec3 dir = vec3_make((real)(k % 3 - 1), (real)(k / 3 % 3 - 1), (real)(k / 9 - 1));
        vec3 p = vec3_add(s.center, vec3_scale(vec3_normalize(dir), 5));
        vec3 d = vec3_sub(vec3_add(s.center, vec3_make((real)0.3, (real)-0.2, (real)0.1)), p);
        real t;
        vec3 n;
        const char *in = intersect_hit(&s, (ray){p, d}, SPHERE_ROBUST, NO_HIT_HINT, &t, &n);
        vec3 x = ray_at((ray){p, d}, t);
        expect_unit_normal(in, n, s.radius);
        const vec3 out = vec3_scale(vec3_sub(x, s.center), 1 / s.radius);
        const suspect_vec3 wrong[] = {{vec3_neg(out), "the normal points inwards: n = (x - c) / |x - c|, not c - x"},
                                      {vec3_sub(x, s.center), "not normalized: n = (x - c) / |x - c|"},
                                      {vec3_normalize(x), "the centre forgotten: n = (x - c) / |x - c|, not x / |x|"}};
        assert_vec3_why(out, n, 32 * REAL_EPSILON, describe("%s: n at x = p + t d, t = %.17g", in, (double)t),
                        "n = (x - c) / |x - c|", wrong, N(wrong));
        const double near = root_expected(&s, (ray){p, d}, 0);
        assert_true_why(vec3_dot(n, d) < 0,
                        "%s: n.d\n    expected < 0: from outside the ray enters the sphere at the hit, n facing it\n"
                        "    got      %.17g at t = %.17g (the entry is at t = %.17g)\n    likely mistake: %s",
                        in, (double)vec3_dot(n, d), (double)t, near,
                        fabs((double)t - near) > 1e-3 * near
                            ? "took the far root, where the ray leaves: the nearest root inside (t_min, t_max) is the "
                              "hit (README, \"The code\")"
                            : "the normal points inwards: n = (x - c) / |x - c|, not c - x");
        /* from the centre outwards: the exit point, normal along d */
        in = intersect_hit(&s, (ray){s.center, vec3_neg(d)}, SPHERE_ROBUST,
                           "from the centre (C = -R^2 < 0) the near root is behind p, before t_min = 0: the hit is the "
                           "far root (README, \"The code\")",
                           &t, &n);
        assert_true_why(vec3_dot(n, vec3_neg(d)) > 0,
                        "%s: n.d\n    expected > 0: from inside the ray leaves the sphere, and the outward normal "
                        "points along d\n    got      %.17g, n = (%.17g, %.17g, %.17g) at t = %.17g\n"
                        "    likely mistake: n = (x - c) / |x - c| points out of the sphere from whichever side the "
                        "ray comes: not c - x, and not turned to face the ray",
                        in, (double)vec3_dot(n, vec3_neg(d)), (double)n.x, (double)n.y, (double)n.z, (double)t);
        expect_unit_normal(in, n, s.radius);
    }
}

/* ---- far, small spheres ----------------------------------------------------
 *
 * A sphere of radius R at distance D = |c - p| from p, for D/R from 10 up,
 * and rays aimed at offsets o R from its centre (o < 1: clearly inside the
 * silhouette, o > 1: clearly outside).  The robust formula must classify
 * every ray right and put every hit point on the sphere.  The bound, to first
 * order, with u = REAL_EPSILON / 2 the unit roundoff (a dot product of three
 * terms errs by at most 3u times the sum of the terms' magnitudes):
 *  - f = p - c rounds once per component: |df| <= u D.
 *  - A = d.d and B = d.f carry 3u relative to |d|^2 and |d| D; B/A carries
 *    about 7u relative to D/|d|, and (B/A) d one more u.
 *  - l = f - (B/A) d subtracts two vectors of length about D and leaves one
 *    of length o R, so those errors survive as absolute errors:
 *    |dl| <~ (1 + 7 + 1 + 1) u D = 5 eps D.
 *  - Hence |d(R^2 - l.l)| <~ 2 |l| |dl| = 10 o eps D R.
 * Classification: the sign of R^2 - l.l is right while |1 - o^2| > 10 o eps D/R
 *   (plus about eps D/R for rounding the aim point c + o R e, which moves the
 *   ray itself by that much).  At o = 0.9 and 1.1 the left side is 0.19 and
 *   0.21; with eps D/R <= 1/256 (below) the right side is at most 0.05.
 * Hit point: dl moves the ray sideways by 5 eps D at most, which moves the hit
 *   point off the sphere by at most as much (the root's sensitivity
 *   1/sqrt(disc) is cancelled by the cosine of the grazing angle).  C, B, q and
 *   the division add about 5 eps relative to t, 5 eps D along the ray, and
 *   forming x = p + t d and the check's own |x - c| about 2 eps S, where
 *   S = |p| + |c| + R >= D bounds every coordinate involved.  In all about
 *   12 eps S: the tolerance is 16 eps S.
 * The limit: "on the sphere" means something while the tolerance is a small
 *   part of R, say 16 eps S <= R / 16, i.e. D/R <= 1 / (256 eps): 1.8e13 for
 *   double, 3.3e4 for float.  So double is swept to 1e8 and float to 1e4.
 *   (Float cannot go much further in any formula: near 1e8 the spacing of
 *   floats is 8, so the centre of a sphere of radius 1 at distance 1e8 cannot
 *   even be placed to within its own radius.)
 *
 * The textbook formula is measured on the same rays and its counts printed,
 * not asserted: B^2 and A C are both about |d|^2 D^2 and their difference,
 * |d|^2 (R^2 - l.l), is lost once eps (D/R)^2 approaches 1, i.e. from D/R
 * about 1/sqrt(eps): 2900 in float, 6.7e7 in double. */

enum { N_ANGLES = 32 };
static const real offsets[] = {0, 0.25, 0.5, 0.75, 0.9, 1.1, 1.25, 1.5, 2, 4};
#define N_OFFSETS (int)(sizeof offsets / sizeof offsets[0])

typedef struct {
    int rays, wrong, off_sphere; /* misclassified rays; hits off the sphere by more than the tolerance */
    double worst;                /* the largest | |x - c| - R | of a right hit, in units of eps S */
    double worst_r;              /* the same, in units of R */
} tally;

static tally sweep(real ratio, sphere_formula formula)
{
    tally out = {0, 0, 0, 0, 0};
    const vec3 p = {0.25, -0.5, 0.125};
    const vec3 w = vec3_normalize(vec3_make(2, 3, -6));
    const vec3 e1 = vec3_normalize(vec3_make(3, -2, 0)); /* e1, e2, w orthonormal */
    const vec3 e2 = vec3_cross(w, e1);
    const sphere s = {vec3_add(p, vec3_scale(w, ratio * (real)0.75)), 0.75};
    const real S = vec3_length(p) + vec3_length(s.center) + s.radius;
    for (int k = 0; k < N_OFFSETS; k++)
        for (int a = 0; a < N_ANGLES; a++) {
            double angle = 2 * 3.14159265358979323846 * (a + 0.5) / N_ANGLES;
            vec3 e = vec3_add(vec3_scale(e1, (real)cos(angle)), vec3_scale(e2, (real)sin(angle)));
            ray r = {p, vec3_sub(vec3_add(s.center, vec3_scale(e, offsets[k] * s.radius)), p)};
            real t;
            vec3 n;
            bool hit = sphere_intersect(&s, r, 0, REAL_INFINITY, formula, &t, &n);
            out.rays++;
            if (hit != (offsets[k] < 1)) {
                out.wrong++;
                continue;
            }
            if (!hit)
                continue;
            double error = fabs((double)vec3_length(vec3_sub(ray_at(r, t), s.center)) - (double)s.radius);
            bool near_side = vec3_dot(n, r.d) < 0 && t > 0;
            if (!(error <= 16 * REAL_EPSILON * S) || !near_side)
                out.off_sphere++;
            out.worst = fmax(out.worst, error / (REAL_EPSILON * S));
            out.worst_r = fmax(out.worst_r, error / s.radius);
        }
    return out;
}

static void test_far_spheres(void **state)
{
    (void)state;
    for (double ratio = 10; ratio <= 1.0001e8 && REAL_EPSILON * ratio <= 1.0 / 256; ratio *= 3.1622776601683795) {
        tally robust = sweep((real)ratio, SPHERE_ROBUST);
        tally textbook = sweep((real)ratio, SPHERE_TEXTBOOK);
        print_message("D/R = %7.2g: robust %d wrong, %d off, worst %.2f eps S = %.1e R; "
                      "textbook %3d of %d wrong, %3d off, worst %.1e R\n",
                      ratio, robust.wrong, robust.off_sphere, robust.worst, robust.worst_r, textbook.wrong,
                      textbook.rays, textbook.off_sphere, textbook.worst_r);
        if (robust.wrong || robust.off_sphere)
            fail_msg("D/R = %g: the robust formula classified %d of %d rays wrong and put %d hits off the sphere",
                     ratio, robust.wrong, robust.rays, robust.off_sphere);
    }
}

static const graded_test tests[] = {
    GRADED(test_roots_robust, 2),
    GRADED(test_roots_textbook, 2),
    GRADED(test_b_zero_sign, 2),
    GRADED(test_small_root_near_surface, 2),
    GRADED(test_tangent_rays_from_the_surface, 2),
    GRADED(test_roots_at_any_scale, 0), /* sphere_roots is given: no points */
    GRADED(test_nearest_root, 3),
    GRADED(test_ray_on_surface, 2),
    GRADED(test_normal_unit_far_from_origin, 2),
    GRADED(test_hit, 2),
    GRADED(test_miss, 1),
    GRADED(test_tangent, 1),
    GRADED(test_origin_inside, 2),
    GRADED(test_sphere_behind, 1),
    GRADED(test_t_window, 2),
    GRADED(test_non_unit_d, 2),
    GRADED(test_outward_normal, 2),
    GRADED(test_textbook, 3),
    GRADED(test_far_spheres, 4),
};
SUITE_MAIN("02_sphere", tests)
