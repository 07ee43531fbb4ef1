/* test_03_triangle.c - chapter 03: ray-triangle intersection.
 *
 * Most tests run both triangle tests, Cramer's rule (the exercise) and the
 * watertight one: they must agree wherever the answer is not decided by
 * rounding.
 *
 * Tolerances.  Each determinant det3 is a sum of six products of
 * differences: with every input of size ~ s, it carries an absolute error of
 * a few (< 8) epsilon * s^3 on a value that, for the well-shaped triangles
 * below, is itself ~ s^3.  beta, gamma and t are ratios of two such
 * determinants, so their relative error is at most ~ 16 epsilon; the data
 * that the tests compute (a target point, a direction) add a few epsilon
 * more.  TOL = 32 REAL_EPSILON covers this with room.  Where a test loses
 * accuracy on purpose (a grazing ray, a triangle far from the origin) its
 * tolerance is TOL times the factor by which the data amplify errors, said
 * there.  Tests whose data are small dyadic numbers compute exactly and
 * check exact values.
 */
#include <math.h>
#include <stdint.h>

#include "suite.h"

#include "crossing.h"
#include "03_triangle/lab/crossing_reference.h"
#include "03_triangle/lab/degenerate_count.h"
#include "03_triangle/scenes/icosahedron.h"
#include "03_triangle/triangle.h"

#define TOL (32 * REAL_EPSILON)

static const triangle_test both[] = {TRIANGLE_CRAMER, TRIANGLE_WATERTIGHT};
static const char *const test_names[] = {"cramer", "watertight"};
enum { N_TESTS = 2 };

/* A well-shaped triangle, not aligned with any axis. */
static const triangle tilted = {{1, 2, 3}, {4, -1, 2}, {-2, 0, 5}};

static vec3 centroid(const triangle *tri)
{
    return vec3_scale(vec3_add(tri->a, vec3_add(tri->b, tri->c)), (real)1 / 3);
}

/* The point of tri with barycentric coordinates (beta, gamma). */
static vec3 point_at(const triangle *tri, real beta, real gamma)
{
    return vec3_add(tri->a, vec3_add(vec3_scale(vec3_sub(tri->b, tri->a), beta),
                                     vec3_scale(vec3_sub(tri->c, tri->a), gamma)));
}

/* The input of a check: the triangle and the ray. */
static const char *describe_input(const triangle *tri, ray r)
{
    return describe("a (%.9g, %.9g, %.9g), b (%.9g, %.9g, %.9g), c (%.9g, %.9g, %.9g); ray p (%.9g, %.9g, %.9g), "
                    "d (%.9g, %.9g, %.9g)",
                    (double)tri->a.x, (double)tri->a.y, (double)tri->a.z, (double)tri->b.x, (double)tri->b.y,
                    (double)tri->b.z, (double)tri->c.x, (double)tri->c.y, (double)tri->c.z, (double)r.p.x,
                    (double)r.p.y, (double)r.p.z, (double)r.d.x, (double)r.d.y, (double)r.d.z);
}

static void print_triangle(const char *what, const triangle *tri, ray r)
{
    print_error("%s: %s\n", what, describe_input(tri, r));
}

/* What *hit holds before a test that may leave it alone: a hit that leaves
 * it so is named as such, never printed as a t, beta and gamma got. */
#define UNWRITTEN_HIT {-7, -7, -7}
static bool unwritten(triangle_hit h) { return h.t == -7 && h.beta == -7 && h.gamma == -7; }
static const char not_written[] = "returned true without writing *hit: a hit writes *hit = (t, beta, gamma), a miss "
                                  "returns false and leaves it alone";

/* What a triangle test gave: a miss, a hit that left *hit unwritten, or the
 * hit's t, beta and gamma (%a: bit for bit). */
static const char *describe_got(bool hit, triangle_hit h, bool bits)
{
    if (!hit)
        return "a miss";
    if (unwritten(h))
        return "a hit, but *hit not written";
    return bits ? describe("t %a, beta %a, gamma %a", (double)h.t, (double)h.beta, (double)h.gamma)
                : describe("t %.9g, beta %.9g, gamma %.9g", (double)h.t, (double)h.beta, (double)h.gamma);
}

/* The likely mistake behind a hit that should have been a miss, from what
 * came back: which of the window's or the edges' comparisons let it in. */
static const char *false_hit_mistake(triangle_hit h, real t_min, real t_max)
{
    if (unwritten(h))
        return not_written;
    if (h.t == t_min)
        return "accepted t == t_min: the window (t_min, t_max) is open, t > t_min";
    if (h.t == t_max)
        return "accepted t == t_max: the window (t_min, t_max) is open, t < t_max";
    if (!(h.t > t_min && h.t < t_max))
        return "t outside the window accepted: the hit needs t_min < t < t_max";
    if (h.beta < 0 || h.gamma < 0)
        return "a negative beta or gamma accepted: the point is outside the edge ab or ac, test beta >= 0 and "
               "gamma >= 0";
    if (h.beta + h.gamma > 1)
        return "beta + gamma > 1 accepted: the point is beyond the edge bc, test beta + gamma <= 1 (beta <= 1 and "
               "gamma <= 1 are not enough)";
    /* t, beta and gamma all in range for a point outside: they are not this point's */
    return "a point outside reported with t, beta and gamma in range: a column of a determinant of the wrong sign or "
           "order, M not checked, or a comparison that lets t == t_min, t == t_max or a point outside an edge "
           "through";
}

/* The likely mistake behind a miss where (beta, gamma) is a hit. */
static const char *lost_hit_mistake(real beta, real gamma)
{
    if (beta == 0 || gamma == 0 || beta + gamma == 1)
        return "the edges are open: a point on an edge (beta = 0, gamma = 0 or beta + gamma = 1) is a hit, "
               "compare with >= 0 and <= 1";
    /* inside, away from the edges: a sign, not an edge's comparison */
    return "a point inside missed: t, beta or gamma came out with the wrong sign, from a column of the wrong sign "
           "or order (each unknown's column of [a - b, a - c, d] replaced by a - p, README \"The intersection: "
           "three equations, three unknowns\"), or a comparison of the window or the edges the wrong way round";
}

/* Asserts a hit of r at (t, beta, gamma) within tol; on failure prints the
 * triangle, the ray, what was expected, what came back and the likely
 * mistake. */
static void expect_hit(const triangle *tri, ray r, triangle_test test, real t, real beta, real gamma, real tol)
{
    triangle_hit h = UNWRITTEN_HIT;
    if (!triangle_intersect(tri, r, 0, REAL_INFINITY, test, &h)) {
        print_triangle("input", tri, r);
        fail_msg("--triangle=%s: expected a hit at t %g, beta %g, gamma %g; got a miss\n    likely mistake: %s",
                 test_names[test], (double)t, (double)beta, (double)gamma, lost_hit_mistake(beta, gamma));
    }
    real t_tol = tol * real_fmax(1, real_abs(t));
    if (!(real_abs(h.t - t) <= t_tol && real_abs(h.beta - beta) <= tol && real_abs(h.gamma - gamma) <= tol)) {
        print_triangle("input", tri, r);
        bool swapped = real_abs(h.beta - gamma) <= tol && real_abs(h.gamma - beta) <= tol;
        fail_msg("--triangle=%s: expected t %.9g, beta %.9g, gamma %.9g (tolerance %g); got %s\n    likely mistake: %s",
                 test_names[test], (double)t, (double)beta, (double)gamma, (double)tol, describe_got(true, h, false),
                 unwritten(h) ? not_written
                 : swapped    ? "beta and gamma swapped: beta goes with b - a, gamma with c - a"
                              : "a column of a determinant replaced by the wrong vector, or beta and gamma swapped");
    }
}

/* Asserts a miss that leaves *hit untouched. */
static void expect_miss(const triangle *tri, ray r, real t_min, real t_max, triangle_test test)
{
    triangle_hit h = UNWRITTEN_HIT;
    if (triangle_intersect(tri, r, t_min, t_max, test, &h)) {
        print_triangle("input", tri, r);
        fail_msg("--triangle=%s: window (%g, %g): expected a miss, got %s\n"
                 "    likely mistake: %s",
                 test_names[test], (double)t_min, (double)t_max, describe_got(true, h, false),
                 false_hit_mistake(h, t_min, t_max));
    }
    if (!unwritten(h))
        fail_msg("--triangle=%s: a miss wrote into *hit (t %g): write it only on a hit", test_names[test],
                 (double)h.t);
}

/* assert_true(triangle_intersect(tri, r, t_min, t_max, test, h)), the same
 * record; a miss fails naming the input, the hit expected (`where`) and the
 * likely mistake. */
static void expect_hit_in(const triangle *tri, ray r, real t_min, real t_max, triangle_test test, const char *where,
                          const char *mistake, triangle_hit *h)
{
    assert_true_why(triangle_intersect(tri, r, t_min, t_max, test, h),
                    "--triangle=%s, window (%g, %g): %s\n    expected a hit %s\n    got      a miss\n"
                    "    likely mistake: %s",
                    test_names[test], (double)t_min, (double)t_max, describe_input(tri, r), where, mistake);
}

/* assert_true(h.t == t) of the hit h of exact data, the same record. */
static void expect_t_exactly(const triangle *tri, ray r, real t_min, real t_max, triangle_test test, triangle_hit h,
                             real t)
{
    assert_true_why(
        h.t == t,
        "--triangle=%s, window (%g, %g): %s\n    expected t = %g exactly (small dyadic data: every "
        "determinant is exact)\n    got      %s\n    likely mistake: %s",
        test_names[test], (double)t_min, (double)t_max, describe_input(tri, r), (double)t, describe_got(true, h, false),
        unwritten(h) ? not_written
                     : "t = det[a - b, a - c, a - p] / M: a column of t's determinant replaced by the wrong "
                       "vector (README, \"The intersection: three equations, three unknowns\")");
}

