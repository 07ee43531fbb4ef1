/* test_11_grid.c - chapter 11: the uniform grid and its 3D-DDA.
 *
 * The grid must give exactly the answer of chapter 04's linear scan: for
 * every ray the same surface (or the same miss) and bit for bit the same t,
 * since both call surface_intersect on the same ray and window and keep the
 * smallest t, the first in the list among equal ones.  So most tests here
 * compare grid_intersect with surfaces_intersect and allow no tolerance at
 * all: `same_hit` compares t with ==, and every other field of the record.
 * They do so on random scenes (arithmetic that is not exact, far from the
 * origin) and on the cases where grids usually break: directions with +0
 * and -0 components, origins outside the grid and on its faces, edges and
 * corners, flat scenes, one huge surface among thousands of tiny ones, rays
 * that start inside a cell of a surface that spans many cells, and ties.
 * The exercises' own tests check cell ranges and the cells a ray visits
 * against numbers computed another way.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "01_camera_rays/camera.h"
#include "04_many_shapes/closest_hit.h"
#include "04_many_shapes/scene_surfaces.h"
#include "05_lambert/shading_scene.h"
#include "08_mirrors/mirror_scene.h"
#include "09_refraction/glass_scene.h"
#include "10_interpolation/interp_scene.h"
#include "10_interpolation/interp_stage.h"
#include "11_grid/grid.h"
#include "11_grid/grid_scene.h"
#include "11_grid/grid_stage.h"
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
static void build_grid(grid *g, const surface_list *list, grid_options opt)
{
    char err[256];
    if (grid_build(g, list, opt, err, sizeof err) != 0)
        fail_msg("grid_build: %s", err);
}

/* The grid of `list` with the given knobs answers every ray as the linear
 * scan did (`expected`, `found`); fails naming the first ray that differs. */
static void compare_grid(const surface_list *list, grid_options opt, const ray *rays, const real *t_min,
                         const real *t_max, long n, const hit_record *expected, const bool *found)
{
    grid g;
    build_grid(&g, list, opt);
    for (long k = 0; k < n; k++) {
        hit_record b = {0};
        bool fb = grid_intersect(&g, rays[k], t_min[k], t_max[k], &b);
        if (!same_hit(found[k], &expected[k], fb, &b)) {
            grid_free(&g);
            fail_msg("ray %ld: p = (%.17g, %.17g, %.17g), d = (%.17g, %.17g, %.17g), t in (%g, %g), density %g, "
                     "mailbox %d, leap %d, cull %d: linear scan %s surface %d at t = %.17g, "
                     "grid %s surface %d at t = %.17g",
                     k, (double)rays[k].p.x, (double)rays[k].p.y, (double)rays[k].p.z, (double)rays[k].d.x,
                     (double)rays[k].d.y, (double)rays[k].d.z, (double)t_min[k], (double)t_max[k], opt.density,
                     opt.mailbox, opt.leap, opt.cull, found[k] ? "hits" : "misses", found[k] ? expected[k].surface : -1,
                     found[k] ? (double)expected[k].t : 0.0, fb ? "hits" : "misses", fb ? b.surface : -1,
                     fb ? (double)b.t : 0.0);
        }
    }
    grid_free(&g);
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

/* The same through grids of a few densities with every knob on, and with
 * mailboxing, leaping and culling off one at a time and all together. */
static long compare_all_knobs(const surface_list *list, const ray *rays, const real *t_min, const real *t_max,
                              long n)
{
    static const struct {
        double density;
        bool mailbox, leap, cull;
    } knobs[] = {
        {0.3, true, true, true},  {2, true, true, true},  {10, true, true, true},   {2, false, true, true},
        {2, true, false, true},   {2, true, true, false}, {2, false, false, false},
    };
    hit_record *expected = malloc((size_t)n * sizeof *expected);
    bool *found = malloc((size_t)n * sizeof *found);
    assert_non_null(expected);
    assert_non_null(found);
    long hits = linear_answers(list, rays, t_min, t_max, n, expected, found);
    for (size_t k = 0; k < sizeof knobs / sizeof knobs[0]; k++) {
        grid_options opt = {.density = knobs[k].density, .max_cells = 1L << 20, .mailbox = knobs[k].mailbox,
                            .leap = knobs[k].leap, .cull = knobs[k].cull};
        compare_grid(list, opt, rays, t_min, t_max, n, expected, found);
    }
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
    grid g;
    build_grid(&g, &list, grid_default_options());
    const vec3 lo = g.lo, hi = g.hi;
    grid_free(&g);
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
        grid g;
        build_grid(&g, &list, grid_default_options());
        /* The flat axis has one cell, the others share the rest. */
        assert_int_equal(1, g.n[axis == 0 ? 2 : 0]);
        assert_true(g.n[1] > 4);
        grid_free(&g);
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
        grid g;
        build_grid(&g, &list, grid_default_options());
        assert_true(g.n[0] > 4 && g.n[2] > 1);
        /* From (-4, y, 1) across to (4.5, y', 0): through many cells of the big triangle first. */
        int small_hits = 0;
        for (int k = 0; k < 64; k++) {
            real y = (real)(k % 8) / 8 + (real)0.0625, target_x = (real)4.25 + (real)(k / 8) / 16;
            ray r = {{-4, y, 1}, {target_x + 4, 0, -1}};
            hit_record a, b;
            bool fa = surfaces_intersect(&list, r, 0, REAL_INFINITY, &a);
            bool fb = grid_intersect(&g, r, 0, REAL_INFINITY, &b);
            assert_true(fa && fb);
            if (a.surface == 0 && a.t == 1)
                small_hits++;
            if (!same_hit(fa, &a, fb, &b))
                fail_msg("ray %d: the linear scan hits surface %d at t = %.17g, the grid %d at t = %.17g", k,
                         a.surface, (double)a.t, b.surface, (double)b.t);
        }
        assert_true(small_hits > 32); /* the case was exercised: the tie went to the small triangle */
        grid_free(&g);
        surface_list_free(&list);
    }
}

