/* test_02_sphere.c - chapter 02: the ray-sphere intersection.
 *
 * Concrete cases first (each checks a hit next to every miss, so that an
 * unfinished function that always says "no hit" fails them), then a sweep of
 * far, small spheres where the robust formula must stay right.  Tolerances
 * are in units of REAL_EPSILON, so the float build runs the same tests.
 */
#include <stdio.h>

#include "02_sphere/sphere.h"
#include "suite.h"

/* Simple cases (t exact in a few operations): a handful of roundings. */
#define TOL(x) (8 * REAL_EPSILON * (x))

static const sphere unit = {{0, 0, 0}, 1};

static ray make_ray(real px, real py, real pz, real dx, real dy, real dz)
{
    return (ray){vec3_make(px, py, pz), vec3_make(dx, dy, dz)};
}

/* Asserts a hit at t_expected with normal n_expected. */
static void expect_hit(const sphere *s, ray r, real t_min, real t_max, sphere_formula formula, real t_expected,
                       vec3 n_expected)
{
    real t = -1;
    vec3 n = {0, 0, 0};
    assert_true(sphere_intersect(s, r, t_min, t_max, formula, &t, &n));
    assert_close(t_expected, t, TOL(t_expected));
    assert_vec3_close(n_expected, n, TOL(1));
}

static void expect_miss(const sphere *s, ray r, real t_min, real t_max, sphere_formula formula)
{
    real t = 12345;
    vec3 n = {0, 0, 0};
    assert_false(sphere_intersect(s, r, t_min, t_max, formula, &t, &n));
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
    expect_hit(&unit, make_ray(1, 0, 5, 0, 0, -1), 0, REAL_INFINITY, f, 5, vec3_make(1, 0, 0));
    expect_miss(&unit, make_ray(1 + (real)0x1p-10, 0, 5, 0, 0, -1), 0, REAL_INFINITY, f);
    real t, x = 1 - (real)0x1p-10;
    vec3 n;
    assert_true(sphere_intersect(&unit, make_ray(x, 0, 5, 0, 0, -1), 0, REAL_INFINITY, f, &t, &n));
    /* Near a tangent the root is sensitive: an error e in the discriminant
     * moves t by e / (2 sqrt(disc)).  Both formulas' discriminants err by at
     * most about 4 eps (B^2 + |A C|) = 4 eps (25 + 25) here. */
    real disc = 1 - x * x;
    assert_close(5 - real_sqrt(disc), t, TOL(5) + 200 * REAL_EPSILON / (2 * real_sqrt(disc)));
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

/* d -> alpha d is the same ray with t -> t / alpha (lecture, "Ray: a half line"). */
static void scaled_case(sphere_formula f)
{
    const sphere s = {{1, -2, 0.5}, 1.5};
    const vec3 p = {4, 1, 3}, d = {-0.6, -0.7, -0.4};
    real t1;
    vec3 n1;
    assert_true(sphere_intersect(&s, (ray){p, d}, 0, REAL_INFINITY, f, &t1, &n1));
    const real alphas[] = {(real)1e-3, (real)0.37, 2, (real)1e3};
    for (int k = 0; k < 4; k++) {
        real t;
        vec3 n;
        assert_true(sphere_intersect(&s, (ray){p, vec3_scale(d, alphas[k])}, 0, REAL_INFINITY, f, &t, &n));
        assert_close(t1, t * alphas[k], 16 * REAL_EPSILON * t1); /* a few roundings in each of t and t1 */
        assert_vec3_close(n1, n, 16 * REAL_EPSILON);
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
        assert_true(sphere_intersect(&s, (ray){p, d}, 0, REAL_INFINITY, SPHERE_ROBUST, &t, &n));
        vec3 x = ray_at((ray){p, d}, t);
        assert_close(1, vec3_length(n), 4 * REAL_EPSILON);
        assert_vec3_close(vec3_scale(vec3_sub(x, s.center), 1 / s.radius), n, 32 * REAL_EPSILON);
        assert_true(vec3_dot(n, d) < 0);
        /* from the centre outwards: the exit point, normal along d */
        assert_true(sphere_intersect(&s, (ray){s.center, vec3_neg(d)}, 0, REAL_INFINITY, SPHERE_ROBUST, &t, &n));
        assert_true(vec3_dot(n, vec3_neg(d)) > 0);
        assert_close(1, vec3_length(n), 4 * REAL_EPSILON);
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
