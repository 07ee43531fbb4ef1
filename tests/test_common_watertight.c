/* The watertight ray/triangle test of common/watertight.h and the crossing
 * check of common/crossing.h, on vertices, as every chapter from 03 on calls
 * them.  (Chapter 03's suite tests them further through triangle_intersect,
 * and compares the crossing check's quick path with its full computation.)
 *
 * Tolerances.  The data of the exact tests are small dyadic numbers: the
 * shear, the edge functions, their sum and the quotients t = 2, beta = gamma
 * = 1/4 are exact in float and double, so those tests compare exactly.
 */
#include <math.h>

#include "crossing.h"
#include "suite.h"
#include "watertight.h"

/* The test of a, b, c for r, with the outputs set to -7 first. */
static bool hit_of(vec3 a, vec3 b, vec3 c, ray r, real t_min, real t_max, real out[3])
{
    out[0] = out[1] = out[2] = -7;
    watertight_ray wr;
    return watertight_ray_make(r, &wr) && watertight_hit(&wr, &a, &b, &c, t_min, t_max, out);
}

/* Component k of v moved to axis (k + shift) % 3, so that each axis in turn
 * is the one along which d is largest (the test's z in ray space). */
static vec3 rotated(vec3 v, int shift)
{
    const real c[3] = {v.x, v.y, v.z};
    real out[3];
    for (int k = 0; k < 3; k++)
        out[(k + shift) % 3] = c[k];
    return vec3_make(out[0], out[1], out[2]);
}

/* The triangle (0,0,0), (4,0,0), (0,4,0) and a ray from (1,1,+-2) straight at
 * it: t = 2, beta = gamma = 1/4, from either side and along every axis. */
static void test_exact_hit_from_both_sides(void **state)
{
    (void)state;
    for (int shift = 0; shift < 3; shift++)
        for (int side = -1; side <= 1; side += 2) {
            vec3 a = rotated(vec3_make(0, 0, 0), shift), b = rotated(vec3_make(4, 0, 0), shift),
                 c = rotated(vec3_make(0, 4, 0), shift);
            ray r = {rotated(vec3_make(1, 1, (real)(2 * side)), shift), rotated(vec3_make(0, 0, (real)-side), shift)};
            real out[3];
            assert_true(hit_of(a, b, c, r, 0, REAL_INFINITY, out));
            assert_close(2, out[0], 0);
            assert_close(0.25, out[1], 0);
            assert_close(0.25, out[2], 0);
            /* The window is open at both ends. */
            assert_false(hit_of(a, b, c, r, 2, REAL_INFINITY, out));
            assert_false(hit_of(a, b, c, r, 0, 2, out));
            assert_close(-7, out[0], 0); /* a miss writes nothing */
        }
}

/* Misses: outside an edge, parallel to the plane, in the plane, a degenerate
 * triangle, a direction that is zero or infinite; none writes an output. */