/* ---- the knobs ------------------------------------------------------------------------- */

/* The resolution follows the density and the box's shape, within the cap. */
static void test_resolution(void **state)
{
    (void)state;
    rng_state = 18;
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_CRAMER);
    /* 1000 tiny spheres in a box 8 x 2 x 4 (plus their radius 0.01) */
    for (int k = 0; k < 1000; k++)
        surface_list_add_sphere(&list, (sphere){uniform_vec(vec3_make(-4, 3, 0), vec3_make(4, 5, 4)), (real)0.01},
                                0, k);
    grid g;
    grid_options opt = {.density = 8, .max_cells = 1L << 20, .mailbox = true};
    build_grid(&g, &list, opt);
    /* 8000 cells for a box of volume ~64: s = 5 cells per unit: 40 x 10 x 20 */
    assert_int_equal(40, g.n[0]);
    assert_int_equal(10, g.n[1]);
    assert_int_equal(20, g.n[2]);
    assert_int_equal(8000, g.n_cells);
    /* every sphere lies in 1 to 8 cells */
    assert_true(g.n_refs >= 1000 && g.n_refs <= 8000);
    assert_true(grid_memory(&g) >= (size_t)(g.n_cells + 1 + g.n_refs) * 4);
    grid_free(&g);
    opt.max_cells = 1000; /* the cap wins: about 1000 cells, in the same proportions */
    build_grid(&g, &list, opt);
    assert_true(g.n_cells <= 1000 && g.n_cells >= 700);
    assert_true(g.n[0] >= 3 * g.n[1] && g.n[0] <= 5 * g.n[1]);
    grid_free(&g);
    opt.density = 0;
    char err[256];
    assert_int_equal(-1, grid_build(&g, &list, opt, err, sizeof err));
    assert_non_null(strstr(err, "density"));
    surface_list_free(&list);
}

/* Mailboxing tests each surface once along a ray: a long thin triangle lying
 * along a row of cells, which the ray passes without hitting it, is tested
 * in every cell without the mailbox and once with it. */
static void test_mailbox_counts(void **state)
{
    (void)state;
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_CRAMER);
    /* tiny spheres at the corners of the box [0, 10] x [0, 1] x [0, 1] */
    for (int k = 0; k < 8; k++)
        surface_list_add_sphere(&list,
                                (sphere){{(real)(10 * (k & 1)), (real)((k >> 1) & 1), (real)((k >> 2) & 1)},
                                         (real)0.001},
                                0, k);
    /* a sliver along x at y = 0.3, in the plane z = 0.5 */
    surface_list_add_triangle(&list, (triangle){{(real)0.2, (real)0.3, (real)0.5}, {(real)9.8, (real)0.3, (real)0.5},
                                                {(real)9.8, (real)0.35, (real)0.5}},
                              0, 8);
    for (int m = 0; m < 2; m++) {
        grid g;
        grid_options opt = {.density = 1.25, .max_cells = 1000, .mailbox = m == 0};
        build_grid(&g, &list, opt);
        assert_int_equal(10, g.n[0]); /* 9 surfaces x 1.25 ~ 11 cells for a box 10 x 1 x 1 */
        assert_int_equal(1, g.n[1]);
        assert_int_equal(1, g.n[2]);
        /* along +x at y = 0.6, z = 0.45: through all 10 cells, missing everything */
        ray r = {{-1, (real)0.6, (real)0.45}, {1, 0, 0}};
        grid_counts counts = {0, 0, 0};
        hit_record hit;
        assert_false(grid_intersect_counted(&g, r, 0, REAL_INFINITY, &hit, &counts));
        assert_int_equal(10, counts.cells);
        /* The sliver is in all 10 cells; the corner spheres in the end cells. */
        assert_int_equal(m == 0 ? 1 + 8 : 10 + 8, counts.tests);
        grid_free(&g);
    }
    surface_list_free(&list);
}

