/* Chapter 03's checks of inputs drawn at grading time (tests/answers.h):
 * Cramer's rule, alone (triangle_cramer) and behind the given checks
 * (triangle_intersect with TRIANGLE_CRAMER), for triangles and rays drawn
 * from the grader's seed, against the reference's answers.
 *
 * The triangles are well shaped (vertices 1 to 10 from a centre, every
 * angle of the fan between them at least 0.5 radians), the rays start 5 to
 * 60 away and meet the plane at least 0.3 from grazing, aimed well inside
 * (barycentrics 0.1 to 0.8) or well outside: the system's determinant is
 * then of the size of |d| times the triangle's area, and each unknown a
 * few roundings of the data's size, (|p| + |a| + distance) REAL_EPSILON,
 * over that; 1024 of those (in units of t, or of the triangle's size for
 * beta and gamma) leave room for any correct order of operations. */
#include "03_triangle/triangle.h"
#include "seeded.h"

typedef struct {
    triangle tri;
    ray r;
    double extent; /* |p| + |centre| + distance + size: the scale of lengths */
    double size;   /* the triangle's smallest vertex distance from its centre */
} triangle_case;

static triangle_case draw(unsigned long *rng, int hit)
{
    triangle_case k;
    vec3 centre = seeded_point(rng, 50), n = suite_random_unit(rng);
    vec3 e = seeded_at_angle(rng, n, acos(0.0)), f = vec3_cross(n, e);
    double angle = 0, r[3];
    vec3 v[3];
    for (int i = 0; i < 3; i++) { /* a fan of three vertices about the centre */
        angle += seeded_between(rng, 0.5, 2.5);
        r[i] = seeded_between(rng, 1, 10);
        v[i] = vec3_add(centre, vec3_add(vec3_scale(e, (real)(r[i] * cos(angle))),
                                         vec3_scale(f, (real)(r[i] * sin(angle)))));
    }
    k.tri = (triangle){v[0], v[1], v[2]};
    k.size = fmin(r[0], fmin(r[1], r[2]));
    double beta = seeded_between(rng, 0.1, 0.45), gamma = seeded_between(rng, 0.1, 0.45);
    if (!hit) /* beside an edge: a barycentric below -0.2 */
        beta = -seeded_between(rng, 0.2, 1);
    vec3 target = vec3_add(k.tri.a, vec3_add(vec3_scale(vec3_sub(k.tri.b, k.tri.a), (real)beta),
                                             vec3_scale(vec3_sub(k.tri.c, k.tri.a), (real)gamma)));
    vec3 side = seeded_point(rng, 1);
    vec3 towards = vec3_normalize(vec3_add(n, vec3_scale(side, (real)0.9))); /* far from the plane's direction */
    double dist = seeded_between(rng, 5, 60);
    k.r.p = vec3_add(target, vec3_scale(towards, (real)dist));
    k.r.d = vec3_scale(vec3_sub(target, k.r.p), (real)(pow(10, seeded_between(rng, -1, 1)) / dist));
    k.extent = vec3_length(k.r.p) + vec3_length(centre) + dist + 10;
    return k;
}

static void answer_hit(const char *in, bool hit, triangle_hit h, const triangle_case *k)
{
    double t_tol = 1024 * REAL_EPSILON * k->extent / vec3_length(k->r.d);
    double bary_tol = 1024 * REAL_EPSILON * k->extent / k->size;
    suite_answer(describe("%s: hit", in), hit, 0);
    suite_answer(describe("%s: t", in), hit ? h.t : 0, t_tol);
    suite_answer(describe("%s: beta", in), hit ? h.beta : 0, bary_tol);
    suite_answer(describe("%s: gamma", in), hit ? h.gamma : 0, bary_tol);
}

static void seeded_cramer(unsigned long *rng)
{
    for (int n = 0; n < 10; n++) {
        triangle_case k = draw(rng, n % 3 != 2);
        const char *in = describe("triangle (%.9g, %.9g, %.9g) (%.9g, %.9g, %.9g) (%.9g, %.9g, %.9g), ray p = "
                                  "(%.9g, %.9g, %.9g), d = (%.9g, %.9g, %.9g), window (0, inf)",
                                  k.tri.a.x, k.tri.a.y, k.tri.a.z, k.tri.b.x, k.tri.b.y, k.tri.b.z, k.tri.c.x,
                                  k.tri.c.y, k.tri.c.z, k.r.p.x, k.r.p.y, k.r.p.z, k.r.d.x, k.r.d.y, k.r.d.z);
        triangle_hit h = {0, 0, 0};
        bool hit = triangle_cramer(&k.tri, k.r, 0, REAL_INFINITY, &h);
        answer_hit(describe("triangle_cramer(%s)", in), hit, h, &k);
        h = (triangle_hit){0, 0, 0};
        hit = triangle_intersect(&k.tri, k.r, 0, REAL_INFINITY, TRIANGLE_CRAMER, &h);
        answer_hit(describe("triangle_intersect(%s, cramer)", in), hit, h, &k);
    }
}

SEEDED_CHECKS(SEEDED(test_centroid, seeded_cramer), SEEDED(test_vertices_and_edge_midpoints, seeded_cramer),
              SEEDED(test_just_outside, seeded_cramer), SEEDED(test_parallel_ray, seeded_cramer),
              SEEDED(test_degenerate_triangles, seeded_cramer),
              SEEDED(test_cramer_alone_rejects_what_it_cannot_solve, seeded_cramer),
              SEEDED(test_tiny_triangle, seeded_cramer), SEEDED(test_far_triangles, seeded_cramer),
              SEEDED(test_grazing_rays, seeded_cramer), SEEDED(test_t_window, seeded_cramer),
              SEEDED(test_hit_point_is_consistent, seeded_cramer), SEEDED(test_degenerate_rounded, seeded_cramer),
              SEEDED(test_rays_in_the_plane, seeded_cramer), SEEDED(test_origin_on_the_triangle, seeded_cramer),
              SEEDED(test_range_ends, seeded_cramer), SEEDED(test_icosahedron_from_inside, seeded_cramer))