/* assert_true(det3(c0, c1, c2) == expected), the same record. */
static void expect_det3(vec3 c0, vec3 c1, vec3 c2, real expected)
{
    const real got = det3(c0, c1, c2);
    assert_true_why(got == expected,
                    "det3((%g, %g, %g), (%g, %g, %g), (%g, %g, %g))\n    expected %g\n    got      %.17g\n"
                    "    likely mistake: %s",
                    (double)c0.x, (double)c0.y, (double)c0.z, (double)c1.x, (double)c1.y, (double)c1.z, (double)c2.x,
                    (double)c2.y, (double)c2.z, (double)expected, (double)got,
                    got == -expected ? "det3 is given: det[c0 c1 c2] = c0 . (c1 x c2), not c0 . (c2 x c1) (README, "
                                       "\"The intersection: three equations, three unknowns\")"
                                     : "det3 is given: det[c0 c1 c2] = c0 . (c1 x c2), the scalar triple product "
                                       "(README, \"The intersection: three equations, three unknowns\")");
}

/* det[c0 c1 c2] of the identity is 1; swapping two columns changes its sign. */
static void test_det3(void **state)
{
    (void)state;
    vec3 x = {1, 0, 0}, y = {0, 1, 0}, z = {0, 0, 1};
    expect_det3(x, y, z, 1);
    expect_det3(y, x, z, -1);
    expect_det3(vec3_make(1, 2, 3), vec3_make(4, 5, 6), vec3_make(7, 8, 10), -3);
}

/* The ray through the centroid: alpha = beta = gamma = 1/3, from either side. */
static void test_centroid(void **state)
{
    (void)state;
    vec3 g = centroid(&tilted);
    vec3 front = vec3_add(g, vec3_scale(triangle_normal(&tilted), 5));
    vec3 back = vec3_sub(g, vec3_make(0.5, 7, -3));
    for (int k = 0; k < N_TESTS; k++) {
        expect_hit(&tilted, (ray){front, vec3_sub(g, front)}, both[k], 1, (real)1 / 3, (real)1 / 3, TOL);
        expect_hit(&tilted, (ray){back, vec3_sub(g, back)}, both[k], 1, (real)1 / 3, (real)1 / 3, TOL);
        /* t scales with 1 / |d|: the same ray with d halved meets the triangle at t = 2. */
        expect_hit(&tilted, (ray){front, vec3_scale(vec3_sub(g, front), (real)0.5)}, both[k], 2, (real)1 / 3,
                   (real)1 / 3, TOL);
    }
}

/* A triangle in the plane z = 2 and an origin at z = 10: every direction to
 * a vertex or an edge midpoint has d_z = -8 and small dyadic components, so
 * both tests compute exactly and the closed edges must be hit. */
static const triangle flat = {{1, 1, 2}, {5, 2, 2}, {2, 6, 2}};
static const vec3 above = {0.5, 0.25, 10};

static void test_vertices_and_edge_midpoints(void **state)
{
    (void)state;
    const struct {
        real beta, gamma;
    } targets[] = {
        {0, 0}, {1, 0}, {0, 1},                 /* the vertices a, b, c */
        {0.5, 0}, {0.5, 0.5}, {0, 0.5},         /* the midpoints of ab, bc, ca */
        {0.25, 0}, {0.75, 0.25}, {0, 0.125},    /* other points on the edges */
    };
    for (int k = 0; k < N_TESTS; k++)
        for (size_t j = 0; j < sizeof targets / sizeof targets[0]; j++) {
            vec3 x = point_at(&flat, targets[j].beta, targets[j].gamma);
            expect_hit(&flat, (ray){above, vec3_sub(x, above)}, both[k], 1, targets[j].beta, targets[j].gamma, 0);
        }
}

/* Just outside each edge, by 1/64 of the triangle: a miss; just inside: a hit. */
static void test_just_outside(void **state)
{
    (void)state;
    const real out = (real)-1 / 64, in = (real)1 / 64;
    const struct {
        real beta, gamma;
    } outside[] = {{0.5, out}, {out, 0.5}, {0.5 - out, 0.5}, {out, out}, {1 - out, 0}},
      inside[] = {{0.5, in}, {in, 0.5}, {0.5 - in, 0.5}, {in, in}, {1 - 2 * in, in}};
    for (int k = 0; k < N_TESTS; k++)
        for (size_t j = 0; j < sizeof outside / sizeof outside[0]; j++) {
            vec3 x = point_at(&flat, outside[j].beta, outside[j].gamma);
            expect_miss(&flat, (ray){above, vec3_sub(x, above)}, 0, REAL_INFINITY, both[k]);
            x = point_at(&flat, inside[j].beta, inside[j].gamma);
            expect_hit(&flat, (ray){above, vec3_sub(x, above)}, both[k], 1, inside[j].beta, inside[j].gamma, 0);
        }
    /* Outside an edge by a hair, 4096 eps in beta or gamma: the rounding of
     * x (coordinates up to 6) and of the three determinants moves beta and
     * gamma by tens of eps, so these are misses; a tolerance in the edge
     * comparisons (beta >= -1e-6) takes them for hits. */
    const real hair = 4096 * REAL_EPSILON;
    const struct {
        real beta, gamma;
    } barely[] = {{0.5, -hair}, {-hair, 0.5}, {0.5 + hair, 0.5}};
    for (int k = 0; k < N_TESTS; k++)
        for (size_t j = 0; j < sizeof barely / sizeof barely[0]; j++) {
            const ray r = {above, vec3_sub(point_at(&flat, barely[j].beta, barely[j].gamma), above)};
            triangle_hit h = UNWRITTEN_HIT;
            const bool hit = triangle_intersect(&flat, r, 0, REAL_INFINITY, both[k], &h);
            if (hit)
                print_triangle("input", &flat, r);
            assert_true_why(!hit,
                            "--triangle=%s: the point beta %.17g, gamma %.17g, outside an edge by 4096 eps\n    "
                            "expected a miss\n    got      %s\n    likely mistake: a tolerance in the edge test "
                            "(beta >= -epsilon): the edges are closed but exact, beta >= 0, gamma >= 0, "
                            "beta + gamma <= 1",
                            test_names[both[k]], (double)barely[j].beta, (double)barely[j].gamma,
                            describe_got(true, h, false));
        }
}

/* A ray parallel to the plane, beside it or in it: M = 0, a miss, no division. */
static void test_parallel_ray(void **state)
{
    (void)state;
    vec3 along = vec3_sub(flat.b, flat.a);
    for (int k = 0; k < N_TESTS; k++) {
        expect_miss(&flat, (ray){vec3_make(0, 0, 3), along}, 0, REAL_INFINITY, both[k]);      /* beside */
        expect_miss(&flat, (ray){vec3_make(0, 1.5, 2), along}, 0, REAL_INFINITY, both[k]);    /* in the plane */
        expect_miss(&tilted, (ray){tilted.a, vec3_sub(tilted.c, tilted.b)}, -1, 1, both[k]); /* in the plane */
        /* ... while a ray that leaves the plane by the least amount hits. */
        vec3 x = point_at(&flat, (real)0.25, (real)0.25);
        vec3 p = vec3_add(x, vec3_make(-8, 0, (real)1 / 1024));
        expect_hit(&flat, (ray){p, vec3_sub(x, p)}, both[k], 1, (real)0.25, (real)0.25, 0);
    }
}

/* The exercise on its own (triangle_cramer: no check of crossing.h after
 * it, which would hide these): where cramer cannot divide, or its data are
 * not numbers, it answers false and leaves *hit alone.  A NaN or infinite
 * coordinate of p leaves M finite (M does not involve p) and makes t, beta
 * and gamma NaN or infinite: comparisons written so that a NaN passes them
 * (t <= t_min || t >= t_max) take such a ray for a hit. */
