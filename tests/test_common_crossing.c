/* The crossing check's first test, triangle_crossing_clear (common/crossing.h):
 * on the data as they are stored, it must never call a crossing certain that
 * the full computation, triangle_crossing_certain_exact, does not, and it
 * must take the clear hits, so that the full computation runs only near an
 * edge of what the data decide.  (Chapter 03's suite compares
 * triangle_crossing_certain, which calls it first, with the full computation
 * on four million inputs at every scale.)
 *
 * The inputs: triangles in randomly rotated frames, far from the origin and
 * near it, hit inside or aimed at their edges, by rays from every side and
 * by grazing rays (a direction in the plane tilted by 2^-k, an origin in the
 * plane lifted by 2^-k of the size, k up to 80), so that the determinants
 * fall on both sides of the bounds.  No tolerance: each check is a yes or no
 * that the proof in crossing.c decides.
 */
#include <math.h>

#include "crossing.h"
#include "suite.h"

static unsigned long rng = 0x2545f4914f6cdd1dul;

static real uniform(void) { return (real)suite_uniform(&rng); }
static real power_of_two(int lo, int hi) { return (real)ldexp(1, lo + (int)(suite_uniform(&rng) * (hi - lo + 1))); }

/* A frame: an origin and three orthonormal axes (a random rotation), in
 * which the triangle lies in the plane z = 0. */
typedef struct {
    vec3 o, u, v, w;
} frame;

static frame random_frame(real distance)
{
    frame f;
    f.w = suite_random_unit(&rng);
    vec3 any = suite_random_unit(&rng);
    f.u = vec3_normalize(vec3_cross(f.w, any));
    f.v = vec3_cross(f.w, f.u);
    f.o = vec3_scale(suite_random_unit(&rng), distance);
    return f;
}

/* The point x u + y v + z w of frame f, at scale s. */
static vec3 place(const frame *f, real s, real x, real y, real z)
{
    return vec3_add(f->o, vec3_scale(vec3_add(vec3_add(vec3_scale(f->u, x), vec3_scale(f->v, y)), vec3_scale(f->w, z)), s));
}

/* A well-shaped triangle of frame f at scale s: the vertices (0, 0),
 * (1, 0) and (x, y) with x in [0, 1], y in [1/2, 1], so that no angle is
 * below 26 degrees. */
static void well_shaped(const frame *f, real s, vec3 *a, vec3 *b, vec3 *c)
{
    real x = uniform(), y = (1 + uniform()) / 2;
    *a = place(f, s, 0, 0, 0);
    *b = place(f, s, 1, 0, 0);
    *c = place(f, s, x, y, 0);
}

/* Clear hits: well-shaped triangles of sizes s = 2^-40 .. 2^60, their
 * frames up to 2^8 sizes from the origin, hit at barycentrics of at least
 * 1/10 each by a ray from 1/2 to 2 sizes above (or below) the plane, at most
 * 55 degrees from its normal, d of length 2^-10 .. 2^10 times s.  There
 * |e1 x e2| >= s^2 / 2, so |M| >= 0.29 s^2 |d| and |N| >= s^3 / 4, while
 * E1 E2 <= 1.5 s^2, F <= 4 s, 2 F + L <= 6 L.  The test's bounds, with
 * k = 96 eps (1 + 2^-18) and eps = 2^-23 in float: k E1 E2 F <= 6.4e-5 s^3
 * against |N| (a margin of 3900), 2 k E1 E2 W (2 F + L) <= 2.1e-4 L s^2 |d|
 * against TRIANGLE_POINT_SLACK L |M| >= 0.036 L s^2 |d| (a margin of 170);
 * |N| and L |M| / 8 are above 2^-250 by more than 2^70 at the smallest size
 * and length.  So every one is clear, in double and in float. */
static void test_clear_hits_are_taken(void **state)
{
    (void)state;
    enum { N = 200000 };
    int taken = 0, certain = 0;
    for (int n = 0; n < N; n++) {
        real s = power_of_two(-40, 59) * (1 + uniform());
        frame f = random_frame(s * power_of_two(0, 8) * uniform());
        vec3 a, b, c;
        well_shaped(&f, s, &a, &b, &c);
        real beta = (real)0.1 + (real)0.4 * uniform(), gamma = (real)0.1 + (real)0.4 * uniform();
        vec3 target = vec3_add(a, vec3_add(vec3_scale(vec3_sub(b, a), beta), vec3_scale(vec3_sub(c, a), gamma)));
        real height = (real)(uniform() < (real)0.5 ? -1 : 1) * ((real)0.5 + (real)1.5 * uniform());
        real x = (2 * uniform() - 1) * (real)0.5, y = (2 * uniform() - 1) * (real)0.5; /* at most 35 degrees off the normal */
        vec3 p = vec3_add(target, vec3_scale(vec3_add(vec3_add(vec3_scale(f.u, x), vec3_scale(f.v, y)), vec3_scale(f.w, height)), s));
        ray r = {p, vec3_scale(vec3_sub(target, p), power_of_two(-10, 10))};
        taken += triangle_crossing_clear(&a, &b, &c, r);
        certain += triangle_crossing_certain_exact(&a, &b, &c, r);
    }
    print_message("clear hits: %d of %d taken by the first test, %d certain in full\n", taken, N, certain);
    assert_int_equal(certain, N);
    assert_int_equal(taken, N);
}

/* Hard inputs: grazing directions, origins in or near the plane, slivers
 * and collinear vertices, rays at the edges, triangles up to 2^40 sizes from
 * the origin.  Wherever the first test says clear, the full computation must
 * say certain. */
