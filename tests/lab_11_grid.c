/* lab_11_grid.c - chapter 11's lab: the fast grid answers as the lesson's grid and the linear scan do.
 *
 * The cases where grids break (grid_cases.h) with the fast grid and every
 * combination of its knobs, then what only the fast grid has: the mailbox
 * (each surface tested once along a ray) and the empty cubes it leaps over.
 */
#include "11_grid/renderer/grid_stage.h"
#include "11_grid/lab/fast_query.h"
#include "11_grid/lab/fast_search.h"
#include "box.h"
#include "scene_shapes.h"

#define GRID fast_grid
#define GRID_OPTIONS fast_grid_options
#define GRID_BUILD fast_grid_build
#define GRID_INTERSECT fast_grid_intersect
#define GRID_FREE fast_grid_free
#define GRID_DEFAULTS fast_grid_default_options
#define GRID_QUERY lab_query_build
#define GRID_QUERY_KNOBS (&fast_defaults)
/* a few densities with every knob on, one level and two (the default split,
 * and splits so low that most cells with surfaces get grids of their own),
 * then mailboxing, leaping and culling off one at a time and all together
 * (boxes too); the two after prefetch (these small scenes' grids would not by
 * size); the second and the fourth from last keep the triangles' normals, as the lab does; the second,
 * the fifth and the ninth set the few large surfaces of a scene apart from the cells, as the default
 * list_up_to does (the others keep every surface in cells); the last two test every scene as a list,
 * without cells (list_up_to), with boxes and without */
static const fast_grid_options knob_sets[] = {
    {0.3, 1L << 20, true, true, true, 0, 0, false, true, 0},
    {2, 1L << 20, true, true, true, FAST_GRID_DEFAULT_SPLIT, 0, true, true, FAST_GRID_DEFAULT_LIST_UP_TO},
    {10, 1L << 20, true, true, true, 0, 0, false, true, 0},
    {2, 1L << 20, true, true, true, 0, 0, false, true, 0},
    {0.3, 1L << 20, true, true, true, 2, 0, false, true, FAST_GRID_DEFAULT_LIST_UP_TO},
    {2, 1L << 20, true, true, true, 4, 0, false, true, 0},
    {2, 1L << 20, false, true, true, 0, 0, false, true, 0},
    {2, 1L << 20, true, false, true, 0, 0, false, true, 0},
    {2, 1L << 20, true, true, false, 0, 0, false, true, FAST_GRID_DEFAULT_LIST_UP_TO},
    {2, 1L << 20, false, false, false, 0, 0, false, false, 0},
    {2, 1L << 20, false, false, false, 3, 0, false, false, 0},
    {2, 1L << 20, true, true, true, 4, FAST_GRID_PREFETCH_ON, false, true, 0},
    {0.3, 1L << 20, true, true, true, 0, FAST_GRID_PREFETCH_ON, true, true, 0},
    {2, 1L << 20, true, true, true, FAST_GRID_DEFAULT_SPLIT, 0, true, true, 1 << 30},
    {2, 1L << 20, true, true, true, FAST_GRID_DEFAULT_SPLIT, 0, false, false, 1 << 30},
};
#define N_KNOB_SETS (sizeof knob_sets / sizeof knob_sets[0])

static const fast_knobs fast_defaults = FAST_KNOBS_DEFAULT; /* the lab's: the fast grid */

#include "grid_cases.h"

/* Allocation faults: this suite's calls to malloc, calloc and realloc go
 * through the wrappers below (the Makefile links it with -Wl,--wrap for the
 * three).  With alloc_fail_at = k > 0, the k-th call from the last reset of
 * alloc_calls returns NULL. */
void *__real_malloc(size_t size);
void *__real_calloc(size_t count, size_t size);
void *__real_realloc(void *old, size_t size);
void *__wrap_malloc(size_t size);
void *__wrap_calloc(size_t count, size_t size);
void *__wrap_realloc(void *old, size_t size);
static long alloc_calls, alloc_fail_at;
static bool alloc_fault(void) { return alloc_fail_at > 0 && ++alloc_calls == alloc_fail_at; }
void *__wrap_malloc(size_t size) { return alloc_fault() ? NULL : __real_malloc(size); }
void *__wrap_calloc(size_t count, size_t size) { return alloc_fault() ? NULL : __real_calloc(count, size); }
void *__wrap_realloc(void *old, size_t size) { return alloc_fault() ? NULL : __real_realloc(old, size); }

static void build_fast(fast_grid *g, const surface_list *list, fast_grid_options opt)
{
    char err[256];
    if (fast_grid_build(g, list, opt, err, sizeof err) != 0)
        fail_msg("fast_grid_build: %s", err);
}

/* Mailboxing tests each surface once along a ray: a long thin triangle lying
 * along a row of cells, which the ray passes without hitting it, is tested
 * in every cell without the mailbox and once with it. */
static void test_mailbox_counts(void **state)
{
    (void)state;
    surface_list list;
    row_of_cells(&list, TRIANGLE_CRAMER, true);
    for (int m = 0; m < 2; m++) {
        fast_grid g;
        fast_grid_options opt = {.density = 1.25, .max_cells = 1000, .mailbox = m == 0};
        build_fast(&g, &list, opt);
        assert_int_equal(10, g.n[0]); /* 9 surfaces x 1.25 ~ 11 cells for a box 10 x 1 x 1 */
        assert_int_equal(1, g.n[1]);
        assert_int_equal(1, g.n[2]);
        /* along +x at y = 0.6, z = 0.45: through all 10 cells, missing everything */
        ray r = {{-1, (real)0.6, (real)0.45}, {1, 0, 0}};
        fast_grid_counts counts = {0, 0, 0, 0};
        hit_record hit;
        assert_false(fast_grid_intersect_counted(&g, r, 0, REAL_INFINITY, &hit, &counts));
        assert_int_equal(10, counts.cells);
        /* The sliver is in all 10 cells; the corner spheres in the end cells. */
        assert_int_equal(m == 0 ? 1 + 8 : 10 + 8, counts.tests);
        fast_grid_free(&g);
    }
    surface_list_free(&list);
}

/* The leap's cubes: for every cell and octant, empty[o n_cells + c] is the side of
 * the largest cube of empty cells with c as its corner and lying ahead of c
 * in octant o (cells beyond the grid count as empty, capped at 255 or at the
 * largest n_a + 1 if less), found
 * here by growing the cube one cell at a time. */