static void test_cramer_alone_rejects_what_it_cannot_solve(void **state)
{
    (void)state;
    const real nan = (real)NAN, inf = REAL_INFINITY;
    const vec3 x = point_at(&flat, (real)0.25, (real)0.25), d = vec3_sub(x, above);
    const triangle collinear = {{1, 1, 2}, {3, 2, 2}, {5, 3, 2}};
    const char *nan_passes = "a NaN t, beta or gamma passed a comparison: write them so that a NaN fails, "
                             "!(t > t_min && t < t_max), !(beta >= 0 && ...)";
    const char *m_unchecked = "M not checked before dividing: return false when M == 0 or M is not finite";
    /* M = 10 (REAL_MAX / 2) overflows where the numerators do not: t, beta and gamma come out +-0, and a
     * window that holds t = 0 would take them for a hit on a vertex */
    const triangle wide = {{0, 0, 0}, {10, 0, 0}, {0, 1, 0}};
    const ray steep = {{(real)-0.005, (real)-0.005, -1}, {0, 0, REAL_MAX / 2}};
    const struct {
        const triangle *tri;
        ray r;
        real t_min;
        const char *what, *mistake;
    } cases[] = {
        {&flat, {{nan, above.y, above.z}, d}, 0, "p = (NaN, 0.25, 10)", nan_passes},
        {&flat, {{above.x, nan, above.z}, d}, 0, "p = (0.5, NaN, 10)", nan_passes},
        {&flat, {{above.x, above.y, inf}, d}, 0, "p = (0.5, 0.25, inf)", nan_passes},
        {&flat, {{above.x, -inf, above.z}, d}, 0, "p = (0.5, -inf, 10)", nan_passes},
        {&flat, {above, {d.x, d.y, nan}}, 0, "d = (.., .., NaN): M is NaN", m_unchecked},
        {&flat, {above, {inf, d.y, d.z}}, 0, "d = (inf, .., ..): M is not finite", m_unchecked},
        {&flat, {vec3_make(0, 0, 3), vec3_sub(flat.b, flat.a)}, 0, "d parallel to the plane: M = 0", m_unchecked},
        {&collinear, {above, vec3_sub(collinear.b, above)}, 0, "collinear vertices: M = 0", m_unchecked},
        {&wide, steep, -1, "d = (0, 0, REAL_MAX / 2): M overflows to inf, t, beta and gamma are +-0", m_unchecked},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        triangle_hit h = {-7, -7, -7};
        const bool hit = triangle_cramer(cases[k].tri, cases[k].r, cases[k].t_min, inf, &h);
        if (hit || !(h.t == -7 && h.beta == -7 && h.gamma == -7)) {
            print_triangle("input", cases[k].tri, cases[k].r);
            fail_msg("cramer, window (%g, inf), %s\n    expected false, *hit untouched\n    got      %s%s\n"
                     "    likely mistake: %s",
                     (double)cases[k].t_min, cases[k].what, hit ? "true" : "false, but *hit written: ",
                     hit ? (unwritten(h) ? ", *hit not written" : describe(", %s", describe_got(true, h, false)))
                         : describe_got(true, h, false),
                     cases[k].mistake);
        }
    }
    /* ... and the same ray from a finite origin is a hit, at beta = gamma = 1/4. */
    triangle_hit h = UNWRITTEN_HIT;
    const ray finite = {above, d};
    const char *in = describe("cramer(%s), window (0, inf)", describe_input(&flat, finite));
    assert_true_why(triangle_cramer(&flat, finite, 0, inf, &h),
                    "%s\n    expected true, a hit at t 1, beta 0.25, gamma 0.25\n    got      false\n"
                    "    likely mistake: %s",
                    in, lost_hit_mistake((real)0.25, (real)0.25));
    if (unwritten(h))
        fail_msg("%s\n    expected t 1, beta 0.25, gamma 0.25\n    got      true, but *hit not written\n"
                 "    likely mistake: %s",
                 in, not_written);
    const char *where = "(README, \"The intersection: three equations, three unknowns\")";
    assert_close_why(1, h.t, TOL, describe("%s: t", in), describe("t = det[a - b, a - c, a - p] / M %s", where), NULL,
                     0);
    assert_close_why(0.25, h.beta, TOL, describe("%s: beta", in), describe("beta = det[a - p, a - c, d] / M %s", where),
                     NULL, 0);
    assert_close_why(0.25, h.gamma, TOL, describe("%s: gamma", in),
                     describe("gamma = det[a - b, a - p, d] / M %s", where), NULL, 0);
}

/* d may have any length (ray.h): triangle_intersect (given) scales a d of
 * extreme length by a power of two first, which changes no digit, so d 2^e
 * gives the hit of d with t / 2^e, bit for bit, beta and gamma the same,
 * for e from one end of the exponent range to the other. */
static void test_any_length_of_d(void **state)
{
    (void)state;
    /* |d| near 2^top times 10: representable, but M (d times two edges of
     * about 5) is not, unless d is scaled first */
    const int top = REAL_EPSILON < 1e-10 ? 1018 : 122;
    const int exps[] = {-top, -top / 2, -20, 20, top / 2, top};
    const vec3 x = point_at(&tilted, (real)0.3, (real)0.45), p = vec3_make(-3, 7, 9);
    for (int k = 0; k < N_TESTS; k++) {
        triangle_hit h1 = UNWRITTEN_HIT;
        expect_hit_in(&tilted, (ray){p, vec3_sub(x, p)}, 0, REAL_INFINITY, both[k], "at t 1, beta 0.3, gamma 0.45",
                      lost_hit_mistake((real)0.3, (real)0.45), &h1);
        for (size_t j = 0; j < sizeof exps / sizeof exps[0]; j++) {
            triangle_hit h = {-7, -7, -7};
            const ray r = {p, vec3_scale(vec3_sub(x, p), (real)ldexp(1, exps[j]))};
            const bool hit = triangle_intersect(&tilted, r, 0, REAL_INFINITY, both[k], &h);
            if (!hit || h.t != (real)ldexp(h1.t, -exps[j]) || h.beta != h1.beta || h.gamma != h1.gamma)
                fail_msg("--triangle=%s: d scaled by 2^%d\n    expected a hit at t %a (t of the unscaled d / 2^%d), "
                         "beta %a, gamma %a\n    got      %s\n    likely mistake: "
                         "triangle_intersect is given; the products with d overflowed or underflowed",
                         test_names[both[k]], exps[j], (double)ldexp(h1.t, -exps[j]), exps[j], (double)h1.beta,
                         (double)h1.gamma, describe_got(hit, h, true));
            /* the window scales with t: open at both ends, exactly at the hit's t */
            const real t = h.t;
            expect_miss(&tilted, r, 0, t, both[k]);
            expect_miss(&tilted, r, t, REAL_INFINITY, both[k]);
            expect_hit_in(&tilted, r, t / 2, t * 2, both[k], describe("at t %a, d scaled by 2^%d", (double)t, exps[j]),
                          "the window: the hit needs t_min < t < t_max with the caller's t_min and t_max "
                          "(triangle_intersect, given, scales them with d)",
                          &h);
        }
    }
    /* A hit near the top of the float range: a small triangle (edges about
     * 2^-11, so that Cramer's products stay finite) in the plane x = 2^126;
     * the ray from x = -2^127 along d = (2^126, 0, 0) meets it at t = 3
     * exactly, which a d scaled all the way down to about 1 would turn into
     * 3 2^127, beyond the largest float.  (The same scene in double, at 2^1022,
     * is beyond the range of the degeneracy check of crossing.h, which
     * scales the coordinates to 1 in double: edges of 2^-11 would fall below
     * the normal doubles.  In double the check stays at 2^126, where it only
     * confirms the hit.) */
    const int top_exp = 128;
    const real x0 = (real)ldexp(1, top_exp - 2), e = (real)ldexp(0.75, -12);
    const triangle far = {{x0, -e, -e}, {x0, e, -e}, {x0, 0, e}};
    const ray r = {{(real)-ldexp(1, top_exp - 1), 0, 0}, {x0, 0, 0}};
    for (int k = 0; k < N_TESTS; k++) {
        triangle_hit h = UNWRITTEN_HIT;
        const bool hit = triangle_intersect(&far, r, 0, REAL_INFINITY, both[k], &h);
        if (!hit || h.t != 3)
            fail_msg("--triangle=%s: the plane x = 2^%d, p = (-2^%d, 0, 0), d = (2^%d, 0, 0)\n    expected a hit at t "
                     "3\n    got      %s\n    likely mistake: triangle_intersect is given; d scaled further than "
                     "needed, so that t overflowed",
                     test_names[both[k]], top_exp - 2, top_exp - 1, top_exp - 2, describe_got(hit, h, true));
    }
}

/* Collinear and coincident vertices span no plane: a miss, no NaN, and no normal. */
static void test_degenerate_triangles(void **state)
{
    (void)state;
    const triangle degenerate[] = {
        {{1, 1, 2}, {3, 2, 2}, {5, 3, 2}}, /* collinear */
        {{1, 1, 2}, {5, 3, 2}, {3, 2, 2}}, /* collinear, the middle one last */
        {{1, 1, 2}, {1, 1, 2}, {5, 3, 2}}, /* two coincide */
        {{3, 2, 2}, {3, 2, 2}, {3, 2, 2}}, /* all three coincide */
        {{1, 1, 2}, {3, 2, 1}, {5, 3, 0}}, /* collinear, across the ray's direction */
    };
    for (int k = 0; k < N_TESTS; k++)
        for (size_t j = 0; j < sizeof degenerate / sizeof degenerate[0]; j++) {
            const triangle *tri = &degenerate[j];
            vec3 targets[] = {tri->a, tri->b, tri->c, vec3_scale(vec3_add(tri->a, tri->c), 0.5)};
            for (int i = 0; i < 4; i++)
                expect_miss(tri, (ray){above, vec3_sub(targets[i], above)}, 0, REAL_INFINITY, both[k]);
            const vec3 n = triangle_normal(tri);
            assert_true_why(vec3_length(n) == 0,
                            "triangle_normal(a (%g, %g, %g), b (%g, %g, %g), c (%g, %g, %g)), a degenerate triangle\n"
                            "    expected (0, 0, 0): no plane, no normal\n    got      (%.17g, %.17g, %.17g)\n"
                            "    likely mistake: triangle_normal is given: it returns the zero vector when "
                            "(b - a) x (c - a) is 0 (collinear or coincident vertices), never a normalized 0",
                            (double)tri->a.x, (double)tri->a.y, (double)tri->a.z, (double)tri->b.x, (double)tri->b.y,
                            (double)tri->b.z, (double)tri->c.x, (double)tri->c.y, (double)tri->c.z, (double)n.x,
                            (double)n.y, (double)n.z);
        }
    /* Moving one vertex of the first by 1/8 makes it a triangle: now it is hit. */
    const triangle sliver = {{1, 1, 2}, {3, (real)2.125, 2}, {5, 3, 2}};
    vec3 x = point_at(&sliver, (real)0.5, (real)0.25);
    for (int k = 0; k < N_TESTS; k++)
        expect_hit(&sliver, (ray){above, vec3_sub(x, above)}, both[k], 1, (real)0.5, (real)0.25, 0);
}

/* A triangle with legs of 1e-6 one unit away is hit like any other: no
 * absolute epsilon on the determinant (here ~ 1e-12) may make it vanish.
 * Every quantity scales, so the relative tolerance TOL holds. */
static void test_tiny_triangle(void **state)
{
    (void)state;
    const real leg = (real)1e-6;
    const triangle tiny = {{0, 0, -1}, {leg, 0, -1}, {0, leg, (real)-1.0000005}};
    vec3 g = centroid(&tiny);
    for (int k = 0; k < N_TESTS; k++) {
        expect_hit(&tiny, (ray){vec3_make(0, 0, 0), g}, both[k], 1, (real)1 / 3, (real)1 / 3, TOL);
        vec3 x = point_at(&tiny, (real)0.2, (real)0.7);
        expect_hit(&tiny, (ray){vec3_make(0, 0, 0), x}, both[k], 1, (real)0.2, (real)0.7, TOL);
        /* ... and, seen from 1e-3 away, 1e-6 beside it is still a miss. */
        expect_miss(&tiny, (ray){vec3_make(0, 0, 0), vec3_make(-leg, leg / 2, -1)}, 0, REAL_INFINITY, both[k]);
    }
}

