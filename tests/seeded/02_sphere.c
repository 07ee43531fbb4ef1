/* Chapter 02's checks of inputs drawn at grading time (tests/answers.h):
 * the roots by either formula, the nearest root in a window, the normal
 * and the whole intersection, for spheres and rays drawn from the grader's
 * seed, against the reference's answers.
 *
 * The rays start outside the sphere (1.5 R to 60 from its centre) and aim
 * at a point inside 0.7 R of the centre (a hit: the discriminant is far
 * from 0) or beyond 1.3 R (a miss), so every answer is well conditioned:
 * a root is a few roundings of t (of size (|p - c| + R) / |d|) plus the
 * rounding of p - c, (|p| + |c|) REAL_EPSILON / |d|; 256 of those leave
 * room for two correct formulas.  The textbook formula loses a further
 * factor |p - c| / R in its small root (cancellation).  The normal at the
 * hit carries the hit point's error divided by R. */
#include "02_sphere/sphere.h"
#include "seeded.h"

typedef struct {
    sphere s;
    ray r;
    double extent; /* |p - c| + R + |p| + |c|: the scale of lengths */
    double size;   /* extent / |d|: the scale of t */
    double ratio;  /* |p - c| / R */
} sphere_case;

/* A sphere and a ray from outside it, aimed inside (hit) or beside it. */
static sphere_case draw(unsigned long *rng, int hit)
{
    sphere_case k;
    k.s.center = seeded_point(rng, 50);
    k.s.radius = (real)seeded_between(rng, 0.5, 10);
    double dist = seeded_between(rng, 1.5 * k.s.radius, 60);
    k.r.p = vec3_add(k.s.center, vec3_scale(suite_random_unit(rng), (real)dist));
    double aim = hit ? seeded_between(rng, 0, 0.7) : seeded_between(rng, 1.3, 3);
    vec3 target = vec3_add(k.s.center, vec3_scale(suite_random_unit(rng), k.s.radius * (real)aim));
    k.r.d = vec3_scale(vec3_normalize(vec3_sub(target, k.r.p)), (real)pow(10, seeded_between(rng, -1, 1)));
    k.extent = dist + k.s.radius + vec3_length(k.r.p) + vec3_length(k.s.center);
    k.size = k.extent / vec3_length(k.r.d);
    k.ratio = dist / k.s.radius;
    return k;
}

static const char *describe_case(const sphere_case *k)
{
    return describe("sphere at (%.9g, %.9g, %.9g), R = %.9g; ray p = (%.9g, %.9g, %.9g), d = (%.9g, %.9g, %.9g)",
                    k->s.center.x, k->s.center.y, k->s.center.z, k->s.radius, k->r.p.x, k->r.p.y, k->r.p.z,
                    k->r.d.x, k->r.d.y, k->r.d.z);
}

static void answer_roots(unsigned long *rng, sphere_formula formula)
{
    for (int n = 0; n < 8; n++) {
        sphere_case k = draw(rng, 1);
        real t0 = 0, t1 = 0;
        bool real_roots = sphere_roots(&k.s, k.r, formula, &t0, &t1);
        const char *in = describe("sphere_roots(%s, %s)", describe_case(&k),
                                  formula == SPHERE_ROBUST ? "robust" : "textbook");
        double tol = 256 * REAL_EPSILON * k.size * (formula == SPHERE_TEXTBOOK ? k.ratio : 1);
        suite_answer(describe("%s: real roots", in), real_roots, 0);
        suite_answer(describe("%s: the smaller root", in), real_roots ? fmin(t0, t1) : 0, tol);
        suite_answer(describe("%s: the larger root", in), real_roots ? fmax(t0, t1) : 0, tol);
    }
}

static void seeded_robust(unsigned long *rng) { answer_roots(rng, SPHERE_ROBUST); }
static void seeded_textbook(unsigned long *rng) { answer_roots(rng, SPHERE_TEXTBOOK); }

/* Roots and windows on a grid of quarters, so that no root is within a
 * rounding of a window's end: the answer is exact. */
static void seeded_nearest(unsigned long *rng)
{
    for (int n = 0; n < 12; n++) {
        real t0 = (real)(0.25 * (int)seeded_between(rng, -40, 40));
        real t1 = (real)(0.25 * (int)seeded_between(rng, -40, 40));
        real lo = (real)(0.25 * (int)seeded_between(rng, -40, 20) + 0.125);
        real hi = n % 3 == 0 ? REAL_INFINITY : lo + (real)(0.25 * (int)seeded_between(rng, 1, 40));
        real t = 0;
        bool found = sphere_nearest_root(t0, t1, lo, hi, &t);
        const char *in = describe("sphere_nearest_root(%g, %g, t_min %g, t_max %g)", t0, t1, lo, hi);
        suite_answer(describe("%s: found", in), found, 0);
        suite_answer(describe("%s: t", in), found ? t : 0, 0);
    }
}

static void seeded_normal(unsigned long *rng)
{
    for (int n = 0; n < 8; n++) {
        sphere s = {seeded_point(rng, 50), (real)seeded_between(rng, 0.5, 10)};
        vec3 x = vec3_add(s.center, vec3_scale(suite_random_unit(rng), s.radius));
        vec3 normal = sphere_normal(&s, x);
        suite_answer_vec3(describe("sphere_normal(sphere at (%.9g, %.9g, %.9g), R = %.9g; x = (%.9g, %.9g, %.9g))",
                                   s.center.x, s.center.y, s.center.z, s.radius, x.x, x.y, x.z),
                          normal, 64 * REAL_EPSILON * (1 + vec3_length(s.center) / s.radius));
    }
}

static void seeded_intersect(unsigned long *rng)
{
    for (int n = 0; n < 10; n++) {
        sphere_case k = draw(rng, n % 3 != 2);
        real t = 0;
        vec3 normal = {0, 0, 0};
        bool hit = sphere_intersect(&k.s, k.r, 0, REAL_INFINITY, SPHERE_ROBUST, &t, &normal);
        const char *in = describe("sphere_intersect(%s, window (0, inf), robust)", describe_case(&k));
        suite_answer(describe("%s: hit", in), hit, 0);
        suite_answer(describe("%s: t", in), hit ? t : 0, 256 * REAL_EPSILON * k.size);
        if (!hit)
            normal = vec3_make(0, 0, 0);
        suite_answer_vec3(describe("%s: n", in), normal, 256 * REAL_EPSILON * k.extent / k.s.radius);
    }
}

SEEDED_CHECKS(SEEDED(test_roots_robust, seeded_robust), SEEDED(test_roots_textbook, seeded_textbook),
              SEEDED(test_b_zero_sign, seeded_robust), SEEDED(test_small_root_near_surface, seeded_robust),
              SEEDED(test_tangent_rays_from_the_surface, seeded_robust), SEEDED(test_nearest_root, seeded_nearest),
              SEEDED(test_ray_on_surface, seeded_intersect),
              SEEDED(test_normal_unit_far_from_origin, seeded_normal), SEEDED(test_hit, seeded_intersect),
              SEEDED(test_miss, seeded_intersect), SEEDED(test_tangent, seeded_intersect),
              SEEDED(test_origin_inside, seeded_intersect), SEEDED(test_sphere_behind, seeded_intersect),
              SEEDED(test_t_window, seeded_intersect), SEEDED(test_non_unit_d, seeded_intersect),
              SEEDED(test_outward_normal, seeded_intersect), SEEDED(test_textbook, seeded_textbook),
              SEEDED(test_far_spheres, seeded_robust))