/* An empty list, and one whose only surface is hit. */
static void test_empty_and_single(void **state)
{
    (void)state;
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_CRAMER);
    grid g;
    build_grid(&g, &list, grid_default_options());
    hit_record hit = {.t = 42};
    const ray r = {{(real)0.3, (real)0.2, 10}, {0, 0, -1}};
    assert_false(grid_intersect(&g, r, 0, REAL_INFINITY, &hit));
    assert_true(hit.t == 42);
    grid_free(&g);
    surface_list_add_sphere(&list, (sphere){{0, 0, 0}, 1}, 0, 0);
    build_grid(&g, &list, grid_default_options());
    assert_true(grid_intersect(&g, r, 0, REAL_INFINITY, &hit));
    hit_record expected;
    assert_true(surfaces_intersect(&list, r, 0, REAL_INFINITY, &expected));
    assert_true(same_hit(true, &expected, true, &hit));
    assert_false(grid_intersect(&g, r, 0, 9, &hit)); /* the window ends before the sphere */
    grid_free(&g);
    surface_list_free(&list);
}

/* The leap's cubes: for every cell and octant, empty[8 c + o] is the side of
 * the largest cube of empty cells with c as its corner and lying ahead of c
 * in octant o (cells beyond the grid count as empty, capped at 255), found
 * here by growing the cube one cell at a time. */
static bool cube_empty(const grid *g, int i, int j, int k, int o, int side)
{
    const int sign[3] = {o & 1 ? -1 : 1, o & 2 ? -1 : 1, o & 4 ? -1 : 1};
    for (int c = 0; c < side; c++)
        for (int b = 0; b < side; b++)
            for (int a = 0; a < side; a++) {
                int ii = i + sign[0] * a, jj = j + sign[1] * b, kk = k + sign[2] * c;
                if (ii < 0 || ii >= g->n[0] || jj < 0 || jj >= g->n[1] || kk < 0 || kk >= g->n[2])
                    continue;
                long cell = ii + (long)g->n[0] * (jj + (long)g->n[1] * kk);
                if (g->start[cell + 1] > g->start[cell])
                    return false;
            }
    return true;
}

static void test_empty_cubes(void **state)
{
    (void)state;
    rng_state = 11;
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_CRAMER);
    for (int k = 0; k < 12; k++) { /* small spheres in a box far from the origin */
        vec3 centre = uniform_vec(vec3_make(1000, -50, 3), vec3_make(1010, -42, 9));
        surface_list_add_sphere(&list, (sphere){centre, uniform((real)0.05, (real)0.4)}, 0, k);
    }
    grid g;
    grid_options opt = grid_default_options();
    opt.density = 40;
    build_grid(&g, &list, opt);
    assert_non_null(g.empty);
    long occupied = 0;
    for (long c = 0; c < g.n_cells; c++)
        occupied += g.start[c + 1] > g.start[c];
    if (occupied == 0)
        fail_msg("no cell lists a surface (%d x %d x %d cells, 12 spheres): is cell_range still the exercise's stub?",
                 g.n[0], g.n[1], g.n[2]);
    const int largest = g.n[0] > g.n[1] ? (g.n[0] > g.n[2] ? g.n[0] : g.n[2]) : (g.n[1] > g.n[2] ? g.n[1] : g.n[2]);
    long leaps = 0;
    for (int k = 0; k < g.n[2]; k++)
        for (int j = 0; j < g.n[1]; j++)
            for (int i = 0; i < g.n[0]; i++)
                for (int o = 0; o < 8; o++) {
                    int side = 0;
                    while (side <= largest && cube_empty(&g, i, j, k, o, side + 1))
                        side++;
                    if (side > largest) /* reaches past the grid on every axis */
                        side = 255;
                    long c = i + (long)g.n[0] * (j + (long)g.n[1] * k);
                    if (g.empty[8 * c + o] != side)
                        fail_msg("cell (%d, %d, %d), octant %d: empty cube of side %d expected, the grid says %d", i,
                                 j, k, o, side, g.empty[8 * c + o]);
                    leaps += side >= 2;
                }
    assert_true(leaps > 0); /* the scene leaves room to leap */
    grid_free(&g);
    surface_list_free(&list);
}

/* ---- the exercises ----------------------------------------------------------------------- */

/* A grid laid out by hand: low corner (-1, 2, 0.5), cells 0.25 x 0.5 x 1
 * (exact in binary), 8 x 4 x 3 cells. */
static grid hand_grid(void)
{
    grid g = {.lo = {-1, 2, (real)0.5}, .cell = {(real)0.25, (real)0.5, 1}, .inv_cell = {4, 2, 1}, .n = {8, 4, 3}};
    g.hi = vec3_add(g.lo, vec3_make(2, 2, 3));
    return g;
}

static double clamp_cell(double f, int lowest, int highest) { return f < lowest ? lowest : f > highest ? highest : f; }

