/* grid_cases.h - the cases where grids break, for any grid that answers chapter 04's query.
 *
 * Included by the suites of chapter 11's two grids, the lesson's
 * (test_11_grid.c) and the lab's fast one (lab_11_grid.c), after they
 * define what is tested:
 *
 *     GRID, GRID_OPTIONS            the grid's types
 *     GRID_BUILD, GRID_INTERSECT,   its functions, with grid_build's,
 *     GRID_FREE, GRID_DEFAULTS()    grid_intersect's and grid_free's shapes
 *     GRID_QUERY, GRID_QUERY_KNOBS  its build_query_fn and the knobs it takes
 *     knob_sets[], N_KNOB_SETS      the options every random ray is tried with
 *
 * The grid must give exactly the answer of chapter 04's linear scan: for
 * every ray the same surface (or the same miss) and bit for bit the same t,
 * since both call surface_intersect on the same ray and window and keep the
 * smallest t, the first in the list among equal ones.  So the cases compare
 * the grid with surfaces_intersect and allow no tolerance at all: `same_hit`
 * compares t with ==, and every other field of the record.  They do so on
 * random scenes (arithmetic that is not exact, far from the origin) and on
 * the cases where grids usually break: directions with +0 and -0
 * components, origins outside the grid and on its faces, edges and corners,
 * flat scenes, one huge surface among thousands of tiny ones, rays that
 * start inside a cell of a surface that spans many cells, and ties; then
 * every scene of the course and the built-in scenes of chapters 05-11.
 */
#ifndef TESTS_GRID_CASES_H
#define TESTS_GRID_CASES_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "01_camera_rays/camera.h"
#include "04_many_shapes/closest_hit.h"
#include "04_many_shapes/surface.h"
#include "05_lambert/scenes/shading_scene.h"
#include "08_mirrors/scenes/mirror_scene.h"
#include "09_refraction/scenes/glass_scene.h"
#include "10_interpolation/scenes/interp_scene.h"
#include "10_interpolation/shade_interp.h"
#include "11_grid/scenes/grid_scene.h"
#include "image.h"
#include "scene_build.h"
#include "suite.h"

static const sphere_formula formulas[] = {SPHERE_ROBUST, SPHERE_TEXTBOOK};
static const triangle_test triangle_tests[] = {TRIANGLE_CRAMER, TRIANGLE_WATERTIGHT};

/* ---- random numbers and random scenes --------------------------------------------- */

static uint64_t rng_state;
static uint64_t next_u64(void)
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}
/* Uniform in [lo, hi). */
static real uniform(real lo, real hi) { return lo + (hi - lo) * (real)((double)(next_u64() >> 11) * 0x1p-53); }
/* Drawn x, y, z in this order: the order of a call's arguments (or of an
 * initialiser's values) is the compiler's choice, and random draws in them
 * would give gcc and clang different data.  Every draw below is a statement
 * or declarator of its own for that reason. */
static vec3 uniform_vec(vec3 lo, vec3 hi)
{
    real x = uniform(lo.x, hi.x), y = uniform(lo.y, hi.y), z = uniform(lo.z, hi.z);
    return vec3_make(x, y, z);
}
static vec3 random_direction(void)
{
    for (;;) {
        vec3 d = uniform_vec(vec3_make(-1, -1, -1), vec3_make(1, 1, 1));
        real l = vec3_length(d);
        if (l > (real)0.1 && l <= 1)
            return d;
    }
}

/* n random surfaces (spheres and triangles, mostly small, a few large) in
 * the box centre +- half. */
static void random_scene(surface_list *list, int n, vec3 centre, real half)
{
    vec3 lo = vec3_sub(centre, vec3_make(half, half, half)), hi = vec3_add(centre, vec3_make(half, half, half));
    for (int k = 0; k < n; k++) {
        real size = half * (next_u64() % 16 == 0 ? uniform((real)0.2, (real)0.8) : uniform((real)0.01, (real)0.1));
        vec3 c = uniform_vec(lo, hi);
        if (next_u64() % 2) {
            surface_list_add_sphere(list, (sphere){c, size}, k % 7, k);
        } else {
            triangle t = {vec3_add(c, vec3_scale(random_direction(), size)),
                          vec3_add(c, vec3_scale(random_direction(), size)),
                          vec3_add(c, vec3_scale(random_direction(), size))};
            surface_list_add_triangle(list, t, k % 7, k);
        }
    }
}