static void test_clear_only_where_certain(void **state)
{
    (void)state;
    enum { KINDS = 5, N = 400000 };
    int wrong = 0, clear[KINDS] = {0}, certain[KINDS] = {0};
    for (int n = 0; n < N; n++) {
        int kind = n % KINDS;
        real s = power_of_two(-60, 50) * (1 + uniform());
        frame f = random_frame(s * power_of_two(0, 40) * uniform());
        vec3 a, b, c;
        well_shaped(&f, s, &a, &b, &c);
        real tilt = power_of_two(-80, 0) * (uniform() < (real)0.5 ? -1 : 1);
        vec3 target = place(&f, s, uniform(), uniform(), 0);
        vec3 p = place(&f, s, 2 * uniform() - 1, 2 * uniform() - 1, 1 + uniform());
        vec3 d = vec3_sub(target, p);
        if (kind == 0) /* grazing: a direction in the plane, tilted by 2^-k */
            d = vec3_add(vec3_sub(place(&f, s, uniform(), uniform(), 0), p), vec3_scale(f.w, s * tilt));
        if (kind == 0)
            p = place(&f, s, 2 * uniform() - 1, 2 * uniform() - 1, tilt);
        if (kind == 1) /* an origin in the plane, lifted by 2^-k of the size */
            p = place(&f, s, 2 * uniform() - 1, 2 * uniform() - 1, tilt);
        if (kind == 2) /* a sliver: c moved onto the line ab, but for 2^-k */
            c = place(&f, s, 2 * uniform() - (real)0.5, tilt, 0);
        if (kind == 3) /* collinear or coincident vertices */
            c = uniform() < (real)0.5 ? a : place(&f, s, 3, 0, 0);
        if (kind == 4) /* at an edge: the target on ab, nudged by 2^-k */
            target = place(&f, s, uniform(), tilt, 0);
        if (kind == 4)
            d = vec3_sub(target, p);
        ray r = {p, d};
        bool quick = triangle_crossing_clear(&a, &b, &c, r), full = triangle_crossing_certain_exact(&a, &b, &c, r);
        clear[kind] += quick;
        certain[kind] += full;
        if (quick && !full && wrong++ < 5)
            print_message("kind %d: clear but not certain: a = (%a, %a, %a), b = (%a, %a, %a), c = (%a, %a, %a), p = "
                          "(%a, %a, %a), d = (%a, %a, %a)\n",
                          kind, (double)a.x, (double)a.y, (double)a.z, (double)b.x, (double)b.y, (double)b.z,
                          (double)c.x, (double)c.y, (double)c.z, (double)p.x, (double)p.y, (double)p.z,
                          (double)d.x, (double)d.y, (double)d.z);
    }
    for (int k = 0; k < KINDS; k++)
        print_message("kind %d: %d clear, %d certain of %d\n", k, clear[k], certain[k], N / KINDS);
    assert_int_equal(wrong, 0);
    /* Both sides were reached: some inputs of each kind that tilts a
     * determinant towards 0 are certain and some not, else the kind tests
     * nothing near the bound (collinear vertices, rounded into their rotated
     * frame, are only nearly collinear).  A ray at an edge crosses the plane
     * clearly: kind 4 only checks the rule above. */
    for (int k = 0; k < KINDS; k++)
        if (k != 4 && (certain[k] == 0 || certain[k] == N / KINDS))
            fail_msg("kind %d: %d of %d certain: the inputs do not straddle the bound", k, certain[k], N / KINDS);
}

/* Data the first test leaves to the scaled one: non-finite coordinates,
 * coordinates of 2^100 and more (a clear hit there is still certain, by
 * the scaled test), and data so small that the determinants are below
 * 2^-250. */
static void test_clear_leaves_the_rest(void **state)
{
    (void)state;
    const vec3 a = {0, 0, 0}, b = {4, 0, 0}, c = {0, 4, 0};
    const ray hit = {{1, 1, 2}, {0, 0, -1}};
    assert_true(triangle_crossing_clear(&a, &b, &c, hit));
    const vec3 inf_c = {0, REAL_INFINITY, 0};
    assert_false(triangle_crossing_clear(&a, &b, &inf_c, hit));
    const ray nan_ray = {{1, (real)NAN, 2}, {0, 0, -1}};
    assert_false(triangle_crossing_clear(&a, &b, &c, nan_ray));
    const vec3 collinear = {2, 0, 0};
    assert_false(triangle_crossing_clear(&a, &b, &collinear, hit));
    /* scaled by 2^e: clear within the range, certain at every scale */
    const int scales[] = {-100, 90, 100, ilogb(REAL_MAX) - 8};
    const bool inside[] = {false, true, false, false}; /* -100: |N| = 2^-300 8; 100: coordinates of 2^100 */
    for (size_t k = 0; k < sizeof scales / sizeof scales[0]; k++) {
        int e = scales[k];
        vec3 sa = vec3_ldexp(a, e), sb = vec3_ldexp(b, e), sc = vec3_ldexp(c, e);
        ray r = {vec3_ldexp(hit.p, e), vec3_ldexp(hit.d, e)};
        if (triangle_crossing_clear(&sa, &sb, &sc, r) != inside[k])
            fail_msg("a clear hit scaled by 2^%d: the first test says %d", e, !inside[k]);
        if (!triangle_crossing_certain(&sa, &sb, &sc, r))
            fail_msg("a clear hit scaled by 2^%d is not certain", e);
    }
}

static const graded_test tests[] = {
    GRADED(test_clear_hits_are_taken, 0),
    GRADED(test_clear_only_where_certain, 0),
    GRADED(test_clear_leaves_the_rest, 0),
};
SUITE_MAIN("common_crossing", tests)