/* grid_cell_range(g, lo, hi) along every axis: cells want_first[a] ..
 * want_last[a] (NULL: the cells i with [i, i + 1] meeting [f_lo, f_hi], the
 * box in units of cells, computed here; none gives first > last).  A
 * failure names the box, the axis, f_lo and f_hi and the likely mistake. */
static void expect_range(const grid *g, vec3 lo, vec3 hi, const int *want_first, const int *want_last)
{
    int first[3], last[3];
    grid_cell_range(g, lo, hi, first, last);
    const real l[3] = {lo.x, lo.y, lo.z}, u[3] = {hi.x, hi.y, hi.z}, o[3] = {g->lo.x, g->lo.y, g->lo.z},
               inv[3] = {g->inv_cell.x, g->inv_cell.y, g->inv_cell.z};
    for (int a = 0; a < 3; a++) {
        const int n = g->n[a];
        const real f_lo = (l[a] - o[a]) * inv[a], f_hi = (u[a] - o[a]) * inv[a];
        int wf = n, wl = -1; /* none */
        if (want_first) {
            wf = want_first[a], wl = want_last[a];
        } else {
            for (int i = n - 1; i >= 0; i--)
                if ((real)i <= f_hi && (real)(i + 1) >= f_lo)
                    wf = i;
            for (int i = 0; i < n; i++)
                if ((real)i <= f_hi && (real)(i + 1) >= f_lo)
                    wl = i;
        }
        bool none = wf > wl;
        if (none ? first[a] > last[a] : first[a] == wf && last[a] == wl)
            continue;
        const double F = f_lo, L = f_hi, right_first = clamp_cell(ceil(F) - 1, 0, n), right_last = clamp_cell(floor(L), -1, n - 1);
        const real f_lo_x = (l[a] - o[0]) * inv[0], f_hi_x = (u[a] - o[0]) * inv[0];
        const struct {
            double first, last;
            const char *why;
        } mistakes[] = {
            {clamp_cell(floor(F), 0, n), right_last, "first = floor(f_lo): a box whose low side lies on a cell boundary "
                                                     "(f_lo whole) touches the cell below too: first = ceil(f_lo) - 1"},
            {right_first, clamp_cell(ceil(L) - 1, -1, n - 1), "last = ceil(f_hi) - 1: a box whose high side lies on a "
                                                              "cell boundary touches the cell above too: last = floor(f_hi)"},
            {right_first, clamp_cell(trunc(L), -1, n - 1), "last truncated towards zero: for -1 < f_hi < 0 (a box "
                                                           "below the grid) floor gives -1, truncation 0"},
            {clamp_cell(trunc(F), 0, n), right_last, "first truncated: first = ceil(f_lo) - 1"},
            {right_first, clamp_cell(floor(L), -1, n), "last clamped to n: the last cell is n - 1"},
            {clamp_cell(ceil(F) - 1, 0, n - 1), right_last, "first clamped to n - 1: a box beyond the grid then gets "
                                                            "its last cell; clamp first to 0 .. n so that first > last"},
            {right_first, clamp_cell(floor(L), 0, n - 1), "last clamped at 0 from below: a box below the grid then "
                                                          "gets cell 0; clamp last to -1 .. n - 1 so that first > last"},
            {ceil(F) - 1, floor(L), "not clamped to the grid: first and last lie in 0 .. n - 1 (or first > last)"},
            {clamp_cell(floor(F) - 1, 0, n), right_last, "floor(f_lo) - 1 is one cell too many when f_lo is not "
                                                         "whole: first = ceil(f_lo) - 1"},
            {clamp_cell(ceil(L) - 1, 0, n), clamp_cell(floor(F), -1, n - 1), "box_lo and box_hi swapped"},
            {clamp_cell(ceil((double)f_lo_x) - 1, 0, n), clamp_cell(floor((double)f_hi_x), -1, n - 1),
             "the x axis's cell size or origin used for another axis: cell_coordinate(g, x, a) with this axis a"},
        };
        /* beyond an int's range the likely mistake is the conversion, whatever else the result looks like */
        const bool beyond_int = fabs(F) > 2147483647.0 || fabs(L) > 2147483647.0;
        const char *why = beyond_int ? "f_lo or f_hi converted to int before it was clamped: beyond an int's range "
                                       "the conversion is undefined (x86-64 gives INT_MIN); clamp the real value "
                                       "with clamp_index, then convert"
                                     : "first = ceil(f_lo) - 1, last = floor(f_hi), clamped to 0 .. n - 1 (first > "
                                       "last: none)";
        for (size_t k = 0; !beyond_int && k < sizeof mistakes / sizeof mistakes[0]; k++)
            if (mistakes[k].first == first[a] && mistakes[k].last == last[a]) {
                why = mistakes[k].why;
                break;
            }
        fail_msg("grid_cell_range(grid from (%g, %g, %g), cells %g x %g x %g, n = %d x %d x %d; box (%.9g, %.9g, "
                 "%.9g) .. (%.9g, %.9g, %.9g)), axis %c: f_lo = %.9g, f_hi = %.9g (in cells)\n"
                 "    expected cells %d .. %d%s\n    got      cells %d .. %d\n    likely mistake: %s",
                 (double)g->lo.x, (double)g->lo.y, (double)g->lo.z, (double)g->cell.x, (double)g->cell.y,
                 (double)g->cell.z, g->n[0], g->n[1], g->n[2], (double)lo.x, (double)lo.y, (double)lo.z, (double)hi.x,
                 (double)hi.y, (double)hi.z, "xyz"[a], F, L, wf, wl, none ? " (none: first > last)" : "", first[a],
                 last[a], why);
    }
}