/* Far from the origin.  Scaled by 1e6 as a whole, nothing changes: TOL.
 * Legs of 1e3 at 1e6 from the origin: the coordinates carry absolute errors
 * of epsilon * 1e6, which are epsilon * 1e3 relative to the triangle. */
static void test_far_triangles(void **state)
{
    (void)state;
    const real big = (real)1e6;
    const triangle scaled = {vec3_scale(tilted.a, big), vec3_scale(tilted.b, big), vec3_scale(tilted.c, big)};
    vec3 p = vec3_scale(vec3_make(0.5, 7, -3), big);
    vec3 g = centroid(&scaled);

    const vec3 offset = {big, -big, big};
    const real leg = 1000;
    const triangle far = {vec3_add(offset, vec3_scale(tilted.a, leg)), vec3_add(offset, vec3_scale(tilted.b, leg)),
                          vec3_add(offset, vec3_scale(tilted.c, leg))};
    vec3 q = vec3_add(offset, vec3_scale(vec3_make(0.5, 7, -3), leg));
    vec3 x = point_at(&far, (real)0.25, (real)0.5);
    for (int k = 0; k < N_TESTS; k++) {
        expect_hit(&scaled, (ray){p, vec3_sub(g, p)}, both[k], 1, (real)1 / 3, (real)1 / 3, TOL);
        expect_hit(&far, (ray){q, vec3_sub(x, q)}, both[k], 1, (real)0.25, (real)0.5, TOL * big / leg);
    }
}

/* Grazing rays meet the plane at a small angle theta: an error e across the
 * ray moves the hit point by e / sin(theta) along the plane, so the
 * tolerance is TOL / sin(theta).  An exactly parallel ray is a miss. */
static void test_grazing_rays(void **state)
{
    (void)state;
    vec3 n = triangle_normal(&tilted);
    vec3 along = vec3_normalize(vec3_sub(tilted.b, tilted.a));
    const real sines[] = {(real)1e-1, (real)1e-2, (real)1e-3};
    for (int k = 0; k < N_TESTS; k++)
        for (int j = 0; j < 3; j++) {
            real s = sines[j];
            vec3 d = vec3_add(vec3_scale(along, real_sqrt(1 - s * s)), vec3_scale(n, -s));
            vec3 x = point_at(&tilted, (real)0.3, (real)0.4);
            ray r = {vec3_sub(x, vec3_scale(d, 2)), d};
            expect_hit(&tilted, r, both[k], 2, (real)0.3, (real)0.4, TOL / s);
        }
    /* Grazing by far less, with exact data: flat's triangle moved to z = 0, the ray from (-5.75, 2.5, s) along
     * (8, 0, -s), s = 2^-20 .. 2^-100 (normal in both builds), meets the plane at t = 1 in (2.25, 2.5, 0), beta =
     * gamma = 1/4.  Every determinant is a small multiple of s, exact (M = -19 s), so the hit is exact however
     * small s is: M is tiny only because the ray is nearly parallel, and the system still has one solution. */
    const triangle low = {{1, 1, 0}, {5, 2, 0}, {2, 6, 0}};
    for (int e = 20; e <= 100; e += 20) {
        const real s = (real)ldexp(1, -e);
        const ray r = {{(real)-5.75, (real)2.5, s}, {8, 0, -s}};
        const char *in = describe("cramer(%s), window (0, inf), the ray 2^-%d above the plane and as steep",
                                  describe_input(&low, r), e);
        triangle_hit h = UNWRITTEN_HIT;
        assert_true_why(triangle_cramer(&low, r, 0, REAL_INFINITY, &h),
                        "%s\n    expected true, a hit at t 1, beta 0.25, gamma 0.25 (exact data: M = -19 s)\n"
                        "    got      false\n    likely mistake: an epsilon on M (absolute, or relative to the "
                        "lengths of a - b, a - c and d): a ray nearly parallel to the plane makes M small, yet the "
                        "system has one finite solution; return false only when M == 0 or M is not finite (README, "
                        "\"Robustness: what M = 0 means, and what not to do about it\")",
                        in);
        assert_true_why(h.t == 1 && h.beta == (real)0.25 && h.gamma == (real)0.25,
                        "%s\n    expected t 1, beta 0.25, gamma 0.25 exactly (every determinant is exact)\n"
                        "    got      %s\n    likely mistake: %s",
                        in, describe_got(true, h, false), unwritten(h) ? not_written
                        : "t = det[a - b, a - c, a - p] / M, beta = det[a - p, a - c, d] / M, gamma = det[a - b, "
                          "a - p, d] / M");
    }
}

/* The window is open: t_min < t < t_max.  The exact setup hits at t = 1 exactly. */
static void test_t_window(void **state)
{
    (void)state;
    vec3 x = point_at(&flat, (real)0.25, (real)0.25);
    ray r = {above, vec3_sub(x, above)};
    for (int k = 0; k < N_TESTS; k++) {
        triangle_hit h = UNWRITTEN_HIT;
        expect_hit_in(&flat, r, 0, 2, both[k], "at t 1, beta 0.25, gamma 0.25",
                      lost_hit_mistake((real)0.25, (real)0.25), &h);
        expect_t_exactly(&flat, r, 0, 2, both[k], h, 1);
        h = (triangle_hit)UNWRITTEN_HIT;
        expect_hit_in(&flat, r, (real)0.999, (real)1.001, both[k], "at t 1, inside the narrow window",
                      "t compared with a fixed epsilon, or with 0 and infinity, instead of the window: the hit needs "
                      "t_min < t < t_max",
                      &h);
        expect_miss(&flat, r, 0, 1, both[k]);              /* t == t_max: outside */
        expect_miss(&flat, r, 1, 2, both[k]);              /* t == t_min: outside */
        expect_miss(&flat, r, (real)1.5, 9, both[k]);      /* the window lies beyond */
        expect_miss(&flat, r, 0, (real)0.5, both[k]);      /* ... or before */
        ray back = {above, vec3_neg(r.d)};                 /* the triangle behind the origin */
        expect_miss(&flat, back, 0, REAL_INFINITY, both[k]);
        h = (triangle_hit)UNWRITTEN_HIT;
        expect_hit_in(&flat, back, -REAL_INFINITY, 0, both[k], "at t -1: the triangle is behind p, inside the window",
                      "t compared with 0 instead of t_min: the window (t_min, t_max) is the caller's, here (-inf, 0)",
                      &h);
        expect_t_exactly(&flat, back, -REAL_INFINITY, 0, both[k], h, -1);
    }
    /* The same with M = N = 49, 121, 169 (legs of 7, 11, 13): t = N / M is 1 exactly, correctly rounded once,
     * where N (1 / M) rounds twice (49 fl(1 / 49) = 1 - 2^-53): a window that ends at t = 1 holds no hit. */
    const real legs[] = {7, 11, 13};
    for (size_t s = 0; s < sizeof legs / sizeof legs[0]; s++) {
        const triangle right = {{0, 0, 0}, {-legs[s], 0, 0}, {0, -legs[s], 0}};
        const ray up = {{-1, -1, -1}, {0, 0, 1}};
        for (int k = 0; k < N_TESTS; k++) {
            triangle_hit h = UNWRITTEN_HIT;
            expect_hit_in(&right, up, 0, 2, both[k], "at t 1, beta = gamma = 1 / leg",
                          lost_hit_mistake(1 / legs[s], 1 / legs[s]), &h);
            assert_true_why(h.t == 1,
                            "--triangle=%s, window (0, 2): %s\n    expected t = 1 exactly (N = M = %g, both exact)\n"
                            "    got      %s\n    likely mistake: %s",
                            test_names[k], describe_input(&right, up), (double)(legs[s] * legs[s]),
                            describe_got(true, h, false),
                            unwritten(h) ? not_written
                                         : "t = det[a - b, a - c, a - p] * (1 / M): two roundings where the README's "
                                           "t = det[a - b, a - c, a - p] / M rounds once");
            expect_miss(&right, up, 0, 1, both[k]); /* t == t_max: outside */
            expect_miss(&right, up, 1, 2, both[k]); /* t == t_min: outside */
        }
    }
}

/* Many rays at a triangle: where a test reports a hit, p + t d is the point
 * a + beta (b - a) + gamma (c - a), and the two tests agree away from the
 * edges.  The points have size ~ 10, hence the tolerance 10 TOL. */