/* ---- the same answer as the linear scan ------------------------------------------- */

/* Both found nothing, or both found the same surface at the same t (==, no
 * tolerance) with the same record. */
static bool same_hit(bool found_list, const hit_record *a, bool found_grid, const hit_record *b)
{
    if (found_list != found_grid)
        return false;
    if (!found_list)
        return true;
    return a->t == b->t && a->surface == b->surface && a->source == b->source && a->shader == b->shader &&
           a->beta == b->beta && a->gamma == b->gamma && a->point.x == b->point.x && a->point.y == b->point.y &&
           a->point.z == b->point.z && a->normal.x == b->normal.x && a->normal.y == b->normal.y &&
           a->normal.z == b->normal.z;
}

/* The grid of `list` with the knobs `opt`; fails with the build's message. */
static void build_grid(GRID *g, const surface_list *list, GRID_OPTIONS opt)
{
    char err[256];
    if (GRID_BUILD(g, list, opt, err, sizeof err) != 0)
        fail_msg("GRID_BUILD: %s", err);
}

/* The grid of `list` with the given knobs answers every ray as the linear
 * scan did (`expected`, `found`); fails naming the first ray that differs. */
static void compare_grid(const surface_list *list, GRID_OPTIONS opt, const ray *rays, const real *t_min,
                         const real *t_max, long n, const hit_record *expected, const bool *found)
{
    GRID g;
    build_grid(&g, list, opt);
    for (long k = 0; k < n; k++) {
        hit_record b = {0};
        bool fb = GRID_INTERSECT(&g, rays[k], t_min[k], t_max[k], &b);
        if (!same_hit(found[k], &expected[k], fb, &b)) {
            GRID_FREE(&g);
            fail_msg("ray %ld: p = (%.17g, %.17g, %.17g), d = (%.17g, %.17g, %.17g), t in (%g, %g), density %g, "
                     "cap %ld: linear scan %s surface %d at t = %.17g, "
                     "grid %s surface %d at t = %.17g",
                     k, (double)rays[k].p.x, (double)rays[k].p.y, (double)rays[k].p.z, (double)rays[k].d.x,
                     (double)rays[k].d.y, (double)rays[k].d.z, (double)t_min[k], (double)t_max[k], opt.density,
                     opt.max_cells, found[k] ? "hits" : "misses", found[k] ? expected[k].surface : -1,
                     found[k] ? (double)expected[k].t : 0.0, fb ? "hits" : "misses", fb ? b.surface : -1,
                     fb ? (double)b.t : 0.0);
        }
    }
    GRID_FREE(&g);
}

/* The linear scan's answers to the rays; returns how many hit something,
 * so that a test can check it compared hits and not only misses. */
static long linear_answers(const surface_list *list, const ray *rays, const real *t_min, const real *t_max, long n,
                           hit_record *expected, bool *found)
{
    long hits = 0;
    for (long k = 0; k < n; k++) {
        expected[k] = (hit_record){0};
        found[k] = surfaces_intersect(list, rays[k], t_min[k], t_max[k], &expected[k]);
        hits += found[k];
    }
    return hits;
}

/* The same through grids of every option set of the suite. */
static long compare_all_knobs(const surface_list *list, const ray *rays, const real *t_min, const real *t_max,
                              long n)
{
    hit_record *expected = malloc((size_t)n * sizeof *expected);
    bool *found = malloc((size_t)n * sizeof *found);
    assert_non_null(expected);
    assert_non_null(found);
    long hits = linear_answers(list, rays, t_min, t_max, n, expected, found);
    for (size_t k = 0; k < N_KNOB_SETS; k++)
        compare_grid(list, knob_sets[k], rays, t_min, t_max, n, expected, found);
    free(expected);
    free(found);
    return hits;
}