static bool cube_empty(const fast_grid *g, int i, int j, int k, int o, int side)
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
    fast_grid g;
    fast_grid_options opt = fast_grid_default_options();
    opt.density = 40;
    build_fast(&g, &list, opt);
    assert_non_null(g.empty);
    long occupied = 0;
    for (long c = 0; c < g.n_cells; c++)
        occupied += g.start[c + 1] > g.start[c];
    if (occupied == 0)
        fail_msg("no cell lists a surface (%d x %d x %d cells, 12 spheres): is cell_range still the exercise's stub?",
                 g.n[0], g.n[1], g.n[2]);
    const int largest = g.n[0] > g.n[1] ? (g.n[0] > g.n[2] ? g.n[0] : g.n[2]) : (g.n[1] > g.n[2] ? g.n[1] : g.n[2]);
    long leaps = 0;
    int from[3] = {-1, -1, -1}; /* a cell with an empty cube of side 3 or more ahead in octant 0 */
    for (int k = 0; k < g.n[2]; k++)
        for (int j = 0; j < g.n[1]; j++)
            for (int i = 0; i < g.n[0]; i++)
                for (int o = 0; o < 8; o++) {
                    int side = 0;
                    while (side <= largest && cube_empty(&g, i, j, k, o, side + 1))
                        side++;
                    if (side > largest) /* reaches past the grid on every axis: the largest side kept */
                        side = largest < 255 ? largest + 1 : 255;
                    long c = i + (long)g.n[0] * (j + (long)g.n[1] * k);
                    if (g.empty[o * g.n_cells + c] != side)
                        fail_msg("cell (%d, %d, %d), octant %d: empty cube of side %d expected, the grid says %d", i,
                                 j, k, o, side, g.empty[o * g.n_cells + c]);
                    leaps += side >= 2;
                    if (o == 0 && side >= 3 && from[0] < 0)
                        from[0] = i, from[1] = j, from[2] = k;
                }
    assert_true(leaps > 0); /* the scene leaves room to leap */
    assert_true(from[0] >= 0);
    /* A ray from that cell's centre into octant 0 leaps at once; without the
     * leap table it steps, and finds the same answer. */
    ray r = {vec3_add(g.lo, vec3_make(((real)from[0] + (real)0.5) * g.cell.x, ((real)from[1] + (real)0.5) * g.cell.y,
                                      ((real)from[2] + (real)0.5) * g.cell.z)),
             {1, (real)1.1, (real)1.3}};
    fast_grid stepping;
    opt.leap = false;
    build_fast(&stepping, &list, opt);
    fast_grid_counts leaping_counts = {0, 0, 0, 0}, stepping_counts = {0, 0, 0, 0};
    hit_record leaping_hit, stepping_hit;
    bool leaping_found = fast_grid_intersect_counted(&g, r, 0, REAL_INFINITY, &leaping_hit, &leaping_counts);
    bool stepping_found = fast_grid_intersect_counted(&stepping, r, 0, REAL_INFINITY, &stepping_hit, &stepping_counts);
    assert_true(leaping_counts.leaps >= 1);
    assert_int_equal(0, stepping_counts.leaps);
    assert_true(leaping_counts.cells < stepping_counts.cells);
    assert_int_equal(stepping_found, leaping_found);
    if (leaping_found) {
        assert_int_equal(stepping_hit.surface, leaping_hit.surface);
        assert_true(stepping_hit.t == leaping_hit.t);
    }
    fast_grid_free(&stepping);
    fast_grid_free(&g);
    surface_list_free(&list);
}

/* The fast grid makes the watertight test's ray part once per ray, and only
 * for directions that triangle_intersect tests as they are: a d longer than
 * 2^REAL_SAFE_EXPONENT is divided by a power of two there first, and the
 * grid must then take that path too.  Random scenes with each triangle test;
 * the same rays with d as it is and with d's largest component made the
 * largest power of two (there S_z = 1 / d_z is below the normal reals, and
 * the test without the scaling loses digits of t): the same answers as the
 * linear scan, bit for bit, record and all. */
static void test_directions_of_any_length(void **state)
{
    (void)state;
    rng_state = 20;
    for (int t = 0; t < 2; t++)
        for (int huge = 0; huge < 2; huge++) {
            surface_list list;
            surface_list_init(&list, SPHERE_ROBUST, triangle_tests[t]);
            vec3 centre = uniform_vec(vec3_make(-100, -100, -100), vec3_make(100, 100, 100));
            random_scene(&list, 300, centre, 10);
            const long n = 2000;
            ray_set rays = rays_alloc(n);
            for (long k = 0; k < n; k++) {
                vec3 p = vec3_add(centre, vec3_scale(random_direction(), k % 2 ? 40 : 8));
                vec3 target = vec3_add(centre, vec3_scale(random_direction(), 10));
                vec3 d = vec3_sub(target, p);
                if (huge) /* exactly: a power of two times d */
                    d = vec3_ldexp(d, ilogb((double)REAL_MAX) - ilogb((double)vec3_max_abs(d)));
                set_ray(&rays, k, p, d);
            }
            expect_as_linear(&list, &rays, n / 4);
        }
}

/* Rays with a NaN or an infinite coordinate in p or d (three rays in four)
 * among ordinary ones: every knob set answers each as the linear scan does,
 * and every march ends (its rounding bounds may then be NaN). */
static void test_rays_not_finite(void **state)
{
    (void)state;
    rng_state = 29;
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
    const vec3 centre = uniform_vec(vec3_make(-100, -100, -100), vec3_make(100, 100, 100));
    random_scene(&list, 300, centre, 10);
    const long n = 2000;
    ray_set rays = rays_alloc(n);
    for (long k = 0; k < n; k++) {
        vec3 p = vec3_add(centre, vec3_scale(random_direction(), k % 8 < 4 ? 8 : 40));
        vec3 d = vec3_sub(vec3_add(centre, vec3_scale(random_direction(), 10)), p);
        vec3 *v = k % 4 == 2 ? &d : &p;
        real *const components[3] = {&v->x, &v->y, &v->z};
        real *component = components[(k / 4) % 3];
        if (k % 4 == 1 || k % 4 == 2)
            *component = (real)NAN;
        else if (k % 4 == 3)
            *component = k % 8 < 4 ? REAL_INFINITY : -REAL_INFINITY;
        if (k % 32 >= 24 && k % 4 != 2) { /* along an axis: the others' boundaries are never crossed */
            const real along = d.x;
            d = vec3_make(0, 0, 0);
            *(k % 3 == 0 ? &d.x : k % 3 == 1 ? &d.y : &d.z) = along != 0 ? along : 1;
        }
        set_ray(&rays, k, p, d);
    }
    expect_as_linear(&list, &rays, n / 32); /* the ordinary quarter aims at the scene: much of it hits */
}

/* The search's next real above a best t (next_above, the bits plus one for a
 * positive finite t) is the library's real_next_up, bit for bit, on both
 * sides of every boundary of the fast path and beyond it. */
static void test_next_above(void **state)
{
    (void)state;
    assert_true(next_above(1) == 1 + REAL_EPSILON);                 /* the spacing above 1 is epsilon */
    assert_true(next_above(REAL_MAX) == REAL_INFINITY);             /* the largest finite real */
    assert_true(next_above(REAL_MIN - REAL_MIN * REAL_EPSILON) > 0); /* a subnormal */
    assert_true(isnan(next_above((real)NAN)));
    const real x[] = {1,  (real)0.1, 3e-5f, REAL_MIN, REAL_MIN / 8, REAL_MAX / 2, REAL_MAX, 0, -0.0f, -1,
                      -REAL_MIN / 8, -REAL_MAX, REAL_INFINITY, -REAL_INFINITY, 12345.678f};
    for (size_t k = 0; k < sizeof x / sizeof x[0]; k++) {
        const real got = next_above(x[k]), want = real_next_up(x[k]);
        if (memcmp(&got, &want, sizeof got) != 0)
            fail_msg("next_above(%a) = %a, real_next_up gives %a", (double)x[k], (double)got, (double)want);
    }
}

/* Whether a grid of `list` built with the knob `prefetch` prefetches. */
static bool prefetches(const surface_list *list, int prefetch)
{
    fast_grid g;
    fast_grid_options opt = fast_grid_default_options();
    opt.prefetch = prefetch;
    build_fast(&g, list, opt);
    const bool on = g.prefetch;
    fast_grid_free(&g);
    return on;
}

/* Prefetching by size: off for a grid and surfaces within FAST_GRID_PREFETCH_FROM
 * bytes, on beyond, and as the knob says when it says. */