static void test_hit_point_is_consistent(void **state)
{
    (void)state;
    int agree = 0, total = 0;
    for (int i = 0; i < 21; i++)
        for (int j = 0; j < 21; j++) {
            real beta = (real)(i - 3) / 14, gamma = (real)(j - 3) / 14;
            vec3 x = point_at(&tilted, beta, gamma);
            vec3 p = vec3_make((real)(3 - i) / 4, 6, (real)j / 3 - 4);
            ray r = {p, vec3_sub(x, p)};
            triangle_hit h[N_TESTS];
            bool hit[N_TESTS];
            const bool on_edge = i == 3 || j == 3 || i + j == 20; /* beta = 0, gamma = 0, beta + gamma = 1 */
            for (int k = 0; k < N_TESTS; k++) {
                hit[k] = triangle_intersect(&tilted, r, 0, REAL_INFINITY, both[k], &h[k]);
                if (!hit[k])
                    continue;
                const vec3 at = ray_at(r, h[k].t), on = point_at(&tilted, h[k].beta, h[k].gamma);
                /* A ray at an edge line may hit or miss in a right answer (README, "Edges: closed"): its hit
                 * point is checked without a record for the grader, whose records must be the same in every
                 * right answer; the others' are recorded. */
                if (!on_edge)
                    assert_vec3_close(at, on, 10 * TOL);
                else if (!(vec3_max_abs(vec3_sub(at, on)) <= 10 * TOL))
                    fail_msg("--triangle=%s, a ray at an edge line: p + t d = (%g, %g, %g), a + beta (b - a) + "
                             "gamma (c - a) = (%g, %g, %g), expected within %g", test_names[k], (double)at.x,
                             (double)at.y, (double)at.z, (double)on.x, (double)on.y, (double)on.z, (double)(10 * TOL));
            }
            const bool inside = i >= 3 && j >= 3 && i + j <= 20;
            for (int k = 0; k < N_TESTS && !on_edge; k++)
                if (hit[k] != inside) {
                    print_triangle("input", &tilted, r);
                    fail_msg("--triangle=%s: the point beta %g, gamma %g (beta + gamma %g) is %s the triangle, "
                             "got %s\n    likely mistake: %s",
                             test_names[k], (double)beta, (double)gamma, (double)(beta + gamma),
                             inside ? "inside" : "outside", hit[k] ? "a hit" : "a miss",
                             hit[k] ? false_hit_mistake(h[k], 0, REAL_INFINITY) : lost_hit_mistake(beta, gamma));
                }
            total++;
            agree += hit[0] == hit[1];
        }
    /* they may differ only on the edge lines */
    assert_true_why(agree >= total - 3 * 21,
                    "cramer and watertight on %d rays at the triangle a (%g, %g, %g), b (%g, %g, %g), c (%g, %g, %g), "
                    "aimed at beta, gamma = -3/14 .. 17/14\n    expected the same answer for at least %d (they may "
                    "differ only on the edge lines)\n    got      %d\n    likely mistake: a point away from the edges "
                    "decided differently: the tests beta >= 0, gamma >= 0, beta + gamma <= 1 (README, \"Edges: "
                    "closed\")",
                    total, (double)tilted.a.x, (double)tilted.a.y, (double)tilted.a.z, (double)tilted.b.x,
                    (double)tilted.b.y, (double)tilted.b.z, (double)tilted.c.x, (double)tilted.c.y, (double)tilted.c.z,
                    total - 3 * 21, agree);
}

/* The geometric normal: unit, (b - a) x (c - a), for huge and tiny triangles too. */
static void test_normal(void **state)
{
    (void)state;
    const triangle xy = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    assert_vec3_close(vec3_make(0, 0, 1), triangle_normal(&xy), 0);
    const triangle yx = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}};
    assert_vec3_close(vec3_make(0, 0, -1), triangle_normal(&yx), 0);
    /* The tilted triangle: (b - a) x (c - a) = (3, -3, -1) x (-3, -2, 2) = (-8, -3, -15). */
    vec3 expected = vec3_scale(vec3_make(-8, -3, -15), 1 / real_sqrt(8 * 8 + 3 * 3 + 15 * 15));
    assert_vec3_close(expected, triangle_normal(&tilted), 4 * REAL_EPSILON);
    /* Legs of 1e15 and 1e-15: |n|^2 would overflow or underflow in float without care; legs of 1e100 and
     * 1e-100 make (b - a) x (c - a) about 1e200 and 1e-200, finite doubles whose squares, in |n|, are not. */
    const bool single = sizeof(real) < sizeof(double);
    const real scales[] = {(real)1e15, (real)1e-15, single ? (real)1e15 : (real)1e100,
                           single ? (real)1e-15 : (real)1e-100};
    for (int k = 0; k < 4; k++) {
        real f = scales[k];
        triangle s = {vec3_scale(tilted.a, f), vec3_scale(tilted.b, f), vec3_scale(tilted.c, f)};
        assert_vec3_why(expected, triangle_normal(&s), TOL,
                        describe("triangle_normal of the tilted triangle scaled by %g", (double)f),
                        "triangle_normal is given: (b - a) x (c - a) scaled by its largest component before it "
                        "is normalized, so that |n| neither overflows nor underflows",
                        NULL, 0);
    }
}

/* ---- data whose arithmetic is not exact ------------------------------------------------ */

/* A small deterministic generator (xorshift64), so that every run and every
 * build sees the same "random" data. */
static uint64_t rng_state;
static real uniform(void) /* in [0, 1) */
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (real)((double)(rng_state >> 11) / 9007199254740992.0);
}
static real symmetric(void) { return 2 * uniform() - 1; }

/* A random frame: an orthonormal basis u, v, w (rounded), a scale and an
 * offset, so that local (x, y, z) becomes offset + scale (x u + y v + z w). */
typedef struct {
    vec3 u, v, w, offset;
    real scale;
} frame;

/* A random vector of the cube [-1, 1]^3, drawn x, y, z in this order (the
 * order of a call's arguments is the compiler's choice: drawn in them, gcc
 * and clang would test different data). */
static vec3 random_vector(void)
{
    real x = symmetric(), y = symmetric(), z = symmetric();
    return vec3_make(x, y, z);
}

static frame random_frame(real scale, real distance)
{
    vec3 w = vec3_normalize(vec3_add(random_vector(), vec3_make(0, 0, (real)0.1)));
    vec3 u = vec3_normalize(vec3_cross(w, vec3_add(random_vector(), vec3_make(0, (real)0.2, 0))));
    vec3 offset = vec3_scale(random_vector(), distance);
    return (frame){u, vec3_cross(w, u), w, offset, scale};
}

static vec3 place(const frame *f, real x, real y, real z)
{
    return vec3_add(f->offset,
                    vec3_scale(vec3_add(vec3_scale(f->u, x), vec3_add(vec3_scale(f->v, y), vec3_scale(f->w, z))),
                               f->scale));
}

/* Sizes and places: small and large triangles, at and far from the origin. */
static const struct {
    real scale, distance;
} placements[] = {{1, 0}, {(real)1e-3, (real)0.5}, {7, 30}, {(real)0.25, 1000}, {(real)1e4, 0}, {3, (real)2e5}};
enum { N_PLACEMENTS = sizeof placements / sizeof placements[0] };

/* The check of crossing.h accepts a hit only where Cramer's rule in real
 * arithmetic puts its point within 1/8 of the triangle's longest edge of the
 * crossing the data have (a first-order bound, worst case: the errors seen
 * are far smaller).  So a hit, if any, is on the triangle to within that:
 * otherwise it is a false hit, made by rounding noise. */
static void expect_on_triangle(const char *what, const triangle *tri, ray r, triangle_test test)
{
    triangle_hit h;
    if (!triangle_intersect(tri, r, 0, REAL_INFINITY, test, &h))
        return;
    long double off = hit_distance(tri, r, h.t);
    if (!(off <= 0.125L)) {
        print_triangle(what, tri, r);
        fail_msg("--triangle=%s: a hit at t %g, beta %g, gamma %g, %Lg edge lengths off the triangle: a "
                 "determinant that is rounding noise is not a hit",
                 test == TRIANGLE_CRAMER ? "cramer" : "watertight", (double)h.t, (double)h.beta, (double)h.gamma, off);
    }
}

/* Degenerate triangles made of rounded data: the third vertex computed on
 * the line of the other two (so off it by rounding), or equal to one of
 * them, in random frames.  Rays from random origins aimed at points of the
 * segment: M = det[a - b  a - c  d] is rounding noise there, or (for a
 * third vertex that rounding moved off the line far from the origin) the
 * data make a sliver of a triangle, so thin that beta and gamma are noise.
 * A hit, if any, must be on the triangle (expect_on_triangle).  The same
 * rays hit the triangle whose third vertex is moved off the line by a
 * quarter of the segment. */
static void test_degenerate_rounded(void **state)
{
    (void)state;
    rng_state = 0x9e3779b97f4a7c15u;
    for (int k = 0; k < N_TESTS; k++)
        for (int pl = 0; pl < N_PLACEMENTS; pl++)
            for (int n = 0; n < 400; n++) {
                frame f = random_frame(placements[pl].scale, placements[pl].distance);
                real ax = symmetric(), ay = symmetric(), bx = symmetric(), by = symmetric();
                real s = 2 * uniform() - (real)0.5;
                vec3 a = place(&f, ax, ay, 0), b = place(&f, bx, by, 0);
                vec3 on_line = n % 3 == 0 ? place(&f, ax + s * (bx - ax), ay + s * (by - ay), 0)
                             : n % 3 == 1 ? vec3_add(a, vec3_scale(vec3_sub(b, a), s))
                                          : (n % 2 ? a : b);
                triangle tri = n % 2 ? (triangle){a, b, on_line} : (triangle){on_line, a, b};
                real along = uniform();
                vec3 x = vec3_add(a, vec3_scale(vec3_sub(b, a), along));
                vec3 p = place(&f, 3 * symmetric(), 3 * symmetric(), 2 + uniform());
                ray r = {p, vec3_sub(x, p)};
                triangle_hit h;
                expect_on_triangle("degenerate triangle", &tri, r, both[k]);
                /* The control: a proper triangle over the same segment is hit at x,
                 * where the coordinates resolve the triangle to better than 1e-3 of
                 * its size (not so for a float triangle of size 3 at 2e5, whose
                 * own plane the data know only to a few degrees). */
                real amplify = 1 + placements[pl].distance / placements[pl].scale;
                if (amplify * REAL_EPSILON > (real)1e-3)
                    continue;
                triangle proper = {a, b, place(&f, (ax + bx) / 2 - (by - ay) / 4, (ay + by) / 2 + (bx - ax) / 4, 0)};
                real target_beta = along * (real)0.8, target_gamma = (real)0.1;
                vec3 y = vec3_add(proper.a, vec3_add(vec3_scale(vec3_sub(proper.b, proper.a), target_beta),
                                                     vec3_scale(vec3_sub(proper.c, proper.a), target_gamma)));
                ray q = {p, vec3_sub(y, p)};
                if (!triangle_intersect(&proper, q, 0, REAL_INFINITY, both[k], &h)) {
                    print_triangle("proper triangle", &proper, q);
                    fail_msg("--triangle=%s: expected a hit at t 1, beta %g, gamma %g; got a miss", test_names[k],
                             (double)target_beta, (double)target_gamma);
                }
                /* The data carry rounding of the size of the placement's distance
                 * against the triangle's size 1 (as in test_far_triangles). */
                assert_close(1, h.t, 16 * TOL * amplify);
            }
}