typedef struct {
    ray *r;
    real *t_min, *t_max;
    long n;
} ray_set;

static ray_set rays_alloc(long n)
{
    ray_set s = {malloc((size_t)n * sizeof(ray)), malloc((size_t)n * sizeof(real)), malloc((size_t)n * sizeof(real)),
                 n};
    assert_non_null(s.r);
    assert_non_null(s.t_min);
    assert_non_null(s.t_max);
    return s;
}
static void rays_free(ray_set *s)
{
    free(s->r);
    free(s->t_min);
    free(s->t_max);
}

/* Ray k of the set: p + t d for t in (0, infinity), as eye rays are. */
static void set_ray(ray_set *s, long k, vec3 p, vec3 d)
{
    s->r[k] = (ray){p, d};
    s->t_min[k] = 0;
    s->t_max[k] = REAL_INFINITY;
}

/* The grid answers every ray of the set as the linear scan does, with every
 * knob (compare_all_knobs); more than min_hits of the rays must hit
 * something, so that hits were compared and not only misses.  Frees the
 * rays and the list. */
static void expect_as_linear(surface_list *list, ray_set *rays, long min_hits)
{
    long hits = compare_all_knobs(list, rays->r, rays->t_min, rays->t_max, rays->n);
    if (hits <= min_hits)
        fail_msg("only %ld of %ld rays hit something (more than %ld expected): too few hits were compared", hits,
                 rays->n, min_hits);
    rays_free(rays);
    surface_list_free(list);
}

/* Random scenes of spheres and triangles, far from the origin, with both
 * sphere formulas and both triangle tests: rays from outside the scene, from
 * inside it, with t_min > 0 (rays that start part-way) and finite t_max
 * (segments, as shadow rays are).  400 000 grid rays in all. */
static void test_random_scenes(void **state)
{
    (void)state;
    rng_state = 11;
    const long n = 5000;
    ray_set rays = rays_alloc(n);
    long hits = 0, total = 0;
    for (int scene_no = 0; scene_no < 4; scene_no++) {
        surface_list list;
        surface_list_init(&list, formulas[scene_no % 2], triangle_tests[scene_no / 2]);
        vec3 centre = uniform_vec(vec3_make(-300, -300, -300), vec3_make(300, 300, 300));
        real half = uniform(1, 40);
        random_scene(&list, 150 + 50 * scene_no, centre, half);
        for (long k = 0; k < n; k++) {
            int kind = (int)(k % 4);
            vec3 target = vec3_add(centre, vec3_scale(random_direction(), half));
            vec3 p = kind == 0 ? vec3_add(centre, vec3_scale(random_direction(), 4 * half)) /* outside */
                               : vec3_add(centre, vec3_scale(random_direction(), half)); /* inside */
            rays.r[k] = (ray){p, kind == 3 ? random_direction() : vec3_sub(target, p)};
            rays.t_min[k] = kind == 2 ? uniform(0, (real)0.5) : 0;
            rays.t_max[k] = kind == 3 ? uniform(0, half) : REAL_INFINITY;
        }
        hits += compare_all_knobs(&list, rays.r, rays.t_min, rays.t_max, n);
        total += n;
        surface_list_free(&list);
    }
    rays_free(&rays);
    /* The rays must have found something to compare: most aim at the scene. */
    assert_true(hits > total / 4);
}

/* ---- where grids break --------------------------------------------------------------- */

/* Rays whose direction has +0 and -0 components, along the axes and in the
 * axis planes, some exactly on the planes between cells and on the faces of
 * axis-aligned boxes. */