static void test_prefetch_by_size(void **state)
{
    (void)state;
    rng_state = 5;
    const long big = (long)(FAST_GRID_PREFETCH_FROM / (long)sizeof(surface)) + 1; /* the surfaces alone exceed it */
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
    random_scene(&list, 100, vec3_make(3, -2, 7), 5);
    fast_grid g;
    build_fast(&g, &list, fast_grid_default_options());
    assert_true(fast_grid_memory(&g) + (size_t)list.n * sizeof(surface) <= (size_t)FAST_GRID_PREFETCH_FROM);
    fast_grid_free(&g);
    assert_false(prefetches(&list, FAST_GRID_PREFETCH_AUTO));
    assert_true(prefetches(&list, FAST_GRID_PREFETCH_ON));
    random_scene(&list, (int)big - 100, vec3_make(3, -2, 7), 5);
    assert_int_equal(big, list.n);
    assert_true(prefetches(&list, FAST_GRID_PREFETCH_AUTO));
    assert_false(prefetches(&list, FAST_GRID_PREFETCH_OFF));
    fast_grid_options opt = fast_grid_default_options();
    opt.prefetch = FAST_GRID_PREFETCH_OFF + 1;
    char err[256];
    assert_int_equal(-1, fast_grid_build(&g, &list, opt, err, sizeof err));
    surface_list_free(&list);
}

/* fast_grid_closest answers as fast_grid_intersect does, without the
 * record: the same surface, t, beta and gamma (==), with both triangle
 * tests, on scenes of small triangles and spheres far from the origin, for
 * rays from outside and inside aimed at a point well inside a triangle (so
 * that most hit one: a ray that grazes its target's plane may be refused by
 * the certainty check); and the normals knob costs exactly a vec3 per
 * surface. */
static void test_closest_without_record(void **state)
{
    (void)state;
    rng_state = 23;
    const int n_rays = 2000;
    for (int scene_no = 0; scene_no < 2; scene_no++) {
        surface_list list;
        surface_list_init(&list, SPHERE_ROBUST, triangle_tests[scene_no]);
        const vec3 centre = uniform_vec(vec3_make(-500, -500, -500), vec3_make(500, 500, 500));
        const real half = uniform(2, 30);
        const vec3 lo = vec3_sub(centre, vec3_make(half, half, half)), hi = vec3_add(centre, vec3_make(half, half, half));
        for (int k = 0; k < 120; k++) { /* sizes a few hundredths of the box: a ray rarely passes another surface */
            const vec3 c = uniform_vec(lo, hi);
            const real size = half * uniform((real)0.02, (real)0.06);
            if (k % 2)
                surface_list_add_sphere(&list, (sphere){c, size}, 0, k);
            else
                surface_list_add_triangle(&list, (triangle){vec3_add(c, vec3_scale(random_direction(), size)),
                                                            vec3_add(c, vec3_scale(random_direction(), size)),
                                                            vec3_add(c, vec3_scale(random_direction(), size))},
                                          0, k);
        }
        fast_grid g;
        fast_grid_options opt = fast_grid_default_options();
        build_fast(&g, &list, opt);
        const size_t without = fast_grid_memory(&g);
        fast_grid_free(&g);
        opt.normals = true;
        build_fast(&g, &list, opt);
        assert_int_equal(without + (size_t)list.n * sizeof(vec3), fast_grid_memory(&g));
        int triangle_hits = 0;
        for (int k = 0; k < n_rays; k++) {
            const triangle *target = &list.items[2 * (next_u64() % 60)].triangle;
            const real beta = uniform((real)0.2, (real)0.4), gamma = uniform((real)0.2, (real)0.4);
            const vec3 aim = vec3_add(target->a, vec3_add(vec3_scale(vec3_sub(target->b, target->a), beta),
                                                          vec3_scale(vec3_sub(target->c, target->a), gamma)));
            const vec3 p = vec3_add(centre, vec3_scale(random_direction(), (k % 2 ? 3 : 1) * half));
            const ray r = {p, vec3_sub(aim, p)};
            hit_record rec;
            fast_grid_hit h;
            const bool found = fast_grid_intersect(&g, r, 0, REAL_INFINITY, &rec);
            if (found != fast_grid_closest(&g, r, 0, REAL_INFINITY, &h))
                fail_msg("ray %d: fast_grid_intersect %s, fast_grid_closest does not", k, found ? "hits" : "misses");
            if (!found)
                continue;
            triangle_hits += list.items[rec.surface].kind == SHAPE_TRIANGLE;
            if (h.surface != rec.surface || h.t != rec.t || h.beta != rec.beta || h.gamma != rec.gamma)
                fail_msg("ray %d: the record says surface %d at t = %a (beta %a, gamma %a), fast_grid_closest %d "
                         "at %a (%a, %a)", k, rec.surface, (double)rec.t, (double)rec.beta, (double)rec.gamma,
                         h.surface, (double)h.t, (double)h.beta, (double)h.gamma);
        }
        /* most rays meet their target first: beta and gamma were compared on triangles */
        if (triangle_hits < n_rays / 2)
            fail_msg("only %d of %d rays hit a triangle first", triangle_hits, n_rays);
        fast_grid_free(&g);
        surface_list_free(&list);
    }
}

/* Component a of *v set to value. */
static void set_axis(vec3 *v, int a, real value) { *(a == 0 ? &v->x : a == 1 ? &v->y : &v->z) = value; }

/* The box [lo, hi] added to list as the scene reader adds one: twelve triangles (box_triangles). */
static void add_box(surface_list *list, vec3 lo, vec3 hi, int source)
{
    vec3 t[BOX_TRIANGLES][3];
    box_triangles(lo, hi, t);
    for (int k = 0; k < BOX_TRIANGLES; k++)
        surface_list_add_triangle(list, (triangle){t[k][0], t[k][1], t[k][2]}, 0, source);
}

/* Boxes of twelve triangles (box_triangles, as the scene reader makes them),
 * each tested as one box: thin slabs, sticks, cubes, one large box, small
 * cubes crowded into cells that cull, a box twice and two boxes that share a
 * corner, after a sphere, far from the origin at a random scale.  The rays
 * are test_box's edge cases: rays from outside at the boxes' faces, at
 * points on the diagonal a face's two triangles share, at edges and corners
 * (along an axis and a cube's diagonal too), rays that start on a face with
 * t_min > 0 and leave it (as shadow rays do), rays along a face's plane and
 * along an axis, and windows that start or end at the hit on a face or a
 * real away from it; every knob set against the linear scan.  Then a box is
 * found: a ray at a face tests that face's two triangles, where the cells
 * that list the twelve test more. */