/* Rays that lie in the triangle's plane: here the plane x + y + z = 0, whose
 * points are rounded off it (the basis (1, -1, 0)/sqrt 2, (1, 1, -2)/sqrt 6
 * is irrational).  Origins and targets in the plane, targets inside the
 * triangle: the ray meets the triangle edge-on, at a t the arithmetic
 * cannot tell (a miss), or, where rounding tilted the data far from the
 * origin, at a grazing angle: a hit, if any, must be on the triangle
 * (expect_on_triangle).  Lifted off the plane by the triangle's size, the
 * same origins hit it at t = 1. */
static void test_rays_in_the_plane(void **state)
{
    (void)state;
    rng_state = 0x2545f4914f6cdd1du;
    const vec3 e_u = {(real)0.70710678118654752, (real)-0.70710678118654752, 0};
    const vec3 e_v = {(real)0.40824829046386302, (real)0.40824829046386302, (real)-0.81649658092772603};
    const vec3 normal = {(real)0.57735026918962576, (real)0.57735026918962576, (real)0.57735026918962576};
    for (int k = 0; k < N_TESTS; k++)
        for (int pl = 0; pl < N_PLACEMENTS; pl++)
            for (int n = 0; n < 400; n++) {
                real size = placements[pl].scale, u0 = placements[pl].distance * symmetric(),
                     v0 = placements[pl].distance * symmetric();
                vec3 v[3];
                for (int i = 0; i < 3; i++)
                    v[i] = vec3_add(vec3_scale(e_u, u0 + size * symmetric()), vec3_scale(e_v, v0 + size * symmetric()));
                triangle tri = {v[0], v[1], v[2]};
                /* at least 0.05 inside, far more than the data's rounding: the lifted ray must hit */
                real beta = (real)0.05 + (real)0.4 * uniform(), gamma = (real)0.05 + (real)0.4 * uniform();
                vec3 x = point_at(&tri, beta, gamma);
                vec3 p = vec3_add(vec3_scale(e_u, u0 + 3 * size * symmetric()), vec3_scale(e_v, v0 + 3 * size * symmetric()));
                ray r = {p, vec3_sub(x, p)};
                triangle_hit h;
                expect_on_triangle("ray in the triangle's plane x + y + z = 0", &tri, r, both[k]);
                real area = vec3_length(vec3_cross(vec3_sub(tri.b, tri.a), vec3_sub(tri.c, tri.a)));
                if (!(area > size * size / 8))
                    continue; /* a sliver: the lifted ray would graze it */
                if ((1 + placements[pl].distance / size) * REAL_EPSILON > (real)1e-3)
                    continue; /* as in test_degenerate_rounded: the data do not resolve the triangle */
                vec3 above_p = vec3_add(p, vec3_scale(normal, size));
                ray lifted = {above_p, vec3_sub(x, above_p)};
                if (!triangle_intersect(&tri, lifted, 0, REAL_INFINITY, both[k], &h)) {
                    print_triangle("ray lifted off the plane", &tri, lifted);
                    fail_msg("--triangle=%s: expected a hit at t 1, beta %g, gamma %g; got a miss", test_names[k],
                             (double)beta, (double)gamma);
                }
            }
}

/* A ray that starts exactly on a triangle meets its plane at t = 0, which
 * is outside the open window (0, infinity): a miss, whether it leaves the
 * triangle or enters the space behind it.  Exact data first (t is exactly
 * 0; test_t_window catches a window written t >= t_min), then a closed
 * icosahedron in a random frame: from a computed point of a face, inwards
 * the ray meets the opposite side; outwards it meets nothing (beyond the
 * rounding of its start, see below). */
static void test_origin_on_the_triangle(void **state)
{
    (void)state;
    vec3 on = point_at(&flat, (real)0.25, (real)0.375); /* exact: small dyadic numbers */
    const vec3 dirs[] = {{0, 0, 1}, {0, 0, -1}, {1, 2, -3}, {-1, 0.5, 0.25}};
    for (int k = 0; k < N_TESTS; k++)
        for (int j = 0; j < 4; j++) {
            triangle_hit h = {-7, -7, -7};
            if (triangle_intersect(&flat, (ray){on, dirs[j]}, 0, REAL_INFINITY, both[k], &h))
                fail_msg("--triangle=%s: ray from (%g, %g, %g), a point of the triangle, along (%g, %g, %g): expected "
                         "a miss (t = 0 is outside (0, infinity)), got %s: is the window test t > t_min?",
                         test_names[k], (double)on.x, (double)on.y, (double)on.z, (double)dirs[j].x, (double)dirs[j].y,
                         (double)dirs[j].z, describe_got(true, h, false));
        }
    rng_state = 0x5851f42d4c957f2du;
    for (int k = 0; k < N_TESTS; k++)
        for (int pl = 0; pl < N_PLACEMENTS; pl++) {
            frame f = random_frame(placements[pl].scale, placements[pl].distance);
            vec3 v[ICOSAHEDRON_VERTICES];
            triangle faces[ICOSAHEDRON_FACES];
            icosahedron_vertices(f.offset, f.scale, v);
            icosahedron_triangles(v, faces);
            const real inradius = (real)0.7946544722917661 * f.scale;
            for (int face = 0; face < ICOSAHEDRON_FACES; face++) {
                vec3 start = point_at(&faces[face], uniform() / 2, uniform() / 2);
                vec3 inward = vec3_sub(f.offset, start), outward = vec3_neg(inward);
                /* The computed start is off its face's plane by a few roundings of
                 * its coordinates (point_at: 3 u max |coordinate|), and the rays
                 * leave at more than asin(inradius / circumradius) = 52 degrees:
                 * a crossing of its own face closer than 8 eps max |coordinate|
                 * is that rounding, which the data decide (the acne of chapter
                 * 06, whose spawn policy moves the start off the surface). */
                const real own = 8 * REAL_EPSILON * vec3_max_abs(start) / vec3_length(inward);
                int first = -1;
                real t_best = REAL_INFINITY;
                for (int g = 0; g < ICOSAHEDRON_FACES; g++) {
                    triangle_hit h;
                    if (triangle_intersect(&faces[g], (ray){start, inward}, g == face ? own : 0, t_best, both[k], &h)) {
                        t_best = h.t;
                        first = g;
                    }
                    if (triangle_intersect(&faces[g], (ray){start, outward}, g == face ? own : 0, REAL_INFINITY, both[k],
                                           &h))
                        fail_msg("--triangle=%s: icosahedron of radius %g at distance %g, ray from a point of face %d "
                                 "outwards: expected no hit, got face %d at t %g",
                                 test_names[k], (double)f.scale, (double)placements[pl].distance, face, g, (double)h.t);
                }
                /* Through the centre to the other side: at least two inradii away (t = 1 is the centre). */
                if (first < 0 || first == face || !(t_best * vec3_length(inward) >= 2 * inradius * (1 - 64 * TOL)))
                    fail_msg("--triangle=%s: icosahedron of radius %g at distance %g, ray from a point of face %d "
                             "inwards: expected the far side (t >= %g), got face %d at t %g",
                             test_names[k], (double)f.scale, (double)placements[pl].distance, face,
                             (double)(2 * inradius / vec3_length(inward)), first, (double)t_best);
            }
        }
}

/* Crossings that the arithmetic decides are hits, at any distance from the
 * origin, and false hits are none.  First a grazing ray over exact vertices:
 * p 1.3e-7 above the plane z = 0, d = (1, 0, -1e-7), meets it at t = 1.3,
 * and every product of Cramer's rule is exact or one rounding (M = -1e-7,
 * N = -1.3e-7 in float).  Then a triangle with edges about 1 at
 * (1e6, 5e5, -2.5e5), seen from 1.5 away at 20 to 90 degrees: in float its
 * coordinates are multiples of 1/16, the data as they are, and the rays
 * aimed 5 % or more inside it hit at t = 1 (d = x - p, all within TOL times
 * 1 / sin 20 degrees).  A check that budgets a rounding of the vertices of
 * the size of their coordinates missed both (the second in float only:
 * about 40 % of the rays).  Last the measurement of degenerate_count.h at
 * 0 to 10^6 edge lengths from the origin: no clear hit that Cramer's rule
 * alone places to within 1/1024 of an edge is lost (the check allows
 * TRIANGLE_POINT_SLACK = 1/8, a worst-case bound), and no hit at a
 * degenerate triangle or by a ray in the plane is further than 1/8 of an
 * edge from the triangle. */