static void test_zero_components(void **state)
{
    (void)state;
    rng_state = 12;
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_CRAMER);
    /* Boxes on a lattice of whole numbers (their faces lie on cell planes of
     * a grid of unit cells), and random spheres and triangles among them. */
    scene desc;
    scene_init(&desc);
    for (int k = 0; k < 40; k++) {
        vec3 lo = vec3_make((real)(k % 5), (real)(k / 5 % 4), (real)(k / 20));
        scene_add_surface(&desc, (scene_surface){.kind = SURFACE_BOX, .shader = -1, .min_pt = lo,
                                                 .max_pt = vec3_add(lo, vec3_make((real)0.5, (real)0.5, 1))});
    }
    char err[256];
    assert_int_equal(0, surface_list_from_scene(&list, &desc, err, sizeof err));
    scene_free(&desc);
    random_scene(&list, 60, vec3_make((real)2.5, 2, 1), 2);
    const long n = 24000;
    ray_set rays = rays_alloc(n);
    static const real zeros[2] = {0.0, -0.0};
    for (long k = 0; k < n; k++) {
        /* p on a lattice point, a half-lattice point or anywhere; one or two
         * of d's components +0 or -0 */
        long kind = k % 3;
        vec3 p;
        if (kind == 0) {
            real x = (real)(next_u64() % 12) / 2 - 1, y = (real)(next_u64() % 10) / 2 - 1;
            p = vec3_make(x, y, (real)(next_u64() % 6) / 2 - 1);
        } else if (kind == 1) {
            real x = (real)(next_u64() % 7) - 1, y = uniform(-1, 5);
            p = vec3_make(x, y, (real)(next_u64() % 4) - 1);
        } else {
            p = uniform_vec(vec3_make(-2, -2, -2), vec3_make(7, 6, 4));
        }
        vec3 c_vec = uniform_vec(vec3_make(-1, -1, -1), vec3_make(1, 1, 1));
        real c[3] = {c_vec.x, c_vec.y, c_vec.z};
        int first = (int)(next_u64() % 3);
        c[first] = zeros[next_u64() % 2];
        if (k % 2)
            c[(first + 1) % 3] = zeros[next_u64() % 2];
        set_ray(&rays, k, p, vec3_make(c[0], c[1], c[2]));
    }
    expect_as_linear(&list, &rays, n / 10);
}

/* Origins outside the grid, on its faces, edges and corners, looking in,
 * out and along them. */
static void test_origins_on_the_grid(void **state)
{
    (void)state;
    rng_state = 13;
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
    const vec3 centre = {(real)17.3, (real)-4.1, (real)9.7};
    random_scene(&list, 300, centre, 3);
    GRID g;
    build_grid(&g, &list, GRID_DEFAULTS());
    const vec3 lo = g.lo, hi = g.hi;
    GRID_FREE(&g);
    const long n = 30000;
    ray_set rays = rays_alloc(n);
    for (long k = 0; k < n; k++) {
        /* Each coordinate at the box's low or high side, or inside, or
         * outside: corners, edges, faces, interior and exterior points. */
        real c[3];
        const real l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
        for (int a = 0; a < 3; a++) {
            switch (next_u64() % 4) {
            case 0: c[a] = l[a]; break;
            case 1: c[a] = h[a]; break;
            case 2: c[a] = uniform(l[a], h[a]); break;
            default: c[a] = uniform(l[a] - 10, h[a] + 10); break;
            }
        }
        vec3 p = vec3_make(c[0], c[1], c[2]);
        vec3 d = k % 2 ? vec3_sub(vec3_add(centre, vec3_scale(random_direction(), 3)), p) : random_direction();
        if (k % 5 == 0) /* along a face: one component zero */
            d = vec3_make(d.x, 0, d.z);
        set_ray(&rays, k, p, d);
    }
    expect_as_linear(&list, &rays, n / 10);
}

/* Scenes flat in one axis (zero extent): triangles in the plane z = 2.7, and
 * a second scene in the plane x = -1.3, met by rays from above, at grazing
 * angles, and lying in the plane. */
