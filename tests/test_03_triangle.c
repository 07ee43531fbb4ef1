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
#include "suite.h"

#include "03_triangle/cracks.h"
#include "03_triangle/icosahedron.h"
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

/* Asserts a hit of r at (t, beta, gamma) within tol. */
static void expect_hit(const triangle *tri, ray r, triangle_test test, real t, real beta, real gamma, real tol)
{
    triangle_hit h;
    if (!triangle_intersect(tri, r, 0, REAL_INFINITY, test, &h)) {
        print_error("--triangle=%s: expected a hit at beta %g, gamma %g\n", test_names[test], (double)beta,
                    (double)gamma);
        fail();
    }
    assert_close(t, h.t, tol * real_fmax(1, real_abs(t)));
    assert_close(beta, h.beta, tol);
    assert_close(gamma, h.gamma, tol);
}

/* Asserts a miss that leaves *hit untouched. */
static void expect_miss(const triangle *tri, ray r, real t_min, real t_max, triangle_test test)
{
    triangle_hit h = {-7, -7, -7};
    if (triangle_intersect(tri, r, t_min, t_max, test, &h)) {
        print_error("--triangle=%s: expected a miss, got t %g, beta %g, gamma %g\n", test_names[test], (double)h.t,
                    (double)h.beta, (double)h.gamma);
        fail();
    }
    assert_true(h.t == -7 && h.beta == -7 && h.gamma == -7);
}

/* det[c0 c1 c2] of the identity is 1; swapping two columns changes its sign. */
static void test_det3(void **state)
{
    (void)state;
    vec3 x = {1, 0, 0}, y = {0, 1, 0}, z = {0, 0, 1};
    assert_true(det3(x, y, z) == 1);
    assert_true(det3(y, x, z) == -1);
    assert_true(det3(vec3_make(1, 2, 3), vec3_make(4, 5, 6), vec3_make(7, 8, 10)) == -3);
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
            assert_true(vec3_length(triangle_normal(tri)) == 0);
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
}