static void test_decided_at_any_distance(void **state)
{
    (void)state;
    const triangle unit = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const ray grazing = {{(real)-0.99999994, (real)0.3, (real)1.3e-7}, {1, 0, (real)-1e-7}};
    for (int k = 0; k < N_TESTS; k++)
        expect_hit(&unit, grazing, both[k], (real)1.3, grazing.p.x + (real)1.3, (real)0.3, TOL);

    rng_state = 0x6a09e667f3bcc909u;
    const vec3 centre = {(real)1e6, (real)5e5, (real)-2.5e5};
    const triangle far = {vec3_add(centre, vec3_make((real)0.3, (real)-0.2, (real)0.1)),
                          vec3_add(centre, vec3_make((real)-0.6, (real)0.4, (real)0.2)),
                          vec3_add(centre, vec3_make((real)0.2, (real)0.7, (real)-0.5))};
    const vec3 n = triangle_normal(&far);
    for (int k = 0; k < N_TESTS; k++)
        for (int i = 0; i < 2000; i++) {
            real beta = (real)0.05 + (real)0.9 * uniform(), gamma = (real)0.05 + (real)0.9 * uniform();
            if (beta + gamma > (real)0.95)
                continue;
            vec3 x = point_at(&far, beta, gamma), side = random_vector();
            vec3 towards = vec3_normalize(vec3_add(n, vec3_scale(side, (real)1.5)));
            if (real_abs(vec3_dot(towards, n)) < (real)0.342) /* sin 20 degrees */
                continue;
            vec3 p = vec3_add(x, vec3_scale(towards, (real)1.5));
            ray r = {p, vec3_sub(x, p)};
            crossing ref;
            assert_true(crossing_reference(&far, r, &ref));
            expect_hit(&far, r, both[k], (real)ref.t, (real)ref.beta, (real)ref.gamma, 3 * TOL);
        }

    const double distances[] = {0, 1e2, 1e4, 1e6};
    for (int k = 0; k < N_TESTS; k++)
        for (int i = 0; i < 4; i++) {
            degenerate_count c = degenerate_counts_at(20000, both[k], distances[i]);
            print_message("--triangle=%s at %g: %ld false hits (1 %%), worst %.3g edge lengths off, %ld of %ld clear "
                          "hits lost\n",
                          test_names[k], distances[i], c.degenerate_false + c.plane_false, c.worst_off, c.lost_hits,
                          c.clear_hits);
            const char *in =
                describe("--triangle=%s: degenerate_counts_at(20000 rays, distance %g)", test_names[k], distances[i]);
            /* about a quarter of the rays at proper triangles */
            assert_true_why(c.clear_hits > 4000,
                            "%s: rays 1 %% inside proper triangles that triangle_cramer places to within 1/1024 of an "
                            "edge\n    expected more than 4000 (about a quarter of the rays)\n    got      %ld\n"
                            "    likely mistake: triangle_cramer misses such points or places them off: a column of a "
                            "determinant of the wrong sign or order (README, \"The intersection: three equations, "
                            "three unknowns\")",
                            in, c.clear_hits);
            assert_int_equal(0, c.lost_hits);
            assert_true_why(
                c.worst_off <= 0.125,
                "%s: hits at degenerate triangles and by rays in their plane\n    expected every hit within "
                "1/8 of an edge of its triangle\n    got      a hit %.3g edge lengths off\n    likely "
                "mistake: %s",
                in, c.worst_off,
                both[k] == TRIANGLE_CRAMER
                    ? "a t that is not the crossing's: t = det[a - b, a - c, a - p] / M (README, \"The "
                      "intersection: three equations, three unknowns\"); the given check vouches for the "
                      "crossing, not for the t reported"
                    : "the watertight test and the check of crossing.h are given (common/): changed?");
        }
}

/* Near the ends of the number range: a triangle and a ray scaled together by
 * 2^-e and 2^e, e a quarter of the exponent range of real, so that M (a
 * product of three coordinates) stays finite and normal.  A power of two
 * scales every rounding exactly, so beta and gamma are the unscaled ones
 * and t too (p and d scale alike). */
static void test_range_ends(void **state)
{
    (void)state;
    const int e = (REAL_EPSILON < 1e-10 ? 1024 : 128) / 4;
    const real scales[] = {(real)ldexp(1, -e), (real)ldexp(1, e)};
    vec3 g = centroid(&tilted);
    vec3 p = vec3_add(g, vec3_make(2, (real)-0.5, 4));
    for (int k = 0; k < N_TESTS; k++) {
        triangle_hit reference = UNWRITTEN_HIT;
        expect_hit_in(&tilted, (ray){p, vec3_sub(g, p)}, 0, REAL_INFINITY, both[k],
                      "at the centroid, t 1, beta = gamma "
                      "= 1/3",
                      lost_hit_mistake((real)1 / 3, (real)1 / 3), &reference);
        for (int j = 0; j < 2; j++) {
            real f = scales[j];
            triangle scaled = {vec3_scale(tilted.a, f), vec3_scale(tilted.b, f), vec3_scale(tilted.c, f)};
            ray r = {vec3_scale(p, f), vec3_scale(vec3_sub(g, p), f)};
            triangle_hit h = UNWRITTEN_HIT;
            if (!triangle_intersect(&scaled, r, 0, REAL_INFINITY, both[k], &h))
                fail_msg("--triangle=%s: the centroid ray scaled by 2^%d: expected a hit at t %g, got a miss",
                         test_names[k], j ? e : -e, (double)reference.t);
            assert_true_why(h.t == reference.t && h.beta == reference.beta && h.gamma == reference.gamma,
                            "--triangle=%s: %s, the centroid ray and the triangle scaled by 2^%d\n    expected %s (the "
                            "unscaled ones, bit for bit: a power of two scales every rounding exactly)\n    got      "
                            "%s\n    likely mistake: %s",
                            test_names[k], describe_input(&scaled, r), j ? e : -e, describe_got(true, reference, true),
                            describe_got(true, h, true),
                            unwritten(h)
                                ? not_written
                                : "a term that does not scale with the data, such as an absolute epsilon on M, "
                                  "t, beta or gamma (README, \"Robustness\": every term scales)");
        }
    }
}

/* The icosahedron: closed, wound outwards, each edge shared by two faces. */
static void test_icosahedron_is_closed(void **state)
{
    (void)state;
    vec3 centre = {0.3, -0.2, 0.1};
    vec3 v[ICOSAHEDRON_VERTICES];
    triangle faces[ICOSAHEDRON_FACES];
    int edges[ICOSAHEDRON_EDGES][2];
    icosahedron_vertices(centre, 2, v);
    icosahedron_triangles(v, faces);
    icosahedron_edges(edges);
    for (int k = 0; k < ICOSAHEDRON_VERTICES; k++)
        assert_close(2, vec3_length(vec3_sub(v[k], centre)), TOL);
    for (int f = 0; f < ICOSAHEDRON_FACES; f++)
        assert_true(vec3_dot(triangle_normal(&faces[f]), vec3_sub(centroid(&faces[f]), centre)) > 0);
    for (int e = 0; e < ICOSAHEDRON_EDGES; e++) {
        int forward = 0, backward = 0; /* faces that run along the edge i -> j, and j -> i */
        for (int f = 0; f < ICOSAHEDRON_FACES; f++)
            for (int k = 0; k < 3; k++) {
                int i = icosahedron_faces[f][k], j = icosahedron_faces[f][(k + 1) % 3];
                forward += i == edges[e][0] && j == edges[e][1];
                backward += i == edges[e][1] && j == edges[e][0];
            }
        assert_int_equal(1, forward);
        assert_int_equal(1, backward);
        for (int d = 0; d < e; d++)
            assert_false(edges[d][0] == edges[e][0] && edges[d][1] == edges[e][1]);
    }
}

/* From inside, through the middle of every face: each face is hit at (1/3, 1/3), from its back.
 * The origins: the centre and three points inside the inscribed sphere (radius 0.79). */
static void test_icosahedron_from_inside(void **state)
{
    (void)state;
    static const vec3 origins[] = {{0, 0, 0}, {0.42, 0.217, 0.238}, {0.081, 0.337, -0.033}, {0.25, 0.138, -0.214}};
    vec3 v[ICOSAHEDRON_VERTICES];
    triangle faces[ICOSAHEDRON_FACES];
    icosahedron_vertices(vec3_make(0, 0, 0), 1, v);
    icosahedron_triangles(v, faces);
    for (int k = 0; k < N_TESTS; k++)
        for (int o = 0; o < 4; o++) {
            vec3 p = origins[o];
            for (int f = 0; f < ICOSAHEDRON_FACES; f++)
                expect_hit(&faces[f], (ray){p, vec3_sub(centroid(&faces[f]), p)}, both[k], 1, (real)1 / 3,
                           (real)1 / 3, TOL);
        }
}

/* triangle_crossing_certain takes a quick sufficient test before the full
 * one (common/crossing.c); it must decide exactly as the full one,
 * triangle_crossing_certain_exact, for every input.  Random triangles and
 * rays in rotated frames, at scales from the smallest subnormal to the
 * largest real and far from the origin, of the kinds where the two could
 * part: nearly collinear or coincident vertices, rays nearly in the plane,
 * origins (nearly) in the plane, each perturbed by 2^-k of its size for k up
 * to 80 so that the determinants fall on both sides of their bounds; axis
 * parallel directions with +0 and -0 components; subnormal, huge, infinite
 * and NaN coordinates. */
static int below(int n) /* uniform in 0 .. n - 1 */
{
    (void)uniform();
    return (int)(rng_state % (uint64_t)n);
}
static real power_of_two(int lo, int hi) { return (real)ldexp(1, lo + below(hi - lo + 1)); }
static real any_sign(real x) { return below(2) ? x : -x; }
/* A random point of the frame's square [-scale, scale]^2 at height z. */
static vec3 in_plane(const frame *f, real scale, real z)
{
    real x = scale * symmetric(), y = scale * symmetric();
    return place(f, x, y, z);
}