static void test_flat_scenes(void **state)
{
    (void)state;
    rng_state = 14;
    for (int axis = 0; axis < 2; axis++) {
        surface_list list;
        surface_list_init(&list, SPHERE_ROBUST, triangle_tests[axis]);
        const real plane = axis == 0 ? (real)2.7 : (real)-1.3;
        for (int k = 0; k < 500; k++) {
            vec3 v[3];
            real u0 = uniform(-5, 5), w0 = uniform(-5, 5);
            for (int j = 0; j < 3; j++) {
                real u = u0 + uniform((real)-0.4, (real)0.4), w = w0 + uniform((real)-0.4, (real)0.4);
                v[j] = axis == 0 ? vec3_make(u, w, plane) : vec3_make(plane, u, w);
            }
            surface_list_add_triangle(&list, (triangle){v[0], v[1], v[2]}, k % 3, k);
        }
        GRID g;
        build_grid(&g, &list, GRID_DEFAULTS());
        /* The flat axis has one cell, the others share the rest. */
        assert_int_equal(1, g.n[axis == 0 ? 2 : 0]);
        assert_true(g.n[1] > 4);
        GRID_FREE(&g);
        const long n = 20000;
        ray_set rays = rays_alloc(n);
        for (long k = 0; k < n; k++) {
            real s1 = uniform(-5, 5), s2 = uniform(-5, 5);
            vec3 target = axis == 0 ? vec3_make(s1, s2, plane) : vec3_make(plane, s1, s2);
            vec3 off = random_direction();
            if (k % 4 == 0) /* in the plane: parallel to every triangle */
                off = axis == 0 ? vec3_make(off.x, off.y, 0) : vec3_make(0, off.y, off.z);
            else if (k % 4 == 1) /* grazing */
                off = axis == 0 ? vec3_make(off.x, off.y, off.z * (real)1e-3)
                                : vec3_make(off.x * (real)1e-3, off.y, off.z);
            vec3 p = vec3_add(target, vec3_scale(off, 8));
            set_ray(&rays, k, p, vec3_sub(target, p));
        }
        expect_as_linear(&list, &rays, n / 10);
    }
}

/* One huge triangle and one huge sphere among 3000 tiny triangles: the huge
 * ones span most cells, the tiny ones set the resolution. */
static void test_huge_among_tiny(void **state)
{
    (void)state;
    rng_state = 15;
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_CRAMER);
    surface_list_add_triangle(&list, (triangle){{-90, -3, -80}, {85, -2, -70}, {0, 4, 95}}, 1, 0);
    random_scene(&list, 1500, vec3_make(0, 0, 0), 6);
    surface_list_add_sphere(&list, (sphere){{3, 1, -2}, (real)70.5}, 2, 1);
    random_scene(&list, 1500, vec3_make(1, 2, 3), 5);
    const long n = 6000;
    ray_set rays = rays_alloc(n);
    for (long k = 0; k < n; k++) {
        vec3 p = k % 2 ? uniform_vec(vec3_make(-8, -8, -8), vec3_make(8, 8, 8)) /* inside the big sphere */
                       : vec3_scale(random_direction(), 200);                  /* outside everything */
        set_ray(&rays, k, p, vec3_sub(uniform_vec(vec3_make(-6, -6, -6), vec3_make(6, 6, 6)), p));
    }
    expect_as_linear(&list, &rays, n / 2);
}

/* Rays that start inside a cell of a surface spanning many cells: inside
 * big spheres and just off big triangles, with t_min = 0 and with t_min
 * small, as the secondary rays of later chapters start. */
static void test_start_inside_spanning_cells(void **state)
{
    (void)state;
    rng_state = 16;
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
    random_scene(&list, 400, vec3_make(50, 50, 50), 4);
    int big = list.n;
    surface_list_add_sphere(&list, (sphere){{(real)50.5, (real)49.7, (real)50.2}, (real)2.9}, 3, 0);
    surface_list_add_triangle(&list, (triangle){{44, 45, 47}, {56, 46, 52}, {49, 56, 53}}, 4, 0);
    const long n = 20000;
    ray_set rays = rays_alloc(n);
    for (long k = 0; k < n; k++) {
        const surface *s = &list.items[big + (int)(k % 2)];
        vec3 p;
        if (s->kind == SHAPE_SPHERE) { /* inside the sphere, near its surface or deep */
            p = vec3_add(s->sphere.center, vec3_scale(random_direction(), s->sphere.radius * uniform(0, 1)));
        } else { /* on the triangle, where a hit found by a ray would be */
            real b = uniform(0, 1), c = uniform(0, 1 - b);
            const triangle *t = &s->triangle;
            p = vec3_add(t->a, vec3_add(vec3_scale(vec3_sub(t->b, t->a), b), vec3_scale(vec3_sub(t->c, t->a), c)));
        }
        rays.r[k] = (ray){p, random_direction()};
        rays.t_min[k] = k % 4 < 2 ? 0 : (real)1e-6;
        rays.t_max[k] = k % 3 ? REAL_INFINITY : uniform(0, 3);
    }
    expect_as_linear(&list, &rays, n / 2);
}