/* cell_range: boxes inside, on cell boundaries (both sides count), reaching
 * outside (clamped) and wholly outside (empty). */
static void test_cell_range(void **state)
{
    (void)state;
    const grid g = hand_grid();
    static const struct {
        vec3 lo, hi;
        int first[3], last[3];
    } cases[] = {
        /* inside one cell: (0.1, 2.1, 0.6) is in cell (4, 0, 0) */
        {{(real)0.1, (real)2.1, (real)0.6}, {(real)0.2, (real)2.4, (real)1.4}, {4, 0, 0}, {4, 0, 0}},
        /* across cells: x from 1.6 (cell 2) to 2.3 (cell 5)... in units: x = -0.6 .. 0.3 */
        {{(real)-0.6, (real)2.6, (real)1.7}, {(real)0.3, (real)3.9, (real)2.2}, {1, 1, 1}, {5, 3, 1}},
        /* corners exactly on boundaries: x = -0.5 is between cells 1 and 2, y = 3 between 1 and 2 */
        {{(real)-0.5, 3, (real)1.5}, {0, 3, (real)2.5}, {1, 1, 0}, {4, 2, 2}},
        /* reaching past the grid: clamped */
        {{-100, -100, -100}, {100, 100, 100}, {0, 0, 0}, {7, 3, 2}},
        /* reaching far past it: f_lo and f_hi are about -+4e30 cells, beyond an int's range */
        {{(real)-1e30, (real)-1e30, (real)-1e30}, {(real)1e30, (real)1e30, (real)1e30}, {0, 0, 0}, {7, 3, 2}},
        /* on the grid's own faces: the outer cells */
        {{-1, 2, (real)0.5}, {-1, 2, (real)0.5}, {0, 0, 0}, {0, 0, 0}},
        {{1, 4, (real)3.5}, {1, 4, (real)3.5}, {7, 3, 2}, {7, 3, 2}},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
        expect_range(&g, cases[c].lo, cases[c].hi, cases[c].first, cases[c].last);
    /* Wholly outside, on each side of each axis: empty on that axis. */
    const vec3 outside[][2] = {
        {{-3, 2, 1}, {-2, 3, 2}}, {{2, 2, 1}, {3, 3, 2}}, {{0, -1, 1}, {0, 1, 2}},
        {{0, 5, 1}, {0, 6, 2}},   {{0, 3, -2}, {0, 3, 0}}, {{0, 3, 4}, {0, 3, 9}},
    };
    for (size_t c = 0; c < sizeof outside / sizeof outside[0]; c++)
        expect_range(&g, outside[c][0], outside[c][1], NULL, NULL);
    /* Random boxes in a grid of inexact sizes: cell i is in the range exactly
     * when [i, i + 1] meets [f_lo, f_hi], the box in units of cells. */
    rng_state = 19;
    grid h = {.lo = {(real)-3.7, (real)1.9, (real)10.1}, .n = {13, 7, 11}};
    h.cell = vec3_make((real)0.31, (real)0.77, (real)0.093);
    h.inv_cell = vec3_make(1 / h.cell.x, 1 / h.cell.y, 1 / h.cell.z);
    for (int k = 0; k < 2000; k++) {
        const vec3 box_lo = {-5, 1, 9}, box_hi = {2, 8, 12};
        vec3 a = uniform_vec(box_lo, box_hi), b = uniform_vec(box_lo, box_hi);
        vec3 lo = vec3_make(real_fmin(a.x, b.x), real_fmin(a.y, b.y), real_fmin(a.z, b.z));
        vec3 hi = vec3_make(real_fmax(a.x, b.x), real_fmax(a.y, b.y), real_fmax(a.z, b.z));
        expect_range(&h, lo, hi, NULL, NULL);
    }
}

/* dda_step: the cells a ray visits, counted against the plane crossings:
 * a ray through the whole grid that hits nothing visits one cell more than
 * the cell planes it crosses inside the grid's box. */
static void test_dda_cells(void **state)
{
    (void)state;
    rng_state = 20;
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_CRAMER);
    /* eight tiny spheres at the corners of [-2, 3] x [1, 4] x [-1, 1]: nothing in between */
    for (int k = 0; k < 8; k++)
        surface_list_add_sphere(&list, (sphere){{k & 1 ? 3 : -2, k & 2 ? 4 : 1, k & 4 ? 1 : -1}, (real)1e-3}, 0, k);
    grid g;
    grid_options opt = {.density = 100, .max_cells = 1000, .mailbox = true};
    build_grid(&g, &list, opt);
    assert_true(g.n[0] > 3 && g.n[1] > 3 && g.n[2] > 1);
    const real lo[3] = {g.lo.x, g.lo.y, g.lo.z}, cell[3] = {g.cell.x, g.cell.y, g.cell.z};
    int checked = 0;
    for (int k = 0; k < 3000; k++) {
        /* from outside, through the middle part of the box (missing the corner spheres) */
        vec3 target = uniform_vec(vec3_make(-1, 2, (real)-0.5), vec3_make(2, 3, (real)0.5));
        vec3 p = vec3_add(target, vec3_scale(random_direction(), 20));
        ray r = {p, vec3_sub(target, p)};
        const real pp[3] = {p.x, p.y, p.z}, dd[3] = {r.d.x, r.d.y, r.d.z};
        /* where the ray is inside the box, and the planes it crosses there */
        real t_in = 0, t_out = REAL_INFINITY;
        for (int a = 0; a < 3; a++) {
            real t0 = (lo[a] - pp[a]) / dd[a], t1 = (lo[a] + (real)g.n[a] * cell[a] - pp[a]) / dd[a];
            t_in = real_fmax(t_in, real_fmin(t0, t1));
            t_out = real_fmin(t_out, real_fmax(t0, t1));
        }
        if (!(t_in < t_out))
            continue;
        int crossings = 0;
        bool near_corner = false;
        for (int a = 0; a < 3; a++)
            for (int plane = 1; plane < g.n[a]; plane++) {
                real t = (lo[a] + (real)plane * cell[a] - pp[a]) / dd[a];
                if (t > t_in && t < t_out)
                    crossings++;
                /* a crossing within a hair of the box's entry or exit, or of
                 * another axis's crossing, may count either way: skip such rays */
                if (real_abs(t - t_in) < (real)1e-4 * t_in || real_abs(t - t_out) < (real)1e-4 * t_out)
                    near_corner = true;
            }
        if (near_corner)
            continue;
        grid_counts counts = {0, 0, 0};
        hit_record hit;
        assert_false(grid_intersect_counted(&g, r, 0, REAL_INFINITY, &hit, &counts));
        if (counts.cells != (uint64_t)crossings + 1)
            fail_msg("grid_intersect_counted(ray %d: p = (%.17g, %.17g, %.17g), d = (%.17g, %.17g, %.17g)) through a "
                     "grid of %d x %d x %d empty cells\n    expected %d cells visited (%d plane crossings + 1)\n"
                     "    got      %llu\n    likely mistake: %s",
                     k, (double)p.x, (double)p.y, (double)p.z, (double)r.d.x, (double)r.d.y, (double)r.d.z, g.n[0],
                     g.n[1], g.n[2], crossings + 1, crossings, (unsigned long long)counts.cells,
                     counts.cells > (uint64_t)crossings + 1
                         ? "dda_step goes on past the grid (the last cell is n_a - 1: stop when i_a < 0 or i_a >= "
                           "n_a), or next_a comes from the plane the ray just crossed (for step_a > 0 the far "
                           "boundary is plane i_a + 1, for step_a < 0 plane i_a)"
                         : "dda_step stops too early (i_a = 0 and i_a = n_a - 1 are inside the grid), or next_a "
                           "comes from the wrong plane (for step_a > 0 plane i_a + 1, for step_a < 0 plane i_a) or "
                           "is not updated");
        checked++;
    }
    assert_true(checked > 2000);
    grid_free(&g);
    surface_list_free(&list);
}