static void test_boxes_as_boxes(void **state)
{
    (void)state;
    rng_state = 29;
    const long n = 4800;
    enum { BOXES = 30 };
    for (int scene_no = 0; scene_no < 4; scene_no++) {
        surface_list list;
        surface_list_init(&list, SPHERE_ROBUST, triangle_tests[scene_no % 2]);
        const real unit = scene_no < 2 ? uniform((real)0.5, 2) : (scene_no == 2 ? (real)1e-5 : (real)1e5);
        const vec3 centre = vec3_scale(uniform_vec(vec3_make(-300, -300, -300), vec3_make(300, 300, 300)), unit);
        /* a sphere first, so that no box starts at a multiple of twelve */
        surface_list_add_sphere(&list, (sphere){vec3_add(centre, vec3_make(0, 20 * unit, 0)), unit}, 0, BOXES);
        vec3 lo[BOXES], hi[BOXES];
        for (int b = 0; b < BOXES; b++) {
            const vec3 c = vec3_add(centre, vec3_scale(uniform_vec(vec3_make(-8, -8, -8), vec3_make(8, 8, 8)), unit));
            vec3 half = vec3_scale(uniform_vec(vec3_make((real)0.3, (real)0.3, (real)0.3), vec3_make(2, 2, 2)), unit);
            if (b % 4 == 1) /* a slab */
                half.y = (real)0.013 * unit;
            if (b % 4 == 2) /* a stick */
                half.x = half.z = (real)0.05 * unit;
            if (b == 3) /* a box around several others */
                half = vec3_scale(vec3_make(6, 5, 7), unit);
            lo[b] = vec3_sub(c, half);
            hi[b] = vec3_add(c, half);
            if (b >= 16 && b < 28) { /* small cubes crowded together: cells of many boxes, which cull */
                const vec3 at = vec3_add(centre, vec3_scale(uniform_vec(vec3_make(-1, -1, -1), vec3_make(1, 1, 1)), unit));
                lo[b] = vec3_sub(at, vec3_scale(vec3_make((real)0.15, (real)0.15, (real)0.15), unit));
                hi[b] = vec3_add(at, vec3_scale(vec3_make((real)0.15, (real)0.15, (real)0.15), unit));
            }
            if (b == 28) { /* box 0 again: ties across boxes */
                lo[b] = lo[0];
                hi[b] = hi[0];
            }
            if (b == 29) { /* a box with a corner on box 1's */
                lo[b] = hi[1];
                hi[b] = vec3_add(hi[1], vec3_scale(vec3_make(1, 1, 1), unit));
            }
            add_box(&list, lo[b], hi[b], b);
        }
        ray_set rays = rays_alloc(n);
        for (long k = 0; k < n; k++) {
            const int b = (int)(next_u64() % BOXES), kind = (int)(k % 6);
            const vec3 size = vec3_sub(hi[b], lo[b]);
            vec3 on = vec3_add(lo[b], vec3_make(size.x * uniform(0, 1), size.y * uniform(0, 1), size.z * uniform(0, 1)));
            const int axis = (int)(next_u64() % 3), high = (int)(next_u64() % 2);
            set_axis(&on, axis, vec3_axis(high ? hi[b] : lo[b], axis)); /* a point on a face */
            if (next_u64() % 2) { /* on the diagonal its two triangles share (box_triangles': low u, v to high) */
                const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                const real f = uniform(0, 1);
                set_axis(&on, u, vec3_axis(lo[b], u) + f * (vec3_axis(hi[b], u) - vec3_axis(lo[b], u)));
                set_axis(&on, v, vec3_axis(lo[b], v) + f * (vec3_axis(hi[b], v) - vec3_axis(lo[b], v)));
            }
            if (kind == 5) /* on an edge, or a corner */
                for (int a = 0; a < 3; a++)
                    if (a != axis && (a == (axis + 1) % 3 || next_u64() % 2))
                        set_axis(&on, a, vec3_axis(next_u64() % 2 ? hi[b] : lo[b], a));
            vec3 d = random_direction();
            if (kind == 2) /* along the face's plane */
                set_axis(&d, axis, 0);
            if (kind == 3 || (kind == 5 && next_u64() % 3 == 0)) /* along an axis */
                d = vec3_make(axis == 0 ? 1 : 0, axis == 1 ? -1 : 0, axis == 2 ? 1 : 0);
            else if (kind == 5 && next_u64() % 2) /* along a diagonal of the cube */
                d = vec3_make(next_u64() % 2 ? 1 : -1, next_u64() % 2 ? 1 : -1, next_u64() % 2 ? 1 : -1);
            const vec3 p = kind == 1 || kind == 2 ? on : vec3_sub(on, vec3_scale(d, 30 * unit));
            rays.r[k] = (ray){p, kind == 0 ? vec3_sub(on, p) : d};
            rays.t_min[k] = kind == 1 ? 64 * REAL_EPSILON * uniform(1, 100) : 0;
            rays.t_max[k] = kind == 4 ? uniform(0, 40) : REAL_INFINITY;
            hit_record h;
            if (kind == 4 && surfaces_intersect(&list, rays.r[k - 4], 0, REAL_INFINITY, &h)) {
                /* a window that starts or ends at the hit of ray k - 4 (at a face) or a real away from it: where
                 * rounding decides whether a face's plane is crossed in the window */
                const int end = (int)(next_u64() % 4);
                rays.r[k] = rays.r[k - 4];
                rays.t_min[k] = end == 0 ? -real_next_up(-h.t) : end == 1 ? h.t : 0; /* the real below h.t, h.t */
                rays.t_max[k] = end == 2 ? real_next_up(h.t) : end == 3 ? h.t : REAL_INFINITY;
            }
        }
        expect_as_linear(&list, &rays, n / 4);
    }
    /* a lattice of 4 x 4 x 4 small cubes, many to a cell, which culls them by the parts of their
     * triangles' boxes it holds: rays at their faces from every side, most of which pass one face of a cube
     * and never come near its opposite face */
    {
        surface_list list;
        surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
        const vec3 corner = vec3_make((real)1003.7, -(real)251.3, (real)77.1);
        vec3 lo[64], hi[64];
        for (int b = 0; b < 64; b++) {
            lo[b] = vec3_add(corner, vec3_make((real)0.5 * (b % 4), (real)0.5 * (b / 4 % 4), (real)0.5 * (b / 16)));
            hi[b] = vec3_add(lo[b], vec3_make((real)0.3, (real)0.3, (real)0.3));
            add_box(&list, lo[b], hi[b], b);
        }
        ray_set rays = rays_alloc(n);
        for (long k = 0; k < n; k++) {
            const int b = (int)(next_u64() % 64), axis = (int)(next_u64() % 3), high = (int)(next_u64() % 2);
            vec3 on = vec3_add(lo[b], vec3_make((real)0.3 * uniform(0, 1), (real)0.3 * uniform(0, 1), (real)0.3 * uniform(0, 1)));
            set_axis(&on, axis, vec3_axis(high ? hi[b] : lo[b], axis));
            const vec3 from = vec3_add(on, vec3_scale(random_direction(), 10));
            set_ray(&rays, k, from, vec3_sub(on, from));
        }
        expect_as_linear(&list, &rays, n / 4);
    }
    /* found: a slab alone (one cell thick: a box is tested as one where its faces share cells), rays at its
     * +x face (triangles 2 and 3 of box_triangles), at the face's centre and at a point off its diagonal:
     * the face's two triangles are tested, no other */
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
    add_box(&list, vec3_make((real)10.1, -(real)3.3, (real)7.7), vec3_make((real)11.9, -(real)3.2, (real)9.4), 0);
    const vec3 d = vec3_make(-1, (real)0.0001, (real)0.0002);
    const vec3 targets[2] = {vec3_make((real)11.9, -(real)3.25, (real)8.55), vec3_make((real)11.9, -(real)3.22, (real)7.9)};
    for (int q = 0; q < 2; q++)
        for (int as_box = 0; as_box < 2; as_box++) {
            const ray r = {vec3_sub(targets[q], vec3_scale(d, 18)), d};
            fast_grid g;
            fast_grid_options opt = fast_grid_default_options();
            opt.boxes = as_box;
            opt.list_up_to = 0; /* cells, not a list of one box */
            build_fast(&g, &list, opt);
            fast_grid_counts counts = {0};
            hit_record h;
            assert_true_why(fast_grid_intersect_counted(&g, r, 0, REAL_INFINITY, &h, &counts),
                            "the ray at the +x face misses the box (boxes %s)", as_box ? "on" : "off");
            assert_true_why(h.surface == 2 || h.surface == 3,
                            "the ray hit triangle %d, not one of the +x face's (2, 3)", h.surface);
            if (as_box && counts.tests != 2)
                fail_msg("a box's ray at its +x face %s: 2 triangle tests expected (the face's), %llu made",
                         q ? "off the diagonal" : "at its centre", (unsigned long long)counts.tests);
            if (!as_box && counts.tests <= 2)
                fail_msg("without boxes the cells at the +x face list more than its two triangles: more than 2 "
                         "tests expected, %llu", (unsigned long long)counts.tests);
            fast_grid_free(&g);
        }
    surface_list_free(&list);
}