/* Ties: two triangles in the plane z = 0 with whole-number corners, met by
 * rays from z = 1 with d_z = -1, are hit at exactly t = 1.  The big one
 * (listed second) spans the cells the ray crosses first, the small one
 * (listed first) sits in a later cell.  The grid finds the big one first,
 * beyond its cell, and must still give the small one, as the linear scan
 * does: the first in the list among equal t. */
static void test_ties_first_in_list(void **state)
{
    (void)state;
    rng_state = 17;
    for (int g_test = 0; g_test < 2; g_test++) {
        surface_list list;
        surface_list_init(&list, SPHERE_ROBUST, triangle_tests[g_test]);
        surface_list_add_triangle(&list, (triangle){{4, 0, 0}, {6, 0, 0}, {4, 2, 0}}, 1, 0);    /* small, first */
        surface_list_add_triangle(&list, (triangle){{-8, -8, 0}, {16, -8, 0}, {-8, 16, 0}}, 2, 1); /* big, second */
        /* tiny spheres above, so that the grid has cells in z and many in x */
        for (int k = 0; k < 200; k++)
            surface_list_add_sphere(&list, (sphere){uniform_vec(vec3_make(-8, -8, 0), vec3_make(8, 8, 4)),
                                                    (real)0.01},
                                    3, 2 + k);
        GRID g;
        build_grid(&g, &list, GRID_DEFAULTS());
        assert_true(g.n[0] > 4 && g.n[2] > 1);
        /* From (-4, y, 1) across to (4.5, y', 0): through many cells of the big triangle first. */
        int small_hits = 0;
        for (int k = 0; k < 64; k++) {
            real y = (real)(k % 8) / 8 + (real)0.0625, target_x = (real)4.25 + (real)(k / 8) / 16;
            ray r = {{-4, y, 1}, {target_x + 4, 0, -1}};
            hit_record a, b;
            bool fa = surfaces_intersect(&list, r, 0, REAL_INFINITY, &a);
            bool fb = GRID_INTERSECT(&g, r, 0, REAL_INFINITY, &b);
            assert_true(fa && fb);
            if (a.surface == 0 && a.t == 1)
                small_hits++;
            if (!same_hit(fa, &a, fb, &b))
                fail_msg("ray %d: the linear scan hits surface %d at t = %.17g, the grid %d at t = %.17g", k,
                         a.surface, (double)a.t, b.surface, (double)b.t);
        }
        assert_true(small_hits > 32); /* the case was exercised: the tie went to the small triangle */
        GRID_FREE(&g);
        surface_list_free(&list);
    }
}