/* dda_step along one axis at a time: tiny spheres on a lattice 5 x 4 x 3
 * (spacings 0.37, 0.61, 0.29, far from the origin), a grid over them with
 * about two cells between neighbours, leaping off (so that only dda_step
 * moves the ray); from each sphere's centre along +x, -x, +y, -y, +z and -z
 * (the negative ones with -0 components), past its own sphere (t_min =
 * twice the radius): the hit is the next sphere along that axis, as the
 * linear scan finds.  A failure names the axis and the direction, which is
 * what a wrong stride or plane gets wrong. */
static void test_dda_axis_steps(void **state)
{
    (void)state;
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
    const vec3 origin = {(real)123.4, (real)-56.7, (real)89.1}, spacing = {(real)0.37, (real)0.61, (real)0.29};
    const int m[3] = {5, 4, 3};
    const real radius = (real)0.02;
    for (int k = 0; k < m[2]; k++)
        for (int j = 0; j < m[1]; j++)
            for (int i = 0; i < m[0]; i++)
                surface_list_add_sphere(&list,
                                        (sphere){vec3_add(origin, vec3_make((real)i * spacing.x, (real)j * spacing.y,
                                                                            (real)k * spacing.z)),
                                                 radius},
                                        0, i + m[0] * (j + m[1] * k));
    grid g;
    build_grid(&g, &list, (grid_options){.density = 8, .max_cells = 1L << 20, .mailbox = true, .cull = true});
    assert_true(g.n[0] > m[0] && g.n[1] > m[1] && g.n[2] > m[2]); /* more cells than spheres along every axis */
    const vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const long stride[3] = {1, g.n[0], (long)g.n[0] * g.n[1]};
    for (int s = 0; s < list.n; s++) {
        const int at[3] = {s % m[0], s / m[0] % m[1], s / (m[0] * m[1])};
        for (int a = 0; a < 3; a++)
            for (int sign = -1; sign <= 1; sign += 2) {
                if (at[a] + sign < 0 || at[a] + sign >= m[a])
                    continue;
                ray r = {list.items[s].sphere.center, sign > 0 ? axes[a] : vec3_neg(axes[a])};
                hit_record want, got;
                bool fw = surfaces_intersect(&list, r, 2 * radius, REAL_INFINITY, &want);
                bool fg = grid_intersect(&g, r, 2 * radius, REAL_INFINITY, &got);
                assert_true(fw && want.surface == s + sign * (a == 0 ? 1 : a == 1 ? m[0] : m[0] * m[1]));
                if (!same_hit(fw, &want, fg, &got))
                    fail_msg("grid_intersect(ray from sphere %d's centre (%.17g, %.17g, %.17g) along %c%c, t_min = "
                             "%g) through a grid of %d x %d x %d cells\n    expected sphere %d at t = %.17g\n"
                             "    got      %s %d at t = %.17g\n    likely mistake: dda_step along %c with step %+d: "
                             "the cell moves by step stride_%c = %+ld (cell = i + n_x (j + n_y k)), the index i_%c by "
                             "step, and next_%c is the crossing of plane i_%c%s, recomputed each step",
                             s, (double)r.p.x, (double)r.p.y, (double)r.p.z, sign > 0 ? '+' : '-', "xyz"[a],
                             (double)(2 * radius), g.n[0], g.n[1], g.n[2], want.surface, (double)want.t,
                             fg ? "sphere" : "no hit, surface", fg ? got.surface : -1, fg ? (double)got.t : 0.0,
                             "xyz"[a], sign, "xyz"[a], sign * stride[a], "xyz"[a], "xyz"[a], "xyz"[a],
                             sign > 0 ? " + 1" : "");
            }
    }
    grid_free(&g);
    surface_list_free(&list);
}