/* The window is open: t_min < t < t_max.  The exact setup hits at t = 1 exactly. */
static void test_t_window(void **state)
{
    (void)state;
    vec3 x = point_at(&flat, (real)0.25, (real)0.25);
    ray r = {above, vec3_sub(x, above)};
    triangle_hit h;
    for (int k = 0; k < N_TESTS; k++) {
        assert_true(triangle_intersect(&flat, r, 0, 2, both[k], &h));
        assert_true(h.t == 1);
        assert_true(triangle_intersect(&flat, r, (real)0.999, (real)1.001, both[k], &h));
        expect_miss(&flat, r, 0, 1, both[k]);              /* t == t_max: outside */
        expect_miss(&flat, r, 1, 2, both[k]);              /* t == t_min: outside */
        expect_miss(&flat, r, (real)1.5, 9, both[k]);      /* the window lies beyond */
        expect_miss(&flat, r, 0, (real)0.5, both[k]);      /* ... or before */
        ray back = {above, vec3_neg(r.d)};                 /* the triangle behind the origin */
        expect_miss(&flat, back, 0, REAL_INFINITY, both[k]);
        assert_true(triangle_intersect(&flat, back, -REAL_INFINITY, 0, both[k], &h));
        assert_true(h.t == -1);
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
            for (int k = 0; k < N_TESTS; k++) {
                hit[k] = triangle_intersect(&tilted, r, 0, REAL_INFINITY, both[k], &h[k]);
                if (hit[k])
                    assert_vec3_close(ray_at(r, h[k].t), point_at(&tilted, h[k].beta, h[k].gamma), 10 * TOL);
            }
            bool on_edge = i == 3 || j == 3 || i + j == 20; /* beta = 0, gamma = 0, beta + gamma = 1 */
            bool inside = i >= 3 && j >= 3 && i + j <= 20;
            if (!on_edge) {
                assert_true(hit[0] == inside);
                assert_true(hit[1] == inside);
            }
            total++;
            agree += hit[0] == hit[1];
        }
    assert_true(agree >= total - 3 * 21); /* they may differ only on the edge lines */
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
    /* Legs of 1e15 and 1e-15: |n|^2 would overflow or underflow in float without care. */
    const real scales[] = {(real)1e15, (real)1e-15};
    for (int k = 0; k < 2; k++) {
        real f = scales[k];
        triangle s = {vec3_scale(tilted.a, f), vec3_scale(tilted.b, f), vec3_scale(tilted.c, f)};
        assert_vec3_close(expected, triangle_normal(&s), TOL);
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

/* From inside, through the middle of every face: each face is hit at (1/3, 1/3), from its back. */
static void test_icosahedron_from_inside(void **state)
{
    (void)state;
    vec3 v[ICOSAHEDRON_VERTICES];
    triangle faces[ICOSAHEDRON_FACES];
    icosahedron_vertices(vec3_make(0, 0, 0), 1, v);
    icosahedron_triangles(v, faces);
    for (int k = 0; k < N_TESTS; k++)
        for (int o = 0; o < 4; o++) {
            vec3 p = crack_origin(vec3_make(0, 0, 0), 1, o);
            for (int f = 0; f < ICOSAHEDRON_FACES; f++)
                expect_hit(&faces[f], (ray){p, vec3_sub(centroid(&faces[f]), p)}, both[k], 1, (real)1 / 3,
                           (real)1 / 3, TOL);
        }
}

/* The watertight test's promise: rays from inside the closed icosahedron
 * aimed exactly at its vertices and at points along its edges (midpoints
 * among them) all hit some face, for icosahedra of any size and place.
 * (Cramer's rule does not keep it: see the chapter's README for the count.) */
static void test_watertight_has_no_cracks(void **state)
{
    (void)state;
    const struct {
        vec3 centre;
        real radius;
    } cases[] = {
        {{0, 0, 0}, 1},
        {{1.3, 0.1, -0.2}, 1.1},
        {{1000, -2000, 500}, 7},
        {{0.37, 0.21, 0.13}, 1e-3},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        crack_count n = icosahedron_cracks(cases[c].centre, cases[c].radius, 20, 16, TRIANGLE_WATERTIGHT);
        assert_int_equal(20 * (12 + 30 * 15), n.rays);
        assert_int_equal(0, n.misses);
    }
}

/* near_edge: the nearest edge point, or the vertex near two edges. */
static void test_near_edge(void **state)
{
    (void)state;
    vec3 e0, e1;
    real s;
    assert_false(near_edge(&flat, (real)0.3, (real)0.3, (real)0.05, &e0, &e1, &s));
    assert_true(near_edge(&flat, (real)0.5, (real)0.01, (real)0.05, &e0, &e1, &s)); /* near ab (gamma small) */
    assert_vec3_close(flat.a, e0, 0);
    assert_vec3_close(flat.b, e1, 0);
    assert_close((real)0.5 / (real)0.99, s, TOL);
    assert_true(near_edge(&flat, (real)0.01, (real)0.98, (real)0.05, &e0, &e1, &s)); /* near c */
    assert_vec3_close(flat.c, e0, 0);
    assert_vec3_close(flat.c, e1, 0);
}

static const graded_test tests[] = {
    GRADED(test_det3, 0), /* handed out complete: no points */
    GRADED(test_centroid, 3),
    GRADED(test_vertices_and_edge_midpoints, 3),
    GRADED(test_just_outside, 2),
    GRADED(test_parallel_ray, 2),
    GRADED(test_degenerate_triangles, 2),
    GRADED(test_tiny_triangle, 2),
    GRADED(test_far_triangles, 2),
    GRADED(test_grazing_rays, 2),
    GRADED(test_t_window, 2),
    GRADED(test_hit_point_is_consistent, 2),
    GRADED(test_normal, 0), /* handed out complete: no points */
    GRADED(test_icosahedron_is_closed, 0), /* handed out complete: no points */
    GRADED(test_icosahedron_from_inside, 2),
    GRADED(test_watertight_has_no_cracks, 0), /* handed out complete: no points */
    GRADED(test_near_edge, 0), /* handed out complete: no points */
};

SUITE_MAIN("03_triangle", tests)