static void test_misses_write_nothing(void **state)
{
    (void)state;
    const vec3 a = {0, 0, 0}, b = {4, 0, 0}, c = {0, 4, 0};
    const vec3 down = {0, 0, -1}, above = {1, 1, 2};
    const struct {
        vec3 a, b, c;
        ray r;
        const char *what;
    } cases[] = {
        {a, b, c, {{(real)2.5, (real)1.75, 2}, down}, "outside the edge bc (beta + gamma = 17/16)"},
        {a, b, c, {{-1, 1, 2}, down}, "outside the edge ca"},
        {a, b, c, {above, {1, 0, 0}}, "parallel to the plane"},
        {a, b, c, {{-1, 1, 0}, {1, 0, 0}}, "in the plane, across the triangle"},
        {a, b, vec3_make(2, 0, 0), {above, down}, "collinear vertices"},
        {a, a, c, {above, down}, "coincident vertices"},
        {a, b, c, {above, {0, 0, 0}}, "no direction"},
        {a, b, c, {above, {0, 0, -REAL_INFINITY}}, "an infinite direction"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        real out[3];
        if (hit_of(cases[k].a, cases[k].b, cases[k].c, cases[k].r, 0, REAL_INFINITY, out))
            fail_msg("%s: reported a hit at t = %g", cases[k].what, (double)out[0]);
        assert_true(out[0] == -7 && out[1] == -7 && out[2] == -7);
    }
    watertight_ray wr;
    assert_false(watertight_ray_make((ray){above, {0, 0, 0}}, &wr));
    assert_false(watertight_ray_make((ray){above, {REAL_INFINITY, 0, 0}}, &wr));
}

/* A quad in a tilted plane, split along its diagonal, with coordinates that
 * are not dyadic: rays from points above it aimed at computed points of the
 * diagonal (rounded, so just off it on either side) must hit one of the two
 * halves, every one; the hit's t is the same point's up to rounding. */
static void test_no_crack_along_a_shared_edge(void **state)
{
    (void)state;
    const vec3 p0 = {(real)0.1, (real)0.2, (real)0.3}, p1 = {(real)1.7, (real)-0.4, (real)0.9},
               p2 = {(real)2.3, (real)1.3, (real)0.4};
    const vec3 p3 = vec3_add(p0, vec3_sub(p2, p1)); /* the fourth corner of the parallelogram */
    const vec3 up = vec3_normalize(vec3_cross(vec3_sub(p1, p0), vec3_sub(p3, p0)));
    unsigned long rng = 12345;
    int cracks = 0, rays = 0;
    for (int o = 0; o < 20; o++) {
        vec3 side = suite_random_unit(&rng);
        vec3 origin = vec3_add(vec3_add(p0, vec3_scale(up, (real)(2 + 3 * suite_uniform(&rng)))), side);
        for (int k = 1; k < 500; k++) {
            vec3 target = vec3_add(p0, vec3_scale(vec3_sub(p2, p0), (real)k / 500)); /* on the diagonal p0 p2 */
            ray r = {origin, vec3_sub(target, origin)};
            real first[3], second[3];
            bool h1 = hit_of(p0, p1, p2, r, 0, REAL_INFINITY, first);
            bool h2 = hit_of(p0, p2, p3, r, 0, REAL_INFINITY, second);
            cracks += !h1 && !h2;
            rays++;
            /* t = 1 at the target: to a few epsilon of the data's size over the ray's length */
            if (h1)
                assert_close(1, first[0], 64 * REAL_EPSILON);
            if (h2)
                assert_close(1, second[0], 64 * REAL_EPSILON);
        }
    }
    print_message("%d rays at the shared diagonal, %d slipped through\n", rays, cracks);
    assert_int_equal(cracks, 0);
}

/* The crossing check on vertices: a clear hit counts at both ends of the
 * range (every coordinate scaled by one power of two, which changes no
 * digit); a degenerate triangle, a direction in the plane, an origin in the
 * plane and non-finite data do not.  The quick path agrees with the full
 * computation on each. */
static void test_crossing_certain_on_vertices(void **state)
{
    (void)state;
    const vec3 a = {0, 0, 0}, b = {4, 0, 0}, c = {0, 4, 0};
    const ray clear = {{1, 1, 2}, {0, 0, -1}};
    const int scales[] = {0, ilogb(REAL_MAX) - 8, ilogb(REAL_MIN) + 8};
    for (size_t k = 0; k < sizeof scales / sizeof scales[0]; k++) {
        int e = scales[k];
        vec3 sa = vec3_ldexp(a, e), sb = vec3_ldexp(b, e), sc = vec3_ldexp(c, e);
        ray r = {vec3_ldexp(clear.p, e), vec3_ldexp(clear.d, e)};
        if (!triangle_crossing_certain(&sa, &sb, &sc, r) || !triangle_crossing_certain_exact(&sa, &sb, &sc, r))
            fail_msg("a clear hit scaled by 2^%d is not certain", e);
    }
    const struct {
        vec3 a, b, c;
        ray r;
        const char *what;
    } not_certain[] = {
        {a, b, vec3_make(2, 0, 0), clear, "collinear vertices"},
        {a, b, vec3_make(2, (real)ldexp(1, ilogb(REAL_EPSILON) - 20), 0), clear, "a sliver thinner than the slack"},
        {a, b, c, {{1, 1, 2}, {1, 0, 0}}, "a direction parallel to the plane"},
        {a, b, c, {{1, 1, 0}, {0, 0, -1}}, "an origin in the plane"},
        {a, b, vec3_make(0, REAL_INFINITY, 0), clear, "an infinite vertex"},
        {a, b, c, {{1, (real)NAN, 2}, {0, 0, -1}}, "a NaN origin"},
    };
    for (size_t k = 0; k < sizeof not_certain / sizeof not_certain[0]; k++) {
        const vec3 *a_k = &not_certain[k].a, *b_k = &not_certain[k].b, *c_k = &not_certain[k].c;
        bool quick = triangle_crossing_certain(a_k, b_k, c_k, not_certain[k].r);
        bool full = triangle_crossing_certain_exact(a_k, b_k, c_k, not_certain[k].r);
        if (quick || full)
            fail_msg("%s: certain (quick %d, full %d)", not_certain[k].what, quick, full);
    }
}

static const graded_test tests[] = {
    GRADED(test_exact_hit_from_both_sides, 0),
    GRADED(test_misses_write_nothing, 0),
    GRADED(test_no_crack_along_a_shared_edge, 0),
    GRADED(test_crossing_certain_on_vertices, 0),
};
SUITE_MAIN("common_watertight", tests)