static void test_empty_and_single(void **state)
{
    (void)state;
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_CRAMER);
    GRID g;
    build_grid(&g, &list, GRID_DEFAULTS());
    hit_record hit = {.t = 42};
    const ray r = {{(real)0.3, (real)0.2, 10}, {0, 0, -1}};
    assert_false(GRID_INTERSECT(&g, r, 0, REAL_INFINITY, &hit));
    assert_true(hit.t == 42);
    GRID_FREE(&g);
    surface_list_add_sphere(&list, (sphere){{0, 0, 0}, 1}, 0, 0);
    build_grid(&g, &list, GRID_DEFAULTS());
    assert_true(GRID_INTERSECT(&g, r, 0, REAL_INFINITY, &hit));
    hit_record expected;
    assert_true(surfaces_intersect(&list, r, 0, REAL_INFINITY, &expected));
    assert_true(same_hit(true, &expected, true, &hit));
    assert_false(GRID_INTERSECT(&g, r, 0, 9, &hit)); /* the window ends before the sphere */
    GRID_FREE(&g);
    /* Beside it a sphere whose box is beyond the reals (centre z 0.75 REAL_MAX, radius REAL_MAX / 2: its top,
     * 1.25 REAL_MAX, overflows): no cell holds it, every ray tests it.  Up +z from (0.3, 0.2, 2) the ray meets
     * it at t about 0.25 REAL_MAX, where the linear scan does. */
    surface_list_add_sphere(&list, (sphere){{0, 0, (real)(0.75 * REAL_MAX)}, (real)(REAL_MAX / 2)}, 1, 1);
    build_grid(&g, &list, GRID_DEFAULTS());
    const ray up = {{(real)0.3, (real)0.2, 2}, {0, 0, 1}};
    const bool found_list = surfaces_intersect(&list, up, 0, REAL_INFINITY, &expected);
    assert_true(found_list && expected.surface == 1);
    hit = (hit_record){.t = 42};
    const bool found_grid = GRID_INTERSECT(&g, up, 0, REAL_INFINITY, &hit);
    if (!same_hit(found_list, &expected, found_grid, &hit))
        fail_msg("a unit sphere and a sphere whose box overflows (centre (0, 0, 0.75 REAL_MAX), radius REAL_MAX / 2), "
                 "the ray p (0.3, 0.2, 2), d (0, 0, 1)\n    expected surface 1 at t %.17g\n    got      %s surface %d "
                 "at t %.17g\n    likely mistake: a surface without finite bounds is in no cell: it is listed "
                 "after the cells, and every ray tests it (README, \"The grid\")",
                 (double)expected.t, found_grid ? "a hit on" : "no hit;", hit.surface, (double)hit.t);
    GRID_FREE(&g);
    surface_list_free(&list);
}


/* ---- the Cornell corpus -------------------------------------------------------------------- */

/* Every scene of the course: each pixel's eye ray (at a reduced size) gives
 * the same hit through the grid as through the linear scan, so the images
 * are the same byte for byte.  Skipped when the corpus is absent. */
static void test_cornell_scenes(void **state)
{
    (void)state;
    const char *data = cornell_data();
    if (!data)
        skip();
    static const char *const scenes[] = {
        "bunny", "bunny2", "bunny-norms", "diagnostic", "earth", "earth-eclipse-textured", "one-sphere",
        "one-sphere-rgb-normals", "teapot", "two-boxes", "two-boxes-rgb-normals", "wire-box",
        "wire-box-orthographic",
    };
    for (size_t s = 0; s < sizeof scenes / sizeof scenes[0]; s++) {
        char path[512], err[512] = "";
        snprintf(path, sizeof path, "%s/scenes/ray1/%s.xml", data, scenes[s]);
        scene desc;
        if (scene_load(path, &desc, err, sizeof err) != 0)
            fail_msg("%s", err);
        camera cam;
        assert_true(camera_from_scene(&cam, &desc, err, sizeof err));
        surface_list list;
        surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_CRAMER);
        assert_int_equal(0, surface_list_from_scene(&list, &desc, err, sizeof err));
        GRID g;
        build_grid(&g, &list, GRID_DEFAULTS());
        int side = list.n > 1000 ? 40 : 96;
        for (int j = 0; j < side; j++)
            for (int i = 0; i < side; i++) {
                ray r = camera_ray(&cam, ((real)i + (real)0.5) / (real)side, ((real)j + (real)0.5) / (real)side);
                hit_record a, b;
                bool fa = surfaces_intersect(&list, r, 0, REAL_INFINITY, &a);
                bool fb = GRID_INTERSECT(&g, r, 0, REAL_INFINITY, &b);
                if (!same_hit(fa, &a, fb, &b))
                    fail_msg("%s, pixel (%d, %d) of %dx%d: the grid differs from the linear scan", scenes[s], i, j,
                             side, side);
            }
        GRID_FREE(&g);
        surface_list_free(&list);
        scene_free(&desc);
    }
}