/* A scene of few surfaces is a list, without cells: with the default knobs
 * when its units cost a ray at most 9 triangle tests (a triangle 1, a box
 * 1.25, a sphere 4: fast_few.c's weights), else cells; surfaces without
 * finite bounds are tested apart and do not count.  Each case one unit
 * either side of the bound, far from the origin; the knob sets above run
 * every scene both ways against the linear scan. */
static void test_few_surfaces_as_a_list(void **state)
{
    (void)state;
    rng_state = 29;
    const struct {
        int boxes, spheres, triangles;
        bool list;
    } cases[] = {{0, 0, 1, true},  {5, 0, 0, true},  {7, 0, 0, true},  {8, 0, 0, false}, {0, 2, 1, true},
                 {0, 2, 2, false}, {0, 0, 9, true},  {0, 0, 10, false}, {3, 1, 1, true}, {3, 1, 2, false}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        surface_list list;
        surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
        const vec3 at = vec3_make(uniform(-9000, 9000), uniform(-9000, 9000), uniform(-9000, 9000));
        int source = 0;
        for (int k = 0; k < cases[c].boxes; k++) {
            const vec3 lo = vec3_add(at, uniform_vec(vec3_make(-5, -5, -5), vec3_make(5, 5, 5)));
            const vec3 size = uniform_vec(vec3_make((real)0.1, (real)0.1, (real)0.1), vec3_make(2, 2, 2));
            add_box(&list, lo, vec3_add(lo, size), source++);
        }
        for (int k = 0; k < cases[c].spheres; k++)
            surface_list_add_sphere(&list, (sphere){vec3_add(at, uniform_vec(vec3_make(-5, -5, -5), vec3_make(5, 5, 5))),
                                                    uniform((real)0.1, 2)},
                                    0, source++);
        for (int k = 0; k < cases[c].triangles; k++) {
            const vec3 a = vec3_add(at, uniform_vec(vec3_make(-5, -5, -5), vec3_make(5, 5, 5)));
            surface_list_add_triangle(&list, (triangle){a, vec3_add(a, random_direction()), vec3_add(a, random_direction())},
                                      0, source++);
        }
        /* and one surface that no cell could hold: it never counts */
        surface_list_add_triangle(&list, (triangle){at, vec3_make(REAL_INFINITY, 0, 0), vec3_add(at, random_direction())},
                                  0, source++);
        const long units = cases[c].boxes + cases[c].spheres + cases[c].triangles;
        for (int up_to = 0; up_to < 2; up_to++) {
            fast_grid_options opt = fast_grid_default_options();
            opt.list_up_to = up_to ? FAST_GRID_DEFAULT_LIST_UP_TO : 0;
            fast_grid g;
            build_fast(&g, &list, opt);
            const bool list_expected = up_to && cases[c].list;
            if ((g.units != NULL) != list_expected || (list_expected && g.n_units != units) ||
                (g.n_cells == 0) != list_expected || g.n_unbinned != 1)
                fail_msg("%d boxes, %d spheres, %d triangles (list_up_to %d): expected %s, got %ld units, %ld cells, "
                         "%ld unbinned (1 expected)",
                         cases[c].boxes, cases[c].spheres, cases[c].triangles, opt.list_up_to,
                         list_expected ? "a list of them all" : "cells", g.n_units, g.n_cells, g.n_unbinned);
            fast_grid_free(&g);
        }
        surface_list_free(&list);
    }
    /* A list tests its units whatever the ray: a direction whose components are so small that 1 / d_a
     * overflows (subnormal) still moves the ray, at t near 1e306 (1e37 in float), where the march takes them
     * as 0.  A box of side 0.02 (its slab cut), a triangle and a sphere beside it, against the linear scan. */
    surface_list tiny;
    surface_list_init(&tiny, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
    const real side = (real)0.02;
    add_box(&tiny, vec3_make(0, 0, 0), vec3_make(side, side, side), 0);
    surface_list_add_triangle(&tiny, (triangle){vec3_make(-side, -side, -side), vec3_make(-side, 0, -side),
                                                vec3_make(0, -side, -side)},
                              0, 1);
    surface_list_add_sphere(&tiny, (sphere){vec3_make(2 * side, side, 0), side / 4}, 0, 2);
    const long n = 2000;
    ray_set rays = rays_alloc(n);
    for (long k = 0; k < n; k++) {
        /* beside the box, and for every other ray below the scene's box (outside its slab along z) */
        const vec3 p = uniform_vec(vec3_make(-side, -side, k % 2 ? -3 * side : -side),
                                   vec3_make(0, side, k % 2 ? -2 * side : 0));
        const vec3 to = vec3_sub(uniform_vec(vec3_make(0, 0, 0), vec3_make(side, side, side)), p);
        vec3 d = vec3_scale(to, REAL_MIN * uniform((real)0.04, (real)0.1) / vec3_max_abs(to));
        if (k % 3 == 1)
            d.y = 0; /* and one component exactly 0 */
        set_ray(&rays, k, p, d);
    }
    hit_record *expected = calloc((size_t)n, sizeof *expected);
    bool *found = calloc((size_t)n, sizeof *found);
    assert_non_null(expected);
    assert_non_null(found);
    const long hits = linear_answers(&tiny, rays.r, rays.t_min, rays.t_max, n, expected, found);
    compare_grid(&tiny, fast_grid_default_options() /* a list of 3 units */, rays.r, rays.t_min, rays.t_max, n, expected, found);
    if (hits <= n / 4)
        fail_msg("only %ld of %ld tiny rays hit something (more than %ld expected)", hits, n, n / 4);
    free(expected);
    free(found);
    rays_free(&rays);
    surface_list_free(&tiny);
    /* a bad knob: a message, no grid */
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
    surface_list_add_sphere(&list, (sphere){vec3_make(1, 2, 3), 1}, 0, 0);
    fast_grid_options opt = fast_grid_default_options();
    opt.list_up_to = -1;
    fast_grid g;
    char err[256] = "";
    assert_int_equal(-1, fast_grid_build(&g, &list, opt, err, sizeof err));
    assert_non_null(strstr(err, "the list's cost >= 0"));
    surface_list_free(&list);
}

/* The floor of test_large_surfaces_apart, half-width w, its top at y = 0: a
 * box (one unit), two triangles, a sphere of radius w below the plane, or
 * five strips of two triangles (ten units, beyond list_up_to). */
enum { FLOOR_BOX, FLOOR_TWO_TRIANGLES, FLOOR_SPHERE, FLOOR_TEN_TRIANGLES };
static void add_floor(surface_list *list, int kind, vec3 at, real w, int *source)
{
    if (kind == FLOOR_BOX) {
        add_box(list, vec3_add(at, vec3_make(-w, -w / 50, -w)), vec3_add(at, vec3_make(w, 0, w)), (*source)++);
    } else if (kind == FLOOR_SPHERE) {
        surface_list_add_sphere(list, (sphere){vec3_add(at, vec3_make(0, -w, 0)), w}, 0, (*source)++);
    } else {
        const int strips = kind == FLOOR_TWO_TRIANGLES ? 1 : 5;
        for (int k = 0; k < strips; k++) {
            const real x0 = -w + 2 * w * (real)k / (real)strips, x1 = -w + 2 * w * (real)(k + 1) / (real)strips;
            const vec3 a = vec3_add(at, vec3_make(x0, 0, -w)), b = vec3_add(at, vec3_make(x1, 0, -w)),
                       c = vec3_add(at, vec3_make(x1, 0, w)), d = vec3_add(at, vec3_make(x0, 0, w));
            surface_list_add_triangle(list, (triangle){a, b, c}, 0, (*source)++);
            surface_list_add_triangle(list, (triangle){a, c, d}, 0, (*source)++);
        }
    }
}

/* The few large surfaces of a scene are tested apart from the cells, which
 * then cover the others alone (fast_few.c): a floor 200 units wide (a box,
 * two triangles or a sphere as the ground) under a cluster of boxes, spheres
 * and turned triangles a few units wide, far from the origin at scales 1e-5
 * to 1e5, once after a box too large to stay a box in the cells (dropped by
 * fast_boxes_keep_small, which renumbers the boxes kept).  Not apart: with
 * list_up_to 0, under a cluster spread over the floor (the cells would not
 * get finer), under a cluster a few margins wide (its cells would be
 * narrower than the margin every box is widened by), under a floor of ten
 * triangles (a ray would test more than list_up_to), nor a stick as tall as
 * the scene (its short axis).  Every scene against the linear scan with
 * every knob set: rays from above at the cluster and the floor around it,
 * rays that leave the floor's top with t_min > 0 (as shadow rays do), rays
 * along the floor's plane, along the axes, from a million to 1e11 times the
 * surfaces' size away (as far as a real resolves them) at the floor's edges
 * and corners and at the spheres' rims, and with direction components so
 * small that 1 / d_a overflows. */
static void test_large_surfaces_apart(void **state)
{
    (void)state;
    rng_state = 31;
    enum { SPREAD, TINY, DROPPED_BOX, STICK };
    const struct {
        int floor;
        real spread; /* the cluster's half-width, in units of the floor's half-width */
        int kind;    /* and what else the scene has */
        long apart;  /* with the default knobs: the entries apart */
    } cases[] = {{FLOOR_BOX, (real)0.02, SPREAD, 1},          {FLOOR_TWO_TRIANGLES, (real)0.02, SPREAD, 2},
                 {FLOOR_SPHERE, (real)0.02, SPREAD, 1},       {FLOOR_TEN_TRIANGLES, (real)0.02, SPREAD, 0},
                 {FLOOR_BOX, (real)0.9, SPREAD, 0},            {FLOOR_BOX, (real)0.02, STICK, 1},
                 {FLOOR_BOX, (real)0.02, DROPPED_BOX, 1},     {FLOOR_TWO_TRIANGLES, 0, TINY, 0}};
    const real scales[] = {(real)1e-5, 1, (real)1e5};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
        for (size_t sc = 0; sc < sizeof scales / sizeof scales[0]; sc++) {
            const real unit = scales[sc] * uniform((real)0.7, (real)1.4), w = 100 * unit;
            /* a thousand units from the origin: in float, the margin there is a hundredth of the cluster's cells */
            const vec3 at = vec3_scale(uniform_vec(vec3_make(-1000, -1000, -1000), vec3_make(1000, 1000, 1000)), unit);
            /* a tiny cluster: 4 margins of the scene's size (fast_build.c) across, its surfaces as small */
            const real margin = 64 * REAL_EPSILON * (vec3_max_abs(at) + w);
            const real h = cases[c].kind == TINY ? 2 * margin : cases[c].spread * w;
            const real size = cases[c].kind == TINY ? margin / 2 : unit;
            const vec3 cluster = vec3_add(at, vec3_make(0, 3 * size, 0));
            const vec3 near_lo = vec3_add(cluster, vec3_make(-h, -2 * size, -h)),
                       near_hi = vec3_add(cluster, vec3_make(h, 2 * size, h));
            surface_list list;
            surface_list_init(&list, SPHERE_ROBUST, triangle_tests[c % 2]);
            int source = 0;
            if (cases[c].kind == DROPPED_BOX) /* 10 units: more than two of the cluster's cells along every axis */
                add_box(&list, vec3_add(cluster, vec3_scale(vec3_make(-5, 0, -5), unit)),
                        vec3_add(cluster, vec3_scale(vec3_make(5, 10, 5), unit)), source++);
            add_floor(&list, cases[c].floor, at, w, &source);
            sphere balls[6];
            for (int k = 0; k < 6; k++) {
                const vec3 lo = uniform_vec(near_lo, near_hi);
                add_box(&list, lo, vec3_add(lo, vec3_scale(uniform_vec(vec3_make((real)0.1, (real)0.1, (real)0.1),
                                                                       vec3_make(1, 1, 1)), size)),
                        source++);
                balls[k] = (sphere){uniform_vec(near_lo, near_hi), uniform((real)0.1, (real)0.5) * size};
                surface_list_add_sphere(&list, balls[k], 0, source++);
                const vec3 a = uniform_vec(near_lo, near_hi);
                surface_list_add_triangle(&list, (triangle){a, vec3_add(a, vec3_scale(random_direction(), size)),
                                                            vec3_add(a, vec3_scale(random_direction(), size))},
                                          0, source++);
            }
            if (cases[c].kind == STICK) /* from the floor to above the cluster: the scene's height */
                add_box(&list, vec3_add(cluster, vec3_make(0, -3 * unit, 0)),
                        vec3_add(cluster, vec3_make(unit / 10, 3 * unit, unit / 10)), source++);
            /* set apart or not, and then the cells' box */
            for (int up_to = 0; up_to < 2; up_to++) {
                fast_grid_options opt = fast_grid_default_options();
                opt.list_up_to = up_to ? FAST_GRID_DEFAULT_LIST_UP_TO : 0;
                fast_grid g;
                build_fast(&g, &list, opt);
                const long expected = up_to ? cases[c].apart : 0;
                const real width = g.hi.x - g.lo.x;
                if (g.n_apart != expected || g.n_cells == 0 || (expected > 0) != (width < w / 4))
                    fail_msg("case %zu at scale %g (list_up_to %d): %ld entries apart (%ld expected), %ld cells, "
                             "cells' box %g wide (the floor %g)",
                             c, (double)unit, opt.list_up_to, g.n_apart, expected, g.n_cells, (double)width,
                             (double)(2 * w));
                fast_grid_free(&g);
            }
            const long n = 3000;
            ray_set rays = rays_alloc(n);
            for (long k = 0; k < n; k++) {
                const vec3 target = k % 8 ? uniform_vec(near_lo, near_hi)
                                          : vec3_add(at, vec3_make(uniform(-3 * h, 3 * h), 0, uniform(-3 * h, 3 * h)));
                vec3 p, d;
                if (k % 6 == 0) { /* from above */
                    p = vec3_add(cluster, vec3_scale(vec3_make(uniform(-20, 20), uniform(5, 20), uniform(-20, 20)), size));
                    d = vec3_sub(target, p);
                } else if (k % 6 == 1) { /* leaving the floor's top */
                    p = vec3_add(at, vec3_make(uniform(-2 * h, 2 * h), 0, uniform(-2 * h, 2 * h)));
                    d = vec3_sub(target, p);
                    d.y = real_abs(d.y) + size / 100;
                } else if (k % 6 == 2) { /* along the floor's plane, or just above it */
                    p = vec3_add(at, vec3_make(uniform(-2 * h, 2 * h), k % 12 == 2 ? 0 : size / 1000, uniform(-2 * h, 2 * h)));
                    d = vec3_sub(target, p);
                    d.y = 0;
                } else if (k % 6 == 3) { /* along an axis */
                    p = uniform_vec(vec3_sub(near_lo, vec3_make(size, size, size)), vec3_add(near_hi, vec3_make(size, size, size)));
                    d = vec3_make(0, 0, 0);
                    set_axis(&d, (int)(k / 6 % 3), k / 18 % 2 ? size : -size);
                } else if (k % 6 == 4) { /* from far away at the floor's edges and corners, or at a sphere's rim */
                    const int along = (int)(k / 96 % 3); /* a corner, or a point of an edge along this axis */
                    vec3 aim = vec3_add(at, vec3_make(k % 24 < 12 ? -w : w, k % 48 < 24 ? 0 : -w / 50, k % 96 < 48 ? -w : w));
                    if (k % 7)
                        set_axis(&aim, along, (along == 0 ? at.x : along == 1 ? at.y - w / 100 : at.z) +
                                                  uniform(-1, 1) * (along == 1 ? w / 100 : w));
                    const sphere *ball = &balls[k / 6 % 6];
                    if (k % 12 == 10)
                        aim = vec3_add(ball->center, vec3_scale(random_direction(), ball->radius));
                    /* 1e6, 1e9 and 1e11 times the surfaces' size away, and never so far that a real's rounding of
                     * the ray's t moves its point by more than 1e-4 of that size (in float, 830 times it) */
                    const real far = k % 5 < 2 ? (real)1e6 : k % 5 < 4 ? (real)1e9 : (real)1e11;
                    const real resolved = (real)1e-4 / REAL_EPSILON;
                    p = vec3_add(aim, vec3_scale(random_direction(), (far < resolved ? far : resolved) * size));
                    d = vec3_sub(aim, p);
                } else { /* down from above, with components so small that 1 / d_a overflows (subnormal): the
                          * cells take them as 0 (frame_of's limit, which a ray along them would meet) */
                    p = vec3_add(cluster, vec3_scale(vec3_make(uniform(-20, 20), uniform(5, 20), uniform(-20, 20)), size));
                    d = vec3_make(REAL_MIN * uniform((real)0.01, (real)0.5), -size * uniform((real)0.5, 2),
                                  -REAL_MIN * uniform((real)0.01, (real)0.5));
                }
                set_ray(&rays, k, p, d);
                if (k % 6 == 1)
                    rays.t_min[k] = (real)1e-9 * size;
            }
            expect_as_linear(&list, &rays, n / 5);
        }
}

/* Spheres that touch, in cells of few entries: a row of them resting on a
 * floor of two triangles (set apart), each touching the next, far from the
 * origin at three scales, and rays from a million times their size away to
 * as far as a real resolves them, aimed at where two surfaces touch: a
 * sphere's lowest point from below the floor (steeply, and at a slant, where
 * the floor's t comes through the watertight test's shear along another
 * axis), the point between two spheres from above.  The two hits are a
 * rounding apart along the ray, so the
 * sphere's box in its cell is looked at (test_entries) with the window
 * already closed by the other surface at about the same t: that look, whose
 * frame is a rounding of far points, must allow that rounding. */
static void test_touching_spheres_from_far(void **state)
{
    (void)state;
    rng_state = 41;
    const real scales[] = {(real)1e-3, 1, (real)1e3};
    for (size_t sc = 0; sc < sizeof scales / sizeof scales[0]; sc++)
        for (int order = 0; order < 2; order++) { /* the floor before the spheres in the list, or after */
            const real unit = scales[sc] * uniform((real)0.7, (real)1.4);
            const vec3 at = vec3_scale(uniform_vec(vec3_make(-500, -500, -500), vec3_make(500, 500, 500)), unit);
            enum { BALLS = 12 };
            sphere balls[BALLS];
            real x = 0;
            for (int k = 0; k < BALLS; k++) {
                const real r = uniform((real)0.3, 1) * unit;
                x += k ? balls[k - 1].radius + r : 0;
                balls[k] = (sphere){vec3_add(at, vec3_make(x, r, uniform(-1, 1) * unit / 4)), r};
            }
            surface_list list;
            surface_list_init(&list, SPHERE_ROBUST, triangle_tests[order]);
            int source = 0;
            if (order == 0)
                add_floor(&list, FLOOR_TWO_TRIANGLES, vec3_add(at, vec3_make(x / 2, 0, 0)), 40 * x, &source);
            for (int k = 0; k < BALLS; k++)
                surface_list_add_sphere(&list, balls[k], 0, source++);
            if (order == 1)
                add_floor(&list, FLOOR_TWO_TRIANGLES, vec3_add(at, vec3_make(x / 2, 0, 0)), 40 * x, &source);
            const long n = 4000;
            ray_set rays = rays_alloc(n);
            const real resolved = (real)1e-4 / REAL_EPSILON;
            for (long k = 0; k < n; k++) {
                const sphere *ball = &balls[k % BALLS], *next = &balls[(k + 1) % BALLS];
                vec3 aim, from;
                if (k % 2 == 0 || next == &balls[0]) { /* the lowest point, from below the floor */
                    aim = vec3_sub(ball->center, vec3_make(0, ball->radius, 0));
                    from = vec3_make(uniform(-1, 1), k % 4 == 0 ? -1 : -uniform((real)0.02, (real)0.3), uniform(-1, 1));
                } else { /* between two spheres, from a side */
                    const real f = ball->radius / (ball->radius + next->radius);
                    aim = vec3_add(ball->center, vec3_scale(vec3_sub(next->center, ball->center), f));
                    from = vec3_make(uniform((real)-0.2, (real)0.2), uniform((real)0.05, 1), k % 4 < 2 ? 1 : -1);
                }
                const real far = k % 3 == 0 ? (real)1e6 : resolved;
                const vec3 p = vec3_add(aim, vec3_scale(vec3_normalize(from), far * unit));
                set_ray(&rays, k, p, vec3_sub(aim, p));
            }
            expect_as_linear(&list, &rays, n / 2);
        }
}

/* The build out of memory: each of its allocations fails in turn, on a
 * floor under a cluster of boxes, spheres and triangles (the floor set
 * apart), on a crowded cluster with grids of their own in its cells and the
 * triangles' normals kept, on a scene of few surfaces (a list) and with every
 * knob off.  Each build either fails with "out of memory" and leaves nothing
 * allocated (the sanitizer build's leak check at exit), or succeeds and
 * answers as the linear scan. */
static void test_out_of_memory(void **state)
{
    (void)state;
    rng_state = 43;
    for (int scene = 0; scene < 4; scene++) {
        surface_list list;
        surface_list_init(&list, SPHERE_ROBUST, triangle_tests[scene % 2]);
        int source = 0;
        const vec3 at = uniform_vec(vec3_make(-50, -50, -50), vec3_make(50, 50, 50));
        if (scene == 0)
            add_floor(&list, FLOOR_BOX, at, 100, &source);
        const int units = scene == 2 ? 2 : scene == 1 ? 60 : 8;
        for (int k = 0; k < units; k++) {
            const vec3 lo = vec3_add(at, uniform_vec(vec3_make(-2, 0, -2), vec3_make(2, 3, 2)));
            add_box(&list, lo, vec3_add(lo, uniform_vec(vec3_make((real)0.1, (real)0.1, (real)0.1), vec3_make(1, 1, 1))),
                    source++);
            surface_list_add_sphere(&list, (sphere){vec3_add(lo, vec3_make(0, 1, 0)), uniform((real)0.1, (real)0.5)},
                                    0, source++);
            const vec3 a = vec3_add(lo, vec3_make(1, 0, 1));
            surface_list_add_triangle(&list, (triangle){a, vec3_add(a, random_direction()), vec3_add(a, random_direction())},
                                      0, source++);
        }
        fast_grid_options opt = fast_grid_default_options();
        if (scene == 1) {
            opt.split = 4;
            opt.normals = true;
        } else if (scene == 3) {
            opt = (fast_grid_options){2, 1L << 20, false, false, false, 0, 0, false, false, 0};
        }
        const long n = 200;
        ray_set rays = rays_alloc(n);
        for (long k = 0; k < n; k++) {
            const vec3 p = vec3_add(at, vec3_scale(random_direction(), 20));
            set_ray(&rays, k, p, vec3_sub(vec3_add(at, uniform_vec(vec3_make(-2, 0, -2), vec3_make(3, 4, 3))), p));
        }
        long failed = 0;
        for (long fail_at = 1;; fail_at++) {
            fast_grid g;
            char err[256] = "";
            alloc_calls = 0;
            alloc_fail_at = fail_at;
            const int status = fast_grid_build(&g, &list, opt, err, sizeof err);
            const bool faulted = alloc_calls >= fail_at;
            alloc_fail_at = 0;
            if (status != 0) {
                if (!faulted || !strstr(err, "out of memory"))
                    fail_msg("scene %d, allocation %ld of the build failing: \"%s\"", scene, fail_at, err);
                failed++;
                continue;
            }
            for (long k = 0; k < n; k++) {
                hit_record a = {0}, b = {0};
                const bool fa = surfaces_intersect(&list, rays.r[k], 0, REAL_INFINITY, &a);
                const bool fb = fast_grid_intersect(&g, rays.r[k], 0, REAL_INFINITY, &b);
                if (!same_hit(fa, &a, fb, &b))
                    fail_msg("scene %d, allocation %ld of the build failing: the build succeeded, and ray %ld hits "
                             "surface %d (grid) where the linear scan hits %d",
                             scene, fail_at, k, fb ? b.surface : -1, fa ? a.surface : -1);
            }
            fast_grid_free(&g);
            if (!faulted)
                break; /* the build made fewer than fail_at allocations: every one has failed once */
        }
        if (failed < 3)
            fail_msg("scene %d: only %ld builds failed (every allocation failed in turn)", scene, failed);
        rays_free(&rays);
        surface_list_free(&list);
    }
}

/* The fast grid's cell range (the build runs it for every surface, its ceil,
 * floor and clamps written out) gives the lesson's grid_cell_range's answers:
 * boxes inside, across and beyond a grid far from the origin, with sides on
 * cell boundaries exactly, a side NaN or infinite, at three scales. */
static void test_cell_range_as_the_lesson(void **state)
{
    (void)state;
    rng_state = 37;
    const real scales[] = {(real)1e-5, 1, (real)1e5};
    for (size_t sc = 0; sc < sizeof scales / sizeof scales[0]; sc++)
        for (int trial = 0; trial < 20; trial++) {
            const real unit = scales[sc] * uniform((real)0.5, 2);
            fast_grid g = {.n = {1 + trial % 7, 1 + trial % 3 * 20, 1 + trial}};
            g.lo = vec3_scale(uniform_vec(vec3_make(-900, -900, -900), vec3_make(900, 900, 900)), unit);
            g.cell = vec3_scale(uniform_vec(vec3_make((real)0.1, (real)0.1, (real)0.1), vec3_make(3, 3, 3)), unit);
            g.hi = vec3_make(g.lo.x + (real)g.n[0] * g.cell.x, g.lo.y + (real)g.n[1] * g.cell.y, g.lo.z + (real)g.n[2] * g.cell.z);
            const grid lesson = {.lo = g.lo, .hi = g.hi, .cell = g.cell, .n = {g.n[0], g.n[1], g.n[2]}};
            for (int k = 0; k < 500; k++) {
                real side[2][3];
                for (int end = 0; end < 2; end++)
                    for (int a = 0; a < 3; a++) {
                        const real lo_a = a == 0 ? g.lo.x : a == 1 ? g.lo.y : g.lo.z;
                        const real cell_a = a == 0 ? g.cell.x : a == 1 ? g.cell.y : g.cell.z;
                        const int pick = (int)(next_u64() % 8);
                        /* a boundary exactly (as the lesson computes it), anywhere around the grid, far beyond */
                        side[end][a] = pick < 3   ? lo_a + (real)(int)(next_u64() % (uint64_t)(g.n[a] + 3) - 1) * cell_a
                                       : pick < 6 ? lo_a + uniform(-2, (real)g.n[a] + 2) * cell_a
                                       : pick == 6 ? (next_u64() % 2 ? REAL_INFINITY : -REAL_INFINITY)
                                                   : (next_u64() % 4 ? lo_a - 1e6 * cell_a : (real)NAN);
                    }
                const vec3 lo = vec3_make(side[0][0], side[0][1], side[0][2]), hi = vec3_make(side[1][0], side[1][1], side[1][2]);
                int first[3], last[3], want_first[3], want_last[3];
                fast_grid_cell_range(&g, lo, hi, first, last);
                grid_cell_range(&lesson, lo, hi, want_first, want_last);
                for (int a = 0; a < 3; a++)
                    if (first[a] != want_first[a] || last[a] != want_last[a])
                        fail_msg("axis %d of a grid of %d cells: the box %.17g .. %.17g gives cells %d .. %d, the "
                                 "lesson's %d .. %d",
                                 a, g.n[a], (double)side[0][a], (double)side[1][a], first[a], last[a], want_first[a],
                                 want_last[a]);
            }
        }
}

static const graded_test tests[] = {
    GRADED(test_random_scenes, 0),
    GRADED(test_zero_components, 0),
    GRADED(test_origins_on_the_grid, 0),
    GRADED(test_flat_scenes, 0),
    GRADED(test_huge_among_tiny, 0),
    GRADED(test_start_inside_spanning_cells, 0),
    GRADED(test_ties_first_in_list, 0),
    GRADED(test_empty_and_single, 0),
    GRADED(test_mailbox_counts, 0),
    GRADED(test_next_above, 0),
    GRADED(test_empty_cubes, 0),
    GRADED(test_prefetch_by_size, 0),
    GRADED(test_closest_without_record, 0),
    GRADED(test_boxes_as_boxes, 0),
    GRADED(test_few_surfaces_as_a_list, 0),
    GRADED(test_large_surfaces_apart, 0),
    GRADED(test_cell_range_as_the_lesson, 0),
    GRADED(test_touching_spheres_from_far, 0),
    GRADED(test_out_of_memory, 0),
    GRADED(test_directions_of_any_length, 0),
    GRADED(test_rays_not_finite, 0),
    GRADED(test_cornell_scenes, 0),
    GRADED(test_builtin_scenes_as_chapter_10, 0),
};

SUITE_MAIN("11_grid lab", tests)