static void test_crossing_certain_quick_is_exact(void **state)
{
    (void)state;
    rng_state = 0x853c49e6748fea9bu;
    const int top = ilogb(REAL_MAX), bottom = ilogb(REAL_MIN) + ilogb(REAL_EPSILON); /* 2^bottom: smallest subnormal */
    const int span = top - 64; /* sizes 2^-span .. 2^span, and distances up to 2^60 sizes, are finite */
    enum { KINDS = 10, N = 1 << 22 };
    long outcomes[KINDS][2] = {{0}};
    for (int n = 0; n < N; n++) {
        int kind = n % KINDS;
        /* A size for the triangle, and the distance of its frame from the origin. */
        int e = kind == 6 ? bottom + below(3 * -ilogb(REAL_EPSILON))  /* subnormal data */
              : kind == 8 ? top - below(20)                          /* near overflow */
                          : -span + below(2 * span);
        /* Each random draw in a statement or initialiser of its own (see random_vector). */
        real size = power_of_two(e, e);
        size *= 1 + uniform();
        real distance = 0;
        if (below(3)) {
            distance = kind == 9 ? power_of_two(-span, span) : size * power_of_two(0, 60);
            distance *= uniform();
        }
        frame f = random_frame(size, distance);
        vec3 a = in_plane(&f, 1, 0), b = in_plane(&f, 1, 0), c = in_plane(&f, 1, 0);
        real tiny = power_of_two(-80, 0);
        if (kind == 1) { /* c nearly on the line ab */
            real along = 2 * uniform() - (real)0.5;
            vec3 off = random_vector();
            c = vec3_add(vec3_add(a, vec3_scale(vec3_sub(b, a), along)), vec3_scale(off, size * tiny));
        }
        if (kind == 2) { /* c (nearly) at a or b */
            c = below(2) ? a : b;
            if (below(4)) {
                vec3 off = random_vector();
                c = vec3_add(c, vec3_scale(off, size * tiny));
            }
        }
        /* Local coordinates of the origin; z = 0 is the triangle's plane. */
        real pz = 0;
        if (kind != 4) {
            pz = any_sign(1);
            pz *= 1 + 2 * uniform();
        } else if (below(3)) {
            pz = any_sign(tiny);
            pz *= uniform();
        }
        vec3 p = in_plane(&f, 3, pz);
        real target_z = 0;
        if (kind == 3) {
            target_z = any_sign(tiny);
            target_z = pz + target_z * uniform();
        }
        vec3 target = in_plane(&f, 1, target_z);
        vec3 d = vec3_sub(target, p);
        if (kind == 3 && below(2)) { /* in the plane */
            vec3 from = in_plane(&f, 1, 0), to = in_plane(&f, 1, 0);
            d = vec3_sub(from, to);
        }
        if (kind == 9) /* a direction of its own size, anywhere in the range */
            d = vec3_scale(d, power_of_two(-span, span) / (size + distance));
        if (kind == 5) { /* along an axis, with signed zeros elsewhere; sometimes an axis-aligned triangle */
            real along[3];
            for (int axis = 0; axis < 3; axis++)
                along[axis] = any_sign(0);
            int axis = below(3);
            along[axis] = any_sign(size);
            along[axis] *= 1 + uniform();
            d = vec3_make(along[0], along[1], along[2]);
            if (below(2)) {
                real z = p.z;
                if (below(2)) {
                    z = any_sign(size);
                    z *= uniform();
                }
                a.z = b.z = c.z = z;
            }
            if (below(4) == 0)
                p = below(2) ? a : vec3_make(0, 0, 0);
        }
        triangle tri = {a, b, c};
        ray r = {p, d};
        if (kind == 7) { /* one coordinate infinite or NaN */
            real bad = below(3) == 0 ? (real)NAN : any_sign(REAL_INFINITY);
            real *all[15] = {&tri.a.x, &tri.a.y, &tri.a.z, &tri.b.x, &tri.b.y, &tri.b.z, &tri.c.x, &tri.c.y,
                             &tri.c.z, &r.p.x, &r.p.y, &r.p.z, &r.d.x, &r.d.y, &r.d.z};
            *all[below(15)] = bad;
        }
        bool quick = triangle_crossing_certain(&tri.a, &tri.b, &tri.c, r),
             exact = triangle_crossing_certain_exact(&tri.a, &tri.b, &tri.c, r);
        if (quick != exact) {
            fail_msg("kind %d, input %d: triangle_crossing_certain says %d, the full computation %d for a = (%a, %a, "
                     "%a), b = (%a, %a, %a), c = (%a, %a, %a), p = (%a, %a, %a), d = (%a, %a, %a)",
                     kind, n, quick, exact, (double)tri.a.x, (double)tri.a.y, (double)tri.a.z, (double)tri.b.x,
                     (double)tri.b.y, (double)tri.b.z, (double)tri.c.x, (double)tri.c.y, (double)tri.c.z,
                     (double)r.p.x, (double)r.p.y, (double)r.p.z, (double)r.d.x, (double)r.d.y, (double)r.d.z);
        }
        outcomes[kind][exact]++;
    }
    /* The inputs reach both answers where the quick test could go wrong:
     * every kind but the non-finite one (always false) gives some of each. */
    for (int kind = 0; kind < KINDS; kind++) {
        print_message("kind %d: %ld certain, %ld not\n", kind, outcomes[kind][1], outcomes[kind][0]);
        if (kind != 7)
            assert_true(outcomes[kind][0] > 0 && outcomes[kind][1] > 0);
    }
    assert_int_equal(outcomes[7][1], 0);

    /* Where the quick bound is tight: every |component| of e1 = a - b,
     * e2 = a - c, d and f = a - p is 1, 1 + delta or 1 + gamma, so that the
     * quick bound 96 eps E1 E2 W (2 F + L) exceeds the full one
     * 16 eps (P_beta E1 + P_gamma E2 + P_M L) only by a factor 1 + O(delta +
     * gamma) (about 1 + 2^-20 in double), and M = -delta gamma, with gamma
     * chosen to put |M| within 2^-5 of the full bound.  (With |M| = delta
     * gamma at the bound, about 2304 eps, delta + gamma is at least
     * 2 sqrt(2304 eps): the bounds cannot come closer there.)  N = det[e1 e2
     * f] = 4 is clearly certain.  Axes permuted and flipped, so the
     * roundings differ.  In float, delta is 2^-8 and the factor about
     * 1 + 2^-4: there the inputs are near the bound but not as tight. */
    const real delta = (real)ldexp(1, ilogb(REAL_EPSILON) / 2 + 3); /* 2^-23 in double, 2^-8 in float */
    long tight[2] = {0, 0};
    for (int n = 0; n < 1 << 17; n++) {
        real rho = (real)ldexp(symmetric(), -5), gamma = 0;
        const real e1[3] = {1, 1, 1}, e2[3] = {1, -1, 1 + delta}, f[3] = {1, 1, -1};
        for (int iteration = 0; iteration < 3; iteration++) { /* gamma from the bound, which depends on gamma */
            const real w[3] = {1, 1 + gamma, 1};
            real p_m = 0, p_beta = 0, p_gamma = 0; /* P of det[e1 e2 w], det[f e2 w], det[e1 f w] */
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    if (j != i) {
                        int k = 3 - i - j;
                        p_m += real_abs(e1[i] * e2[j] * w[k]);
                        p_beta += real_abs(f[i] * e2[j] * w[k]);
                        p_gamma += real_abs(e1[i] * f[j] * w[k]);
                    }
            /* 16 eps (P_beta E1 + P_gamma E2 + P_M L) = slack L |M|, E1 = 1, E2 = L = 1 + delta */
            gamma = 16 * REAL_EPSILON * (p_beta + (p_gamma + p_m) * (1 + delta)) /
                    ((real)TRIANGLE_POINT_SLACK * (1 + delta)) * (1 + rho) / delta;
        }
        /* a = 0, so f = a - o = (1, 1, -1): N = det[e1 e2 f] = 4, clearly certain */
        const real points[5][3] = {{0, 0, 0}, {-1, -1, -1}, {-1, 1, -1 - delta}, {-1, -1, 1}, {1, 1 + gamma, 1}};
        int shift = below(3);
        real flip[3] = {any_sign(1), any_sign(1), any_sign(1)};
        vec3 v[5];
        for (int i = 0; i < 5; i++)
            v[i] = vec3_make(flip[0] * points[i][shift], flip[1] * points[i][(shift + 1) % 3],
                             flip[2] * points[i][(shift + 2) % 3]);
        vec3 a = v[0], b = v[1], c = v[2], o = v[3], d = v[4];
        triangle tri = {a, b, c};
        ray r = {o, d};
        bool quick = triangle_crossing_certain(&tri.a, &tri.b, &tri.c, r),
             exact = triangle_crossing_certain_exact(&tri.a, &tri.b, &tri.c, r);
        if (quick != exact)
            fail_msg("tight input %d: triangle_crossing_certain says %d, the full computation %d for rho %a, shift %d",
                     n, quick, exact, (double)rho, shift);
        tight[exact]++;
    }
    print_message("tight: %ld certain, %ld not\n", tight[1], tight[0]);
    assert_true(tight[0] > 0 && tight[1] > 0);
}

static const graded_test tests[] = {
    GRADED(test_det3, 0), /* handed out complete: no points */
    GRADED(test_centroid, 3),
    GRADED(test_vertices_and_edge_midpoints, 3),
    GRADED(test_just_outside, 2),
    GRADED(test_parallel_ray, 2),
    GRADED(test_degenerate_triangles, 2),
    GRADED(test_cramer_alone_rejects_what_it_cannot_solve, 2),
    GRADED(test_tiny_triangle, 2),
    GRADED(test_far_triangles, 2),
    GRADED(test_grazing_rays, 2),
    GRADED(test_t_window, 2),
    GRADED(test_hit_point_is_consistent, 2),
    GRADED(test_degenerate_rounded, 2),
    GRADED(test_rays_in_the_plane, 2),
    GRADED(test_origin_on_the_triangle, 2),
    GRADED(test_range_ends, 1),
    GRADED(test_any_length_of_d, 0), /* triangle_intersect is given: no points */
    GRADED(test_normal, 0), /* handed out complete: no points */
    GRADED(test_icosahedron_is_closed, 0), /* handed out complete: no points */
    GRADED(test_icosahedron_from_inside, 2),
    GRADED(test_crossing_certain_quick_is_exact, 0), /* handed out complete: no points */
    GRADED(test_decided_at_any_distance, 0),         /* the given check: no points */
};

SUITE_MAIN("03_triangle", tests)