/* ---- chapter 11's renderer: chapter 10's images, byte for byte ------------------------------- */

/* Renders `desc` at side x side through `stage` into *img (1 sample per pixel, the centre). */
static void render_stage(const shading_stage *stage, const scene *desc, int side, image *img)
{
    char err[512] = "";
    shading_view *view = shading_prepare(stage, desc, SPHERE_ROBUST, TRIANGLE_WATERTIGHT, err, sizeof err);
    if (!view)
        fail_msg("%s", err);
    assert_int_equal(0, image_init(img, side, side));
    render_options opt = {.samples = 1};
    render_image(img, shading_sample, view, &opt);
    shading_release(view);
}

/* The built-in scenes of chapters 05-07 (one scene), 08, 09, 10 and 11,
 * rendered by chapter 10's stage (shade_interp over the linear scan) and by
 * chapter 11's (the same over the grid): every pixel the same, bit for
 * bit, since every ray of every kind gets the same hit.  (Chapter 04's
 * built-in scene lives in its render.c; tools/check-grid-images.sh compares
 * the two renderers on the chapters' scene files and the Cornell corpus.) */
static void test_builtin_scenes_as_chapter_10(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        int (*builtin)(scene *desc);
        int side;
    } scenes[] = {
        {"chapters 05-07", shading_scene, 64}, {"chapter 08", mirror_scene, 64}, {"chapter 09", glass_scene, 64},
        {"chapter 10", interp_scene, 64},      {"chapter 11", grid_scene, 40},
    };
    const shading_stage linear = {.name = "10_interpolation", .shade = shade_interp}, /* the knobs' defaults */
        gridded = {.name = "11_grid", .shade = shade_interp, .build_query = GRID_QUERY, .query_knobs = GRID_QUERY_KNOBS};
    for (size_t s = 0; s < sizeof scenes / sizeof scenes[0]; s++) {
        scene desc;
        scene_init(&desc);
        assert_int_equal(0, scenes[s].builtin(&desc));
        image a, b;
        render_stage(&linear, &desc, scenes[s].side, &a);
        render_stage(&gridded, &desc, scenes[s].side, &b);
        for (int k = 0; k < a.width * a.height; k++)
            if (memcmp(&a.pixels[k], &b.pixels[k], sizeof a.pixels[k]) != 0)
                fail_msg("built-in scene of %s, pixel (%d, %d) of %dx%d: chapter 11's radiance differs from chapter "
                         "10's (likely mistake: the grid returns another hit than the linear scan for a shadow or "
                         "reflected ray, t_min > 0 or a finite t_max)",
                         scenes[s].name, k % a.width, k / a.width, a.width, a.height);
        image_free(&a);
        image_free(&b);
        scene_free(&desc);
    }
}


/* A row of cells: tiny spheres at the corners of the box [0, 10] x [0, 1] x
 * [0, 1] fix the grid's box (surfaces 0-7), and with `sliver` a long thin
 * triangle along x at y = 0.3 in the plane z = 0.5 (surface 8), which a ray
 * along x at y = 0.6 passes in every cell without hitting it. */
static inline void row_of_cells(surface_list *list, triangle_test test, bool sliver)
{
    surface_list_init(list, SPHERE_ROBUST, test);
    for (int k = 0; k < 8; k++)
        surface_list_add_sphere(list,
                                (sphere){{(real)(10 * (k & 1)), (real)((k >> 1) & 1), (real)((k >> 2) & 1)},
                                         (real)0.001},
                                0, k);
    if (sliver)
        surface_list_add_triangle(list,
                                  (triangle){{(real)0.2, (real)0.3, (real)0.5}, {(real)9.8, (real)0.3, (real)0.5},
                                             {(real)9.8, (real)0.35, (real)0.5}},
                                  0, 8);
}

#endif