/* next_a is computed from the plane at every step, not by adding a t step
 * per cell: the sum gathers one rounding per cell, and after 10^5 cells it
 * is off by far more than the margin (64 eps |coordinates|) that keeps the
 * march safe.  A long thin grid, over 10^5 cells along x and one across (two
 * tiny spheres at x = 0 and x = L, L a bit over 1000, off the x axis):
 * rays along +x and -x meet, just past a cell boundary b far along, a small
 * sphere B (hit 4 margins past b) and beyond it a triangle A that spans the
 * boundary (hit 16 margins past b), so it is listed in the cell before b
 * too.  The closest is B, in the cells after b only; a march whose next_x
 * lies beyond the boundary by more than 16 margins stops in the cell
 * before b with A.  Three lengths L (cell sizes whose rounding goes either
 * way), five boundaries each, both directions. */
static void test_dda_no_accumulation(void **state)
{
    (void)state;
    const vec3 off = {(real)0.5, (real)-3.25, (real)7.5};
    enum { PLANES = 5 };
    for (int variant = 0; variant < 3; variant++) {
        const real L = (real)(1000 + 37.3 * variant);
        /* The grid's box and resolution depend on the surfaces' box and
         * count only: learn them from the end spheres and stand-ins. */
        surface_list list;
        surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
        surface_list_add_sphere(&list, (sphere){off, (real)1e-3}, 0, 0);
        surface_list_add_sphere(&list, (sphere){vec3_add(off, vec3_make(L, 0, 0)), (real)1e-3}, 0, 1);
        for (int k = 0; k < 4 * PLANES; k++)
            surface_list_add_sphere(&list, (sphere){off, (real)1e-5}, 0, 2 + k);
        const grid_options opt = {.density = 5000, .max_cells = 1L << 20, .mailbox = true, .cull = true};
        grid g;
        build_grid(&g, &list, opt);
        assert_true(g.n[0] > 100000 && g.n[1] == 1 && g.n[2] == 1);
        const long cells = g.n[0];
        const real lo = g.lo.x, cell = g.cell.x, margin = g.margin;
        grid_free(&g);
        surface_list_free(&list);
        surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
        surface_list_add_sphere(&list, (sphere){off, (real)1e-3}, 0, 0);
        surface_list_add_sphere(&list, (sphere){vec3_add(off, vec3_make(L, 0, 0)), (real)1e-3}, 0, 1);
        const long planes[PLANES] = {cells / 3, cells / 2, (2 * cells) / 3, cells - 2000, cells - 1000};
        ray rays[2 * PLANES];
        for (int q = 0; q < 2 * PLANES; q++) {
            const int dir = q % 2 ? -1 : 1; /* +x or -x */
            const long plane = dir > 0 ? planes[q / 2] : cells - planes[q / 2];
            const real b = lo + (real)plane * cell;
            /* its own place across, inside the box's 2e-3 */
            const real y = off.y + (real)(q - PLANES) * (real)1.5e-4, z = off.z + (real)(q % 3 - 1) * (real)2e-4;
            const real xB = b + dir * 4 * margin, xA = b + dir * 16 * margin, rB = (real)1e-5, w = (real)5e-5;
            surface_list_add_sphere(&list, (sphere){vec3_make(xB + dir * rB, y, z), rB}, 0, 2 + 2 * q);
            /* A: in the plane x - xA = c (y' - y) through (xA, y, z), reaching a cell and 32 margins
             * (one cell in double, many in float) either side of xA */
            const real c = real_fmax(cell, 32 * margin) / w;
            triangle A = {{xA - c * w, y - w, z - 2 * w}, {xA - c * w, y - w, z + 2 * w}, {xA + 2 * c * w, y + 2 * w, z}};
            surface_list_add_triangle(&list, A, 0, 3 + 2 * q);
            /* from inside the box, past the end sphere (radius 1e-3) */
            rays[q] = (ray){vec3_make(dir > 0 ? off.x + (real)0.01 : off.x + L - (real)0.01, y, z),
                            vec3_make((real)dir, 0, 0)};
        }
        build_grid(&g, &list, opt);
        assert_true(g.n[0] == cells && g.lo.x == lo && g.cell.x == cell); /* the same grid */
        for (int q = 0; q < 2 * PLANES; q++) {
            hit_record want, got;
            bool fw = surfaces_intersect(&list, rays[q], 0, REAL_INFINITY, &want);
            bool fg = grid_intersect(&g, rays[q], 0, REAL_INFINITY, &got);
            assert_true(fw && want.surface == 2 + 2 * q); /* B is the closest */
            if (!same_hit(fw, &want, fg, &got))
                fail_msg("grid_intersect(ray from (%.17g, %.17g, %.17g) along %cx) through %ld cells of %.17g along "
                         "x\n    expected the small sphere (surface %d) at t = %.17g, just past the boundary of cell "
                         "%ld\n    got      %s %d at t = %.17g\n    likely mistake: next_x gathered rounding: compute "
                         "it from the plane at each step (crossing(g, a, plane, p, inv_d)), not by adding a t step "
                         "per cell",
                         (double)rays[q].p.x, (double)rays[q].p.y, (double)rays[q].p.z, q % 2 ? '-' : '+', cells,
                         (double)cell, want.surface, (double)want.t, q % 2 ? cells - planes[q / 2] : planes[q / 2],
                         fg ? "surface" : "no hit, surface", fg ? got.surface : -1, fg ? (double)got.t : 0.0);
        }
        grid_free(&g);
        surface_list_free(&list);
    }
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
        grid g;
        build_grid(&g, &list, grid_default_options());
        int side = list.n > 1000 ? 40 : 96;
        for (int j = 0; j < side; j++)
            for (int i = 0; i < side; i++) {
                ray r = camera_ray(&cam, ((real)i + (real)0.5) / (real)side, ((real)j + (real)0.5) / (real)side);
                hit_record a, b;
                bool fa = surfaces_intersect(&list, r, 0, REAL_INFINITY, &a);
                bool fb = grid_intersect(&g, r, 0, REAL_INFINITY, &b);
                if (!same_hit(fa, &a, fb, &b))
                    fail_msg("%s, pixel (%d, %d) of %dx%d: the grid differs from the linear scan", scenes[s], i, j,
                             side, side);
            }
        grid_free(&g);
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
 * rendered by chapter 10's stage (interp_stage over the linear scan) and by
 * chapter 11's (the same stage over the grid): every pixel the same, bit for
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
    const shading_stage linear = interp_stage(NULL), gridded = grid_stage();
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

static const graded_test tests[] = {
    GRADED(test_cell_range, 4),
    GRADED(test_dda_cells, 4),
    GRADED(test_dda_axis_steps, 2),
    GRADED(test_dda_no_accumulation, 1),
    GRADED(test_random_scenes, 3),
    GRADED(test_zero_components, 2),
    GRADED(test_origins_on_the_grid, 2),
    GRADED(test_flat_scenes, 2),
    GRADED(test_huge_among_tiny, 2),
    GRADED(test_start_inside_spanning_cells, 2),
    GRADED(test_ties_first_in_list, 2),
    GRADED(test_resolution, 1),
    GRADED(test_mailbox_counts, 1),
    GRADED(test_empty_and_single, 1),
    GRADED(test_empty_cubes, 1),
    GRADED(test_cornell_scenes, 0),
    GRADED(test_builtin_scenes_as_chapter_10, 0),
};

SUITE_MAIN("11_grid", tests)
