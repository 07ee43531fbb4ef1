/* test_11_grid.c - chapter 11: the uniform grid and its 3D-DDA.
 *
 * The lesson's grid against the cases where grids break (grid_cases.h: the
 * linear scan's answer, bit for bit, on random scenes and at the extremes,
 * the course's scenes and the built-in scenes), and the exercises' own
 * tests: the resolution, the cell ranges, the cells a ray visits and the
 * stop rule, against numbers computed another way.
 */
#include "11_grid/grid.h"
#include "11_grid/renderer/grid_stage.h"

#define GRID grid
#define GRID_OPTIONS grid_options
#define GRID_BUILD grid_build
#define GRID_INTERSECT grid_intersect
#define GRID_FREE grid_free
#define GRID_DEFAULTS grid_default_options
#define GRID_QUERY grid_query
#define GRID_QUERY_KNOBS (&grid_defaults)
/* a few densities, and a cap that makes the cells few and large */
static const grid_options knob_sets[] = {{0.3, 1L << 20}, {2, 1L << 20}, {10, 1L << 20}, {2, 64}};
#define N_KNOB_SETS (sizeof knob_sets / sizeof knob_sets[0])

static const grid_knobs grid_defaults = GRID_KNOBS_DEFAULT; /* chapter 11's renderer's */

#include "grid_cases.h"

/* What a query found, for a message: "surface K at t = T", or "no hit". */
static const char *found_what(bool found, const hit_record *hit)
{
    return found ? describe("surface %d at t = %.17g", hit->surface, (double)hit->t) : "no hit";
}

/* The march of r through g, which passes every surface (`what` says where),
 * finds nothing; the cells visited and the tests made are added to *counts. */
static void expect_no_hit(const grid *g, ray r, const char *what, grid_counts *counts)
{
    hit_record hit;
    const bool found = grid_intersect_counted(g, r, 0, REAL_INFINITY, &hit, counts);
    assert_true_why(
        !found,
        "grid_intersect_counted(ray from (%.17g, %.17g, %.17g) along (%.17g, %.17g, %.17g), %s, passing every "
        "surface)\n    expected no hit\n    got      %s\n    likely mistake: the march keeps only what "
        "surface_intersect finds in the window (test_surface, given), and no exercise changes that: a hit on a "
        "ray that passes every surface means the given part of grid_march.c was changed (README, \"The same "
        "answer as the linear scan\")",
        (double)r.p.x, (double)r.p.y, (double)r.p.z, (double)r.d.x, (double)r.d.y, (double)r.d.z, what,
        found_what(found, &hit));
}

/* The counts of a grid the test relies on (`holds`: they are as `expected`
 * says) for the surfaces `build` describes; a failure names grid_resolution. */
static void expect_counts(const grid *g, bool holds, const char *build, const char *expected)
{
    assert_true_why(
        holds,
        "grid_build(%s)\n    expected %s\n    got      %d x %d x %d cells\n    likely mistake: grid_resolution: "
        "s = (min(lambda N, C) / product of the spanned extents)^(1/k), n_a = max(round(e_a s), 1), a flat "
        "axis 1 (README, \"The grid's box and resolution\"; test_resolution names its mistakes)",
        build, expected, g->n[0], g->n[1], g->n[2]);
}

/* Along axis a, the grid *got (built from the surfaces `build` describes)
 * has the cells of one built before from the same box and number of
 * surfaces: n of size cell from lo. */
static void expect_same_cells(const grid *got, int a, long n, real lo, real cell, const char *build)
{
    assert_true_why(
        got->n[a] == n && vec3_axis(got->lo, a) == lo && vec3_axis(got->cell, a) == cell,
        "grid_build(%s), along %c\n    expected the cells of a grid built before from the same box and number "
        "of surfaces: %ld from %.17g, each %.17g\n    got      %d from %.17g, each %.17g\n    likely mistake: "
        "grid_resolution gave other counts for the same extents, number of surfaces, density and cap: the "
        "counts depend on those alone (nothing read from n[] before it is written, nothing kept from an "
        "earlier call; README, \"The grid's box and resolution\")",
        build, "xyz"[a], n, (double)lo, (double)cell, got -> n[a], (double)vec3_axis(got->lo, a),
        (double)vec3_axis(got->cell, a));
}

/* ---- the knobs ------------------------------------------------------------------------- */

/* The counts a resolution rule gives when the cap does not bind: `cells` cells
 * over the spanned axes' product of extents relative to the largest, s = (cells / volume)^(1/root) (or its inverse,
 * or the root of the cells alone over the volume), each spanned axis
 * rounded by `rnd` (at least 1 when `at_least_one`), clamped to 2^20. */
typedef enum { S_RIGHT, S_INVERSE, S_ROOT_OF_CELLS } s_form;
static void resolution_as(const double extent[3], double cells, int root, s_form form, double (*rnd)(double),
                          bool at_least_one, int n[3])
{
    const double largest = fmax(fmax(extent[0], extent[1]), extent[2]);
    double volume = 1, e[3]; /* the extents relative to the largest, as the README computes s */
    int spanned = 0;
    for (int a = 0; a < 3; a++) {
        e[a] = extent[a] > 0 ? extent[a] / largest : 0;
        if (extent[a] > 0)
            volume *= e[a], spanned++;
    }
    const double k = root ? root : spanned;
    const double s = form == S_INVERSE ? pow(volume / cells, 1 / k)
                     : form == S_ROOT_OF_CELLS ? pow(cells, 1 / k) / volume
                                               : pow(cells / volume, 1 / k);
    for (int a = 0; a < 3; a++)
        n[a] = extent[a] > 0 ? (int)fmin(at_least_one ? fmax(rnd(e[a] * s), 1) : rnd(e[a] * s), 1 << 20) : 1;
}

/* grid_resolution(extent, surfaces, density, cap) is want[] (a case where the
 * cap does not bind: the README's formula gives it exactly); a failure names
 * the mistake whose counts were got. */
static void expect_resolution(const double extent[3], long surfaces, double density, long cap, const int want[3])
{
    int n[3];
    grid_resolution(extent, surfaces, density, cap, n);
    if (n[0] == want[0] && n[1] == want[1] && n[2] == want[2])
        return;
    const double lambda_n = density * (double)surfaces, first = fmax(lambda_n, 1); /* step 1: at least 1 */
    const struct {
        double cells;
        int root;
        s_form form;
        double (*rnd)(double);
        bool at_least_one;
        const char *why;
    } mistakes[] = {
        {(double)surfaces, 0, S_RIGHT, round, true, "the density left out: about lambda N cells, the density times the "
                                                    "number of surfaces"},
        {density, 0, S_RIGHT, round, true, "the number of surfaces left out: about lambda N cells, the density times "
                                           "the number of surfaces"},
        {first, 0, S_RIGHT, floor, true, "n_a = floor(e_a s): the counts are rounded to the nearest, round(e_a s)"},
        {first, 0, S_RIGHT, ceil, true, "n_a = ceil(e_a s): the counts are rounded to the nearest, round(e_a s)"},
        {first, 0, S_RIGHT, round, false, "an axis whose e_a s rounds to 0 still gets one cell: n_a = max(round(e_a "
                                             "s), 1)"},
        {first, 3, S_RIGHT, round, true, "the cube root for a flat scene: with k spanned axes (extent above 0) s "
                                            "is the k-th root, here the square root, not the cube root"},
        {first, 0, S_INVERSE, round, true, "s upside down: s = (lambda N / (e_x e_y e_z))^(1/k) cells per unit of "
                                              "length, the cells over the volume"},
        {first, 0, S_ROOT_OF_CELLS, round, true, "s = (lambda N)^(1/k) / (e_x e_y e_z): the root is of the cells "
                                                    "over the volume, s = (lambda N / (e_x e_y e_z))^(1/k)"},
        {lambda_n, 0, S_RIGHT, round, true, "lambda N below 1 taken as it is: the first try is s for max(lambda N, 1) "
                                            "cells, at least one (README, \"The grid's box and resolution\", step 1)"},
        {fmax(trunc(density) * (double)surfaces, 1), 0, S_RIGHT, round, true,
         "the density cut to an integer: lambda is any real above 0, lambda N cells (README, \"Knobs\")"},
        {fmax(trunc(lambda_n), 1), 0, S_RIGHT, round, true,
         "lambda N cut to an integer (the cells wanted held in an integer type): the first try is s for lambda N "
         "cells, any real (README, \"The grid's box and resolution\", step 1)"},
        {fmax(round(density) * (double)surfaces, 1), 0, S_RIGHT, round, true,
         "the density rounded to an integer: lambda is any real above 0, lambda N cells (README, \"Knobs\")"},
    };
    const char *why = "s = (min(lambda N, cap) / product of the spanned extents)^(1/k) with k spanned axes, n_a = "
                      "max(round(e_a s), 1), a flat axis 1";
    if ((double)n[0] * n[1] * n[2] > 1e3 * lambda_n)
        why = "far more cells than lambda N: the product of extents is over the spanned axes only (a flat axis's "
              "zero extent makes s infinite)";
    for (int a = 0; a < 3; a++) {
        if (n[a] > 1 << 20)
            why = "an axis over 2^20 cells: n_a = min(max(round(e_a s), 1), 2^20), an int however large s is";
        if (extent[a] == 0 && n[a] == 0)
            why = "a flat axis without cells: an axis of zero extent gets one cell (n_a = 1), else the grid has none";
    }
    bool named = false;
    for (size_t k = 0; k < sizeof mistakes / sizeof mistakes[0]; k++) {
        int m[3];
        resolution_as(extent, mistakes[k].cells, mistakes[k].root, mistakes[k].form, mistakes[k].rnd,
                      mistakes[k].at_least_one, m);
        if (m[0] == n[0] && m[1] == n[1] && m[2] == n[2]) {
            why = named ? describe("%s\n    or, the same numbers: %s", why, mistakes[k].why) : mistakes[k].why;
            named = true;
        }
    }
    fail_msg("grid_resolution(extent %g x %g x %g, %ld surfaces, density %g, cap %ld)\n    expected %d x %d x %d "
             "cells\n    got      %d x %d x %d\n    likely mistake: %s",
             extent[0], extent[1], extent[2], surfaces, density, cap, want[0], want[1], want[2], n[0], n[1], n[2], why);
}

/* grid_resolution(box, surfaces, density, cap) must give exactly `want` (`why`, in the message); a product
 * above the cap names `over_cap` as the likely mistake, any other count `otherwise`. */
static void expect_cells(const double box[3], long surfaces, double density, long cap, const int want[3],
                         const char *why, const char *over_cap, const char *otherwise)
{
    int n[3];
    grid_resolution(box, surfaces, density, cap, n);
    if (n[0] != want[0] || n[1] != want[1] || n[2] != want[2])
        fail_msg("grid_resolution(extent %g x %g x %g, %ld surfaces, density %g, cap %ld)\n    expected %d x %d x %d "
                 "cells (%s)\n    got      %d x %d x %d\n    likely mistake: %s",
                 box[0], box[1], box[2], surfaces, density, cap, want[0], want[1], want[2], why, n[0], n[1], n[2],
                 (double)n[0] * n[1] * n[2] > (double)cap ? over_cap : otherwise);
}

/* The cap, on a box 8 x 2 x 4 (volume 64) with 1000 surfaces at density 8.
 * Capped at 1000 the first try fits: s0 = (1000 / 64)^(1/3) = 2.5 gives
 * exactly 20 x 5 x 10.  Capped at 990, s0 = 2.4915 gives 20 x 5 x 10 too,
 * 1000 cells, above the cap: s shrinks.  The counts jump where e_a s is a
 * half: x at 19.5 / 8 = 2.4375, z at 9.5 / 4 = 2.375, y at 4.5 / 2 = 2.25,
 * so the s that fit are those below s_fit = 2.4375 (19 x 5 x 10, 950 cells).
 * A shrink by a factor from 0.9 to 1 a try (README) ends at s from 0.9 s_fit
 * = 2.19375 (18 x 4 x 9) up to s_fit: n_x 18 .. 20, n_y 4 .. 5, n_z 9 .. 10,
 * and at most 990 cells (grid_resolution_range.h says why). */
static void expect_capped_resolution(void)
{
    const double box[3] = {8, 2, 4};
    int n[3];
    grid_resolution(box, 1000, 8, 1000, n);
    if (n[0] != 20 || n[1] != 5 || n[2] != 10)
        fail_msg("grid_resolution(extent 8 x 2 x 4, 1000 surfaces, density 8, cap 1000)\n    expected 20 x 5 x 10 "
                 "cells\n    got      %d x %d x %d\n    likely mistake: %s",
                 n[0], n[1], n[2],
                 (double)n[0] * n[1] * n[2] > 1000 ? "the cap: while n_x n_y n_z is above it, shrink s and round again"
                 : (double)n[0] * n[1] * n[2] < 1000 && n[0] >= 18 && n[1] >= 4 && n[2] >= 9
                     ? "a product equal to the cap shrunk: the cap allows n_x n_y n_z = C, so shrink only while the "
                       "product is above it (> C, not >= C)"
                 : "s = (min(lambda N, cap) / (e_x e_y e_z))^(1/3) cells per unit, n_a = round(e_a s), and the "
                   "first try fits here");
    /* lambda N = 5000 over the cap 4096: the first try is s for the cap's 4096 cells, (4096 / 64)^(1/3) = 4,
     * and 32 x 8 x 16 = 4096 fits at once.  A first try for lambda N = 5000 cells, s = 4.27, gives 34 x 9 x
     * 17 = 5202, and one shrink by 0.99 (4096 / 5202)^(1/3) = 0.914 lands below: 31 x 8 x 16. */
    expect_cells(box, 1000, 5, 4096, (const int[3]){32, 8, 16}, "s = (4096 / 64)^(1/3) = 4: the first try fits",
                 "the cap: while n_x n_y n_z is above it, shrink s and round again",
                 "the first try's s from lambda N cells, above the cap: it is s for min(lambda N, C) cells, here the "
                 "cap's 4096, which fit at once (or a product equal to the cap shrunk: > C, not >= C)");
    grid_resolution(box, 1000, 8, 990, n);
    const int lowest[3] = {18, 4, 9}, highest[3] = {20, 5, 10};
    const double cells = (double)n[0] * n[1] * n[2];
    bool inside = cells <= 990;
    for (int a = 0; a < 3; a++)
        inside = inside && n[a] >= lowest[a] && n[a] <= highest[a];
    if (!inside)
        fail_msg("grid_resolution(extent 8 x 2 x 4, 1000 surfaces, density 8, cap 990)\n    expected 18 .. 20 x 4 .. 5 "
                 "x 9 .. 10 cells, at most 990 (the reference: 19 x 5 x 10)\n    got      %d x %d x %d = %.0f\n    "
                 "likely mistake: %s",
                 n[0], n[1], n[2], cells,
                 cells > 990 ? "the cap: while n_x n_y n_z is above it, shrink s and round again (20 x 5 x 10 rounds "
                               "past it)"
                 : n[0] < lowest[0] || n[1] < lowest[1] || n[2] < lowest[2]
                     ? "s shrinks by a tenth at most a try (a factor from 0.9 to 1), from the s of min(lambda N, cap) "
                       "cells"
                     : "one s for every axis, n_a = round(e_a s): the cells stay cubic");
    /* Many shrinks: a box 8 x 4 x 0.01 capped at 3 (1000 surfaces, density 1).  The first try, s0 = (3 / (1 x 0.5 x
     * 0.00125))^(1/3) = 16.87 cells per e_max, gives 17 x 8 x 1 = 136 (z's 0.02 raised to one cell).  The product
     * is 1 below s = 1.5, 2 x 1 x 1 from there, 3 x 1 x 1 from 2.5 and 3 x 2 x 1 = 6 from 3: every try before the
     * last had s >= 3, the last is below 3 and at least 0.9 of the one before, so 2.7 <= s < 3: 3 x 1 x 1, some
     * fifteen tries from s0 whatever the factors from 0.9 to 1.  One shrink by 0.99 (3 / 136)^(1/3) = 0.28 and two
     * more of its kind land at s = 2.44, 2 x 1 x 1; a loop that gives up after a few tries stays above the cap. */
    expect_cells((const double[3]){8, 4, 0.01}, 1000, 1, 3, (const int[3]){3, 1, 1},
                 "the first try 17 x 8 x 1, then some fifteen shrinks",
                 "the cap: while n_x n_y n_z is above it, shrink s and round again, as many times as it takes",
                 "s shrinks by a tenth at most a try (a factor from 0.9 to 1): a larger shrink jumps past the counts "
                 "that fit");
}

/* The resolution follows the density and the box's shape, within the cap. */
static void test_resolution(void **state)
{
    (void)state;
    /* 8000 cells for a box 8 x 2 x 4 (volume 64): s = 125^(1/3) = 5 cells per unit, 40 x 10 x 20 */
    expect_resolution((const double[3]){8, 2, 4}, 1000, 8, 1L << 20, (const int[3]){40, 10, 20});
    /* A density need not be an integer: 2.5 per surface, 2500 cells, s = (2500 / 64)^(1/3) = 3.393 cells per
     * unit, n = round of 27.14, 6.79 and 13.57 (2 or 3 per surface would give 25 x 6 x 13 or 29 x 7 x 14) */
    expect_resolution((const double[3]){8, 2, 4}, 1000, 2.5, 1L << 20, (const int[3]){27, 7, 14});
    /* Nor need lambda N be one: 3 surfaces at 1.9 want 5.7 cells, s = (5.7 / 64)^(1/3) = 0.4465 cells per unit,
     * n = round of 3.572, 0.893 and 1.786: 4 x 1 x 2 (lambda N cut to 5 cells: s = 0.4275, 3 x 1 x 2) */
    expect_resolution((const double[3]){8, 2, 4}, 3, 1.9, 1L << 20, (const int[3]){4, 1, 2});
    /* The same box 2^1000 and 2^-990 times as large: its extents relative to the largest are again exactly 1,
     * 1/4 and 1/2, and so are the counts.  The extents' own product, 2^3006 or 2^-2964, overflows to infinity
     * (s = 0: one cell an axis) or underflows to 0 (s infinite, held at 1e300: counts set by that bound). */
    for (int k = 0; k < 2; k++) {
        const double scale = k ? 0x1p1000 : 0x1p-990, box[3] = {8 * scale, 2 * scale, 4 * scale};
        int n[3];
        grid_resolution(box, 1000, 8, 1L << 20, n);
        if (n[0] != 40 || n[1] != 10 || n[2] != 20)
            fail_msg("grid_resolution(extent %g x %g x %g, 1000 surfaces, density 8, cap 2^20: the box above, "
                     "%s)\n    expected 40 x 10 x 20 cells\n    got      %d x %d x %d\n    likely mistake: %s",
                     box[0], box[1], box[2], k ? "2^1000 times as large" : "2^-990 times as large", n[0], n[1], n[2],
                     "s from the product of the extents themselves, which overflows to infinity at this scale "
                     "(s = 0) or underflows to 0 (s infinite): the counts of a box do not depend on its size; take "
                     "the extents relative to the largest, e_a / e_max (README, \"The grid's box and resolution\", "
                     "step 1)");
    }
    /* flat in y: x and z share 1024 cells, s = (1024 / 32)^(1/2) = sqrt 32 = 5.657: round(45.25) = 45 and
     * round(22.63) = 23 */
    expect_resolution((const double[3]){8, 0, 4}, 512, 2, 1L << 20, (const int[3]){45, 1, 23});
    /* flat in x and y, a line along z: k = 1, s = 100 cells per e_max = e_z, 1 x 1 x 100.  e_max is the largest
     * of all three extents: taken over two axes it is 0 here, and e_z / 0 is infinite */
    {
        int line[3];
        grid_resolution((const double[3]){0, 0, 8}, 100, 1, 1L << 20, line);
        if (line[0] != 1 || line[1] != 1 || line[2] != 100)
            fail_msg("grid_resolution(extent 0 x 0 x 8, 100 surfaces, density 1, cap 2^20: a line along z)\n"
                     "    expected 1 x 1 x 100 cells\n    got      %d x %d x %d\n    likely mistake: %s",
                     line[0], line[1], line[2],
                     line[2] == 1 ? "e_max, the largest extent, taken over two axes only: it is the largest of all "
                                    "three (here z's, the one axis above 0)"
                                  : "one spanned axis: s = min(lambda N, cap) / (e_z / e_max), n_z = round(e_z s)");
    }
    /* thin in y: s = (8000 / 0.32)^(1/3) = 29.24, e_y s = 0.29 rounds to 0, yet y is spanned: one cell;
     * round(233.92) = 234, round(116.96) = 117 */
    expect_resolution((const double[3]){8, 0.01, 4}, 1000, 8, 1L << 20, (const int[3]){234, 1, 117});
    /* a thin line: s = (10^6 / 10^-18)^(1/3) = 10^8 cells per unit; x is held at 2^20 cells, y and z round
     * 0.1 to 0 and get one each: 2^20 cells, within the cap 2^24, so no shrinking */
    expect_resolution((const double[3]){1, 1e-9, 1e-9}, 500000, 2, 1L << 24, (const int[3]){1 << 20, 1, 1});
    /* lambda N = 0.05 x 2 = 0.1, below 1: the first try is s for max(0.1, 1) = 1 cell over the volume 8,
     * s = (1 / 8)^(1/3) = 0.5 (to a rounding), round(4) = 4 and round(0.5) = 0 or 1 (either way one cell);
     * s for 0.1 cells, 0.232, would give round(1.86) = 2 */
    expect_resolution((const double[3]){8, 1, 1}, 2, 0.05, 1L << 20, (const int[3]){4, 1, 1});
    /* A scene shrunk by 1e-300 (tests/extremes/tiny-scale.xml): the product of its extents, 8e-900, underflows
     * to 0 and lambda N over it is infinite.  Whatever finite s the first try settles for, every count is
     * round(2e-300 s) held to 1 .. 2^20 and the cap is then met in finitely many shrinks; an s left infinite
     * holds every axis at 2^20 cells, 2^60 in all, above the cap after every shrink (infinity times 0.9 is
     * infinity): grid_resolution never returns, and the test ends only by the grader's timeout. */
    int tiny[3] = {0, 0, 0};
    grid_resolution((const double[3]){2e-300, 2e-300, 2e-300}, 1000, 8, 1L << 20, tiny);
    const double tiny_cells = (double)tiny[0] * tiny[1] * tiny[2];
    assert_true_why(tiny[0] >= 1 && tiny[1] >= 1 && tiny[2] >= 1 && tiny[0] <= 1 << 20 && tiny[1] <= 1 << 20 &&
                        tiny[2] <= 1 << 20 && tiny_cells <= (double)(1L << 20),
                    "grid_resolution(extent 2e-300 x 2e-300 x 2e-300, 1000 surfaces, density 8, cap 2^20: the "
                    "extents' product underflows to 0)\n    expected 1 to 2^20 cells an axis, at most 2^20 in all\n"
                    "    got      %d x %d x %d\n    likely mistake: s infinite (cells over a volume of 0) is held to "
                    "a finite bound, as n_a is held to 1 .. 2^20: an infinite s gives no counts",
                    tiny[0], tiny[1], tiny[2]);
    rng_state = 18;
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_CRAMER);
    /* 1000 tiny spheres in a box 8 x 2 x 4 (plus their radius 0.01) */
    for (int k = 0; k < 1000; k++)
        surface_list_add_sphere(&list, (sphere){uniform_vec(vec3_make(-4, 3, 0), vec3_make(4, 5, 4)), (real)0.01},
                                0, k);
    grid g;
    grid_options opt = {.density = 8, .max_cells = 1L << 20};
    build_grid(&g, &list, opt);
    /* 8000 cells for a box of volume ~64: s = 5 cells per unit: 40 x 10 x 20 */
    assert_int_equal(40, g.n[0]);
    assert_int_equal(10, g.n[1]);
    assert_int_equal(20, g.n[2]);
    assert_int_equal(8000, g.n_cells);
    /* every sphere lies in 1 to 8 cells */
    assert_true_why(
        g.n_refs >= 1000 && g.n_refs <= 8000,
        "grid_build(1000 spheres of radius 0.01 in a box 8 x 2 x 4, density 8: 40 x 10 x 20 cells of about 0.2)\n"
        "    expected 1000 to 8000 cell entries (every sphere lies in 1 to 8 cells)\n    got      %ld\n"
        "    likely mistake: %s",
        g.n_refs,
        g.n_refs < 1000 ? "a sphere listed in no cell: grid_cell_range gives cells first = ceil(f_lo) - 1 to "
                          "last = floor(f_hi) (README, \"Listing the surfaces\"; test_cell_range names its "
                          "mistakes)"
                        : "a sphere listed in cells its box does not overlap: first = ceil(f_lo) - 1, last = "
                          "floor(f_hi), no cell more on either side (README, \"Listing the surfaces\"; "
                          "test_cell_range names its mistakes)");
    assert_true(grid_memory(&g) >= (size_t)(g.n_cells + 1 + g.n_refs) * 4);
    grid_free(&g);
    surface_list_free(&list);
    expect_capped_resolution();
    /* A flat scene: 32 x 16 small triangles in the plane y = 3.25, x from 0
     * to 8 and z from 0 to 4 (exact in binary).  y has no extent: one cell,
     * and x and z share 2 x 512 cells, s = (1024 / (8 x 4))^(1/2) = sqrt 32:
     * n_x = round(8 s) = 45, n_z = round(4 s) = 23. */
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_CRAMER);
    for (int i = 0; i < 32; i++)
        for (int j = 0; j < 16; j++) {
            const real x = (real)i * (real)0.25, z = (real)j * (real)0.25, y = (real)3.25;
            surface_list_add_triangle(&list, (triangle){{x, y, z}, {x + (real)0.25, y, z}, {x, y, z + (real)0.25}}, 0,
                                      16 * i + j);
        }
    build_grid(&g, &list, (grid_options){.density = 2, .max_cells = 1L << 20});
    if (g.n[0] != 45 || g.n[1] != 1 || g.n[2] != 23)
        fail_msg("grid_resolution of a flat scene (512 triangles at y = 3.25 over 8 x 4, density 2)\n"
                 "    expected 45 x 1 x 23 cells\n    got      %d x %d x %d\n    likely mistake: %s",
                 g.n[0], g.n[1], g.n[2],
                 g.n[1] != 1 ? "an axis of zero extent gets one cell"
                             : "the cells per unit s is the root of degree (number of spanned axes): here the square "
                               "root of lambda N / (e_x e_z), not the cube root");
    grid_free(&g);
    opt.density = 0;
    char err[256];
    assert_int_equal(-1, grid_build(&g, &list, opt, err, sizeof err));
    assert_non_null(strstr(err, "density"));
    surface_list_free(&list);
}

/* The march tests every surface listed in every cell it visits, and stops
 * only at the grid's end when nothing is hit: a long thin triangle lying
 * along a row of cells, which the ray passes without hitting it, is tested
 * in each of the 10 cells, the corner spheres in the end cells. */
/* The march starts where the window does: in the row of 10 cells of
 * test_march_counts, a ray along +x from x = 5.5 (inside the grid, in cell
 * 5) and a ray from x = -1 with the window (6.5, infinity), which starts at
 * x = 5.5 too, each visit cells 5 to 9 only, 5 cells.  An entry that takes
 * *t0 from one axis's crossing alone (x's, the first: *t0 = near_x instead
 * of max(*t0, near_x)) starts both marches where the ray's line enters the
 * box, x = lo_x, behind the origin or before t_min: the answer is the same,
 * but every cell before is visited for nothing. */
static void expect_march_from_window_start(const grid *g)
{
    const long first = (long)((5.5 - (double)g->lo.x) / (double)g->cell.x), cells = g->n[0] - first;
    const struct {
        ray r;
        real t_min;
        const char *what;
    } cases[] = {
        {{{(real)5.5, (real)0.6, (real)0.45}, {1, 0, 0}}, 0, "from x = 5.5, inside the grid, along +x"},
        {{{-1, (real)0.6, (real)0.45}, {1, 0, 0}}, (real)6.5, "from x = -1 along +x, the window (6.5, infinity)"},
    };
    for (int k = 0; k < 2; k++) {
        grid_counts counts = {0, 0};
        hit_record hit;
        const bool found = grid_intersect_counted(g, cases[k].r, cases[k].t_min, REAL_INFINITY, &hit, &counts);
        if (found || counts.cells != (uint64_t)cells)
            fail_msg("grid_intersect_counted(ray %s, through a row of %d cells, missing everything: the window "
                     "starts at x = 5.5, in cell %ld)\n    expected no hit, %ld cells visited (cells %ld to %d)\n"
                     "    got      %s, %llu cells\n    likely mistake: %s",
                     cases[k].what, g->n[0], first, cells, first, g->n[0] - 1, found_what(found, &hit),
                     (unsigned long long)counts.cells,
                     counts.cells > (uint64_t)cells
                         ? "enter: the window narrowed with *t0 = max(*t0, near_a) on every axis, the first too: a "
                           "*t0 taken from one axis's crossing alone starts the march where the ray's line enters "
                           "the box, behind the origin or before t_min, and visits those cells for nothing"
                         : "the march ends before the grid's end with no hit in the window (dda_step, the stop rule)");
    }
}

static void test_march_counts(void **state)
{
    (void)state;
    surface_list list;
    row_of_cells(&list, TRIANGLE_CRAMER, true);
    grid g;
    build_grid(&g, &list, (grid_options){.density = 1.25, .max_cells = 1000});
    assert_int_equal(10, g.n[0]); /* 9 surfaces x 1.25 ~ 11 cells for a box 10 x 1 x 1 */
    assert_int_equal(1, g.n[1]);
    assert_int_equal(1, g.n[2]);
    /* along +x at y = 0.6, z = 0.45: through all 10 cells, missing everything */
    ray r = {{-1, (real)0.6, (real)0.45}, {1, 0, 0}};
    grid_counts counts = {0, 0};
    expect_no_hit(&g, r, "through a row of 10 cells", &counts);
    assert_int_equal(10, counts.cells);
    assert_int_equal(10 + 8, counts.tests); /* the sliver in all 10 cells, a sphere at each corner */
    expect_march_from_window_start(&g);
    grid_free(&g);
    surface_list_free(&list);
}

/* ---- the exercises ----------------------------------------------------------------------- */

/* A grid laid out by hand: low corner (-1, 2, 0.5), cells 0.25 x 0.5 x 1
 * (exact in binary), 8 x 4 x 3 cells. */
static grid hand_grid(void)
{
    grid g = {.lo = {-1, 2, (real)0.5}, .cell = {(real)0.25, (real)0.5, 1}, .n = {8, 4, 3}};
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
               cell[3] = {g->cell.x, g->cell.y, g->cell.z};
    for (int a = 0; a < 3; a++) {
        const int n = g->n[a];
        const real f_lo = (l[a] - o[a]) / cell[a], f_hi = (u[a] - o[a]) / cell[a];
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
        const real f_lo_x = (l[a] - o[0]) / cell[0], f_hi_x = (u[a] - o[0]) / cell[0];
        const real f_lo_xc = (l[a] - o[a]) / cell[0], f_hi_xc = (u[a] - o[a]) / cell[0]; /* x's cell size only */
        const real f_lo_0 = l[a] / cell[a], f_hi_0 = u[a] / cell[a];                     /* from the origin */
        const real f_lo_times = (l[a] - o[a]) * cell[a], f_hi_times = (u[a] - o[a]) * cell[a];
        const real f_hi_hi = (u[a] - vec3_axis(g->hi, a)) / cell[a]; /* from the grid's high corner */
        const struct {
            double first, last;
            const char *why;
        } mistakes[] = {
            {clamp_cell(floor(F), 0, n), right_last, "first = floor(f_lo): a box whose low side lies on a cell boundary "
                                                     "(f_lo whole) touches the cell below too (so does a truncated "
                                                     "f_lo): first = ceil(f_lo) - 1"},
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
             "the x axis's cell size or origin used for another axis: this axis's lo_a and cell_a"},
            {clamp_cell(ceil((double)f_lo_xc) - 1, 0, n), clamp_cell(floor((double)f_hi_xc), -1, n - 1),
             "the x axis's cell size used for another axis: f = (x - lo_a) / cell_a with this axis's cell_a"},
            {right_first, clamp_cell(ceil(L), -1, n - 1), "last = ceil(f_hi): that is the cell after the box when "
                                                          "f_hi is not whole; last = floor(f_hi)"},
            {clamp_cell(floor(F), 0, n), clamp_cell(ceil(L), -1, n - 1),
             "first = floor(f_lo), last = ceil(f_hi): ceil(f_hi) is the cell after the box when f_hi is not whole; "
             "first = ceil(f_lo) - 1, last = floor(f_hi)"},
            {right_first, clamp_cell(floor(F), -1, n - 1), "f_hi computed from box_lo: the last cell is floor(f_hi) "
                                                           "with f_hi = (box_hi_a - lo_a) / cell_a"},
            {clamp_cell(ceil((double)f_lo_0) - 1, 0, n), clamp_cell(floor((double)f_hi_0), -1, n - 1),
             "f counted from the origin: f = (x - lo_a) / cell_a counts cells from the grid's low corner lo_a"},
            {clamp_cell(ceil((double)f_lo_times) - 1, 0, n), clamp_cell(floor((double)f_hi_times), -1, n - 1),
             "f = (x - lo_a) cell_a: divide by the cell's size, f = (x - lo_a) / cell_a, to count cells"},
            {right_first, clamp_cell(floor((double)f_hi_hi), -1, n - 1),
             "f_hi counted from the grid's high corner: f_lo and f_hi both count from lo_a, f_hi = (box_hi_a - lo_a) "
             "/ cell_a"},
            {a ? clamp_cell(ceil(F) - 1, 0, g->n[0]) : NAN, right_last,
             "first clamped to the x axis's count of cells: each axis a to its own, 0 .. n_a"},
            {a ? clamp_cell(ceil(F) - 1, 0, g->n[0]) : NAN, a ? clamp_cell(floor(L), -1, g->n[0] - 1) : NAN,
             "clamped to the x axis's count of cells: each axis a to its own, first to 0 .. n_a, last to -1 .. "
             "n_a - 1"},
        };
        /* beyond an int's range the likely mistake is the conversion, whatever else the result looks like */
        const bool beyond_int = fabs(F) > 2147483647.0 || fabs(L) > 2147483647.0;
        const char *why = beyond_int ? "f_lo or f_hi converted to int before it was clamped: beyond an int's range "
                                       "the conversion is undefined (x86-64 gives INT_MIN); clamp the real value "
                                       "with real_to_index (common/box.h), then convert"
                                     : "first = ceil(f_lo) - 1, last = floor(f_hi), clamped to 0 .. n - 1 (first > "
                                       "last: none)";
        bool named = false;
        for (size_t k = 0; !beyond_int && k < sizeof mistakes / sizeof mistakes[0]; k++)
            if (mistakes[k].first == first[a] && mistakes[k].last == last[a]) {
                why = named ? describe("%s\n    or, the same numbers: %s", why, mistakes[k].why) : mistakes[k].why;
                named = true;
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

/* 2000 random boxes between (-5, 1, 9) and (2, 8, 12), the same ones for every grid, each against expect_range. */
static void expect_random_ranges(const grid *g)
{
    rng_state = 19;
    for (int k = 0; k < 2000; k++) {
        const vec3 box_lo = {-5, 1, 9}, box_hi = {2, 8, 12};
        vec3 a = uniform_vec(box_lo, box_hi), b = uniform_vec(box_lo, box_hi);
        vec3 lo = vec3_make(real_fmin(a.x, b.x), real_fmin(a.y, b.y), real_fmin(a.z, b.z));
        vec3 hi = vec3_make(real_fmax(a.x, b.x), real_fmax(a.y, b.y), real_fmax(a.z, b.z));
        expect_range(g, lo, hi, NULL, NULL);
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
    grid h = {.lo = {(real)-3.7, (real)1.9, (real)10.1}, .n = {13, 7, 11}};
    h.cell = vec3_make((real)0.31, (real)0.77, (real)0.093);
    expect_random_ranges(&h);
    /* The same boxes in a grid with more cells along y and z than along x (7, 11, 13): each axis is clamped
     * to its own count of cells, a box's first cell along z reaches 12. */
    grid h2 = {.lo = h.lo, .n = {7, 11, 13}};
    h2.cell = vec3_make((real)0.93, (real)0.64, (real)0.27);
    expect_random_ranges(&h2);
}

/* The cells a ray through g's box visits when nothing is hit: one more than
 * the cell planes it crosses inside the box.  False when it misses the box,
 * or when a crossing lies within a hair of the box's entry or exit, where it
 * may count either way (such rays are skipped). */
static bool cells_along(const grid *g, ray r, int *cells)
{
    const real lo[3] = {g->lo.x, g->lo.y, g->lo.z}, cell[3] = {g->cell.x, g->cell.y, g->cell.z};
    const real pp[3] = {r.p.x, r.p.y, r.p.z}, dd[3] = {r.d.x, r.d.y, r.d.z};
    real t_in = 0, t_out = REAL_INFINITY;
    for (int a = 0; a < 3; a++) {
        real t0 = (lo[a] - pp[a]) / dd[a], t1 = (lo[a] + (real)g->n[a] * cell[a] - pp[a]) / dd[a];
        t_in = real_fmax(t_in, real_fmin(t0, t1));
        t_out = real_fmin(t_out, real_fmax(t0, t1));
    }
    if (!(t_in < t_out))
        return false;
    int crossings = 0;
    for (int a = 0; a < 3; a++)
        for (int plane = 1; plane < g->n[a]; plane++) {
            real t = (lo[a] + (real)plane * cell[a] - pp[a]) / dd[a];
            if (t > t_in && t < t_out)
                crossings++;
            if (real_abs(t - t_in) < (real)1e-4 * t_in || real_abs(t - t_out) < (real)1e-4 * t_out)
                return false;
        }
    *cells = crossings + 1;
    return true;
}

/* The march of ray r (`what` names it) through g, which it crosses without
 * hitting anything, visits `cells` cells; a failure names dda_step's mistakes. */
static void expect_march_cells(const grid *g, ray r, const char *what, int cells)
{
    grid_counts counts = {0, 0};
    expect_no_hit(g, r, what, &counts);
    if (counts.cells != (uint64_t)cells)
        fail_msg("grid_intersect_counted(%s: p = (%.17g, %.17g, %.17g), d = (%.17g, %.17g, %.17g)) through a grid of %d "
                 "x %d x %d empty cells\n    expected %d cells visited (%d plane crossings + 1)\n"
                 "    got      %llu\n    likely mistake: %s",
                 what, (double)r.p.x, (double)r.p.y, (double)r.p.z, (double)r.d.x, (double)r.d.y, (double)r.d.z,
                 g->n[0], g->n[1], g->n[2], cells, cells - 1, (unsigned long long)counts.cells,
                 counts.cells > (uint64_t)cells
                     ? "dda_step goes on past the grid (the last cell is n_a - 1: stop when i_a < 0 or i_a >= "
                       "n_a), or next_a comes from the plane the ray just crossed (for step_a > 0 the far "
                       "boundary is plane i_a + 1, for step_a < 0 plane i_a)"
                     : "dda_step stops too early (i_a = 0 and i_a = n_a - 1 are inside the grid), or next_a "
                       "comes from the wrong plane (for step_a > 0 plane i_a + 1, for step_a < 0 plane i_a) or "
                       "is not updated");
}

/* The entry's closed slabs and slack, by the cells visited (at least one):
 * a ray along x in the plane of the box's face y = hi_y is inside that
 * slab (lo_a <= p_a <= hi_a); a ray along (1, -1, 0) passing the box's
 * edge x = hi_x, y = hi_y outside by half the reach of box_ray_slack (it
 * leaves x's slab at t = 2, enters y's at t = 2 + reach / 2: the gap is
 * far more than the roundings of these crossings, far less than the two
 * slacks) enters the widened box: the march errs towards a cell too many.
 * So does one outside by 1.5 reach: the slacks of x and y are reach each
 * (|d_a| = 1), and the gap is within their sum, 2 reach, but beyond either
 * alone (half a reach either way, again far more than the roundings).  The
 * same half reach past the edge y = hi_y, z = hi_z along (0, -1, 1): x's
 * slack is 0 there (d_x = 0), and y's and z's are reach each. */
static void expect_entry_edges(const grid *g)
{
    const ray on_face = {{g->lo.x - 1, g->hi.y, 0}, {1, 0, 0}};
    real inv_d[3], slack[3];
    const real reach = box_ray_slack((box){g->lo, g->hi}, (ray){{g->hi.x - 2, g->hi.y + 2, 0}, {1, -1, 0}}, inv_d, slack);
    const ray past_edge = {{g->hi.x - 2, g->hi.y + 2 + reach / 2, 0}, {1, -1, 0}};
    const ray farther = {{g->hi.x - 2, g->hi.y + 2 + reach * (real)1.5, 0}, {1, -1, 0}};
    const real mid_x = (g->lo.x + g->hi.x) / 2;
    const real reach_yz =
        box_ray_slack((box){g->lo, g->hi}, (ray){{mid_x, g->hi.y + 2, g->hi.z - 2}, {0, -1, 1}}, inv_d, slack);
    const ray past_edge_yz = {{mid_x, g->hi.y + 2 + reach_yz / 2, g->hi.z - 2}, {0, -1, 1}};
    /* past_edge from 1.8e6 farther back along the ray (in double; in float the same ray as past_edge): the reach
     * grows with the origin's distance, to 6.4e-9, above any fixed epsilon an entry might take for the slack */
    const real back = REAL_EPSILON < (real)1e-10 ? (real)4e-10 / REAL_EPSILON : 0;
    const ray towards_edge = {{g->hi.x - 2 - back, g->hi.y + 2 + back, 0}, {1, -1, 0}};
    const real reach_far = box_ray_slack((box){g->lo, g->hi}, towards_edge, inv_d, slack);
    const ray past_edge_far = {{g->hi.x - 2 - back, g->hi.y + 2 + back + reach_far / 2, 0}, {1, -1, 0}};
    for (int k = 0; k < 5; k++) {
        const ray r = k == 4 ? past_edge_far : k == 3 ? past_edge_yz : k == 2 ? farther : k ? past_edge : on_face;
        const char *where = k == 4   ? "from far away, passing the box's edge x = hi_x, y = hi_y outside by half the "
                                       "reach of the slack"
                            : k == 3 ? "passing the box's edge y = hi_y, z = hi_z outside by half the reach of the "
                                       "slack, with d_x = 0"
                            : k == 2 ? "passing the box's edge x = hi_x, y = hi_y outside by 1.5 times the reach of "
                                       "the slack, within the two slacks together"
                            : k      ? "passing the box's edge x = hi_x, y = hi_y outside by half the reach of the slack"
                                     : "in the plane of the box's face y = hi_y";
        grid_counts counts = {0, 0};
        expect_no_hit(g, r, where, &counts);
        if (counts.cells == 0)
            fail_msg("grid_intersect_counted(ray from (%.17g, %.17g, %.17g) along (%g, %g, %g), %s)\n    expected "
                     "at least 1 cell visited\n    got      0\n    likely mistake: %s",
                     (double)r.p.x, (double)r.p.y, (double)r.p.z, (double)r.d.x, (double)r.d.y, (double)r.d.z, where,
                     k == 4 ? "enter with a slack of its own (a fixed epsilon): the crossings round by more the "
                              "farther the ray's origin is (box_ray_slack's reach, here 6.4e-9 in double); widen each "
                              "by its axis's slack_a"
                     : k == 3 ? "enter: each axis's crossings widened by that axis's own slack_a (here slack_x is 0, "
                              "d_x = 0; slack_y and slack_z are the reach), not by another axis's"
                     : k == 2 ? "enter with the slack on one side only: the entering t is lowered by slack_a AND the "
                              "leaving t raised by slack_a, so that the gap between two axes' crossings is covered by "
                              "both slacks"
                     : k    ? "enter without the slack (or with it taken inwards): each entering t is lowered and each "
                              "leaving t raised by its axis's slack_a, so that a ray within rounding of the box's edge "
                              "still visits its cells (the march errs towards a cell too many, never one too few)"
                            : "enter: a ray with d_a = 0 on a face of axis a is inside that slab: lo_a <= p_a <= hi_a, "
                              "the faces included");
    }
}

/* A ray along x from outside the box, through its middle, whose d_y is the
 * smallest positive subnormal of the build: 1 / d_y overflows, so
 * box_ray_slack gives inv_d_y = 0 (and slack_y = 0), and the ray is never
 * counted as crossing a plane of y.  It visits every cell of its row along
 * x, n_x of them, as a ray with d_y = 0 does.  An entry that tests d_y == 0
 * instead of inv_d_y == 0 takes the crossings (lo_y - p_y) inv_d_y = 0 and
 * (hi_y - p_y) inv_d_y = 0 for y's slab: the window closes at t = 0, before
 * the ray reaches the box, and it visits no cell. */
static void expect_entry_tiny_component(const grid *g)
{
    const real tiny = real_next_up((real)0);
    const vec3 p = {g->lo.x - 5, (g->lo.y + g->hi.y) / 2 + (real)0.1, (g->lo.z + g->hi.z) / 2 + (real)0.1};
    const ray r = {p, {1, tiny, 0}};
    const char *what = "through the middle of the grid's box along x, d_y the smallest subnormal";
    grid_counts counts = {0, 0};
    expect_no_hit(g, r, what, &counts);
    if (counts.cells == 0)
        fail_msg("grid_intersect_counted(ray from (%.17g, %.17g, %.17g) along (1, %g, 0), d_y the smallest positive "
                 "subnormal, through the middle of the grid's box along x)\n    expected %d cells visited (its row "
                 "along x)\n    got      0\n    likely mistake: enter: the axis that is never crossed is the one "
                 "with inv_d_a == 0, as box_ray_slack gives it (also when d_a is so tiny that 1 / d_a overflows), not "
                 "d_a == 0: with inv_d_a = 0 both crossings (lo_a - p_a) inv_d_a and (hi_a - p_a) inv_d_a are 0 and "
                 "the window closes at t = 0",
                 (double)r.p.x, (double)r.p.y, (double)r.p.z, (double)tiny, g->n[0]);
    expect_march_cells(g, r, what, g->n[0]);
}

/* The entry: a ray that crosses each slab, but never all three at once,
 * passes beside the box's edge and visits no cell; a ray from outside with
 * every component negative enters the box (through the high faces). */
static void expect_entry(const grid *g)
{
    /* in the plane near z = 0 along x + y = 8: inside x's slab for t in [7, 12], y's for t in [3, 6] */
    const ray beside = {{10, -2, (real)-0.5}, {-1, 1, (real)0.05}};
    grid_counts counts = {0, 0};
    hit_record hit;
    bool found = grid_intersect_counted(g, beside, 0, REAL_INFINITY, &hit, &counts);
    if (found || counts.cells != 0)
        fail_msg("grid_intersect_counted(ray from (10, -2, -0.5) along (-1, 1, 0.05), beside the box's edge x = 3, y = "
                 "4: inside the slab of x for t in [7, 12], of y for t in [3, 6], never both)\n    expected no hit "
                 "and 0 cells visited\n    got      %s, %llu cells\n    likely mistake: enter: the ray is inside the "
                 "box only where it is inside all three slabs at once: *t0 = max(*t0, entering t of each axis), *t1 = "
                 "min(*t1, leaving t of each axis), and it misses the box when *t0 > *t1 (each axis narrows the "
                 "window, none overwrites it)",
                 found ? "a hit" : "no hit", (unsigned long long)counts.cells);
    const vec3 target = {(real)0.37, (real)2.61, (real)0.13}; /* inside the box [-2, 3] x [1, 4] x [-1, 1] */
    const vec3 from = vec3_add(target, vec3_make(14, 11, 6));
    const ray down = {from, vec3_sub(target, from)};
    int cells = 0;
    assert_true(cells_along(g, down, &cells));
    counts = (grid_counts){0, 0};
    expect_no_hit(g, down, "every component negative, through the grid's box", &counts);
    if (counts.cells == 0)
        fail_msg("grid_intersect_counted(ray from (%.17g, %.17g, %.17g) along (%.17g, %.17g, %.17g), every component "
                 "negative, through the grid's box)\n    expected %d cells visited\n    got      0 (the ray missed "
                 "the box)\n    likely mistake: enter: for d_a < 0 the ray enters the slab at hi_a and leaves it at "
                 "lo_a; the entering t is the smaller of (lo_a - p_a) inv_d_a and (hi_a - p_a) inv_d_a (take the "
                 "min and the max, or swap them when d_a < 0); or the crossings' sign flipped: t = (lo_a - p_a) "
                 "inv_d_a, from the ray's origin to the plane",
                 (double)down.p.x, (double)down.p.y, (double)down.p.z, (double)down.d.x, (double)down.d.y,
                 (double)down.d.z, cells);
    expect_march_cells(g, down, "ray with every component negative", cells);
    expect_entry_edges(g);
}

/* The first cell when the entry point lies a hair below a plane of cells: spheres of radius 0.1 at
 * (0, 0, 0) and (1, 1, 1) set the box, a triangle in the plane y = b - delta / 2 just below the plane
 * y = b of cells k - 1 and k (delta = 1000 REAL_EPSILON: half of it is several times the margin, 70
 * REAL_EPSILON here, so the triangle is listed in the cells below b only), and a ray from x = -100 that
 * climbs delta / 2 in y over 100.3 units of x enters the box about 500 REAL_EPSILON below b and meets
 * the triangle at t = 100.3, x = 0.3.  Moving the entry point by the rounding allowance (about 3200
 * REAL_EPSILON for an origin 100 away) forwards along the ray instead of backwards starts the march in
 * the row above b, which never holds the triangle. */
static void expect_first_cell_below_a_plane(void)
{
    surface_list list;
    surface_list_init(&list, SPHERE_ROBUST, TRIANGLE_CRAMER);
    surface_list_add_sphere(&list, (sphere){{0, 0, 0}, (real)0.1}, 0, 0);
    surface_list_add_sphere(&list, (sphere){{1, 1, 1}, (real)0.1}, 0, 1);
    surface_list_add_triangle(&list, (triangle){{0, (real)0.5, 0}, {1, (real)0.5, 0}, {(real)0.5, (real)0.5, 1}}, 0, 2);
    const grid_options opt = {.density = 100, .max_cells = 1000};
    grid g;
    build_grid(&g, &list, opt);
    const int k = g.n[1] / 2;
    const real b = g.lo.y + (real)k * g.cell.y, delta = 1000 * REAL_EPSILON, y0 = b - delta / 2;
    grid_free(&g);
    /* the same box and count: the same cells */
    list.items[2].triangle = (triangle){{0, y0, 0}, {1, y0, 0}, {(real)0.5, y0, 1}};
    build_grid(&g, &list, opt);
    const ray r = {{-100, b - delta, (real)0.5}, {1, delta / 2 / (real)100.3, 0}};
    hit_record want, got;
    assert_true(surfaces_intersect(&list, r, 0, REAL_INFINITY, &want) && want.surface == 2);
    if (!grid_intersect_counted(&g, r, 0, REAL_INFINITY, &got, NULL) || got.surface != 2 || got.t != want.t)
        fail_msg("a ray from (-100, b - %.3g, 0.5) along (1, %.3g, 0), b the plane of y cells %d and %d (%d x %d x %d "
                 "cells), towards a triangle in the plane y = b - %.3g listed below b only\n    expected surface 2 "
                 "at t = %.17g\n    got      %s\n    likely mistake: the first cell from p + t0 d moved forwards "
                 "along the ray by the rounding allowance: move it back, x_a -= step_a back (README, \"Entering "
                 "the grid\")",
                 (double)delta, (double)r.d.y, k - 1, k, g.n[0], g.n[1], g.n[2], (double)(delta / 2), (double)want.t,
                 found_what(grid_intersect_counted(&g, r, 0, REAL_INFINITY, &got, NULL), &got));
    grid_free(&g);
    surface_list_free(&list);
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
    grid_options opt = {.density = 100, .max_cells = 1000};
    build_grid(&g, &list, opt);
    expect_counts(&g, g.n[0] > 3 && g.n[1] > 3 && g.n[2] > 1,
                  "8 tiny spheres at the corners of [-2, 3] x [1, 4] x [-1, 1], density 100, cap 1000",
                  "more than 3 x 3 x 1 cells (the rays must cross cell planes)");
    expect_entry(&g);
    int checked = 0;
    for (int k = 0; k < 3000; k++) {
        /* from outside, through the middle part of the box (missing the corner spheres) */
        vec3 target = uniform_vec(vec3_make(-1, 2, (real)-0.5), vec3_make(2, 3, (real)0.5));
        vec3 p = vec3_add(target, vec3_scale(random_direction(), 20));
        ray r = {p, vec3_sub(target, p)};
        int cells;
        if (!cells_along(&g, r, &cells))
            continue;
        expect_march_cells(&g, r, describe("ray %d", k), cells);
        checked++;
    }
    assert_true(checked > 2000);
    expect_entry_tiny_component(&g); /* after the rays above, which name the march's own mistakes first */
    grid_free(&g);
    surface_list_free(&list);
    expect_first_cell_below_a_plane();
}

/* dda_step along one axis at a time: tiny spheres on a lattice 5 x 4 x 3
 * (spacings 0.37, 0.61, 0.29, far from the origin), a grid over them with
 * about two cells between neighbours; from each sphere's centre along +x, -x, +y, -y, +z and -z
 * (the negative ones with -0 components), past its own sphere (t_min =
 * twice the radius): the hit is the next sphere along that axis, as the
 * linear scan finds.  A failure names the axis and the direction, which is
 * what a wrong index or plane gets wrong; a ray that visits no cell, though
 * it starts inside the grid's box, names the entry (its zero components). */
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
    build_grid(&g, &list, (grid_options){.density = 8, .max_cells = 1L << 20});
    expect_counts(&g, g.n[0] > m[0] && g.n[1] > m[1] && g.n[2] > m[2],
                  "60 tiny spheres on a lattice 5 x 4 x 3, spacings 0.37, 0.61, 0.29, density 8",
                  "more cells than spheres along every axis (above 5 x 4 x 3)");
    const vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int s = 0; s < list.n; s++) {
        const int at[3] = {s % m[0], s / m[0] % m[1], s / (m[0] * m[1])};
        for (int a = 0; a < 3; a++)
            for (int sign = -1; sign <= 1; sign += 2) {
                if (at[a] + sign < 0 || at[a] + sign >= m[a])
                    continue;
                ray r = {list.items[s].sphere.center, sign > 0 ? axes[a] : vec3_neg(axes[a])};
                hit_record want, got;
                grid_counts counts = {0, 0};
                bool fw = surfaces_intersect(&list, r, 2 * radius, REAL_INFINITY, &want);
                bool fg = grid_intersect_counted(&g, r, 2 * radius, REAL_INFINITY, &got, &counts);
                assert_true(fw && want.surface == s + sign * (a == 0 ? 1 : a == 1 ? m[0] : m[0] * m[1]));
                /* The ray starts inside the grid's box, so the march visits at least its first cell
                 * whatever dda_step does: no cell at all is the entry's mistake. */
                if (counts.cells == 0)
                    fail_msg("grid_intersect_counted(ray from sphere %d's centre, inside the grid's box, along "
                             "%c%c, t_min = %g)\n    expected sphere %d, at least 1 cell visited\n    got      %s, "
                             "0 cells\n    likely mistake: %senter: a component d_a = +0 or -0 (inv_d_a = 0, here "
                             "along the two axes other than %c) never crosses a face of axis a; the ray stays inside "
                             "that slab (lo_a <= p_a <= hi_a) and the axis must not narrow [t0, t1] ((lo_a - p_a) "
                             "inv_d_a = 0 is no crossing)",
                             s, sign > 0 ? '+' : '-', "xyz"[a], (double)(2 * radius), want.surface,
                             fg ? "a hit" : "no hit",
                             sign < 0 ? "enter: along a negative axis the ray enters the slab at hi_a and leaves it "
                                        "at lo_a, so the entering t is the smaller of the two crossings (take the min "
                                        "and the max); or "
                                      : "",
                             "xyz"[a]);
                /* the next sphere's near side lies more than a cell away (the cells are smaller than the
                 * spacing times (m_a - 1) / m_a, plus a few hundredths): the march visits more than one cell */
                if (!fg && counts.cells == 1)
                    fail_msg("grid_intersect_counted(ray from sphere %d's centre along %c%c, t_min = %g)\n    expected "
                             "sphere %d, more than a cell away\n    got      no hit, after 1 cell\n    likely mistake: "
                             "the march ended after its first cell: the stop rule tests next_a - slack_a of the axis "
                             "a the cell ends by (the nearest boundary, here %c's; another axis's next is infinite "
                             "along an axis), or dda_step gave false at once",
                             s, sign > 0 ? '+' : '-', "xyz"[a], (double)(2 * radius), want.surface, "xyz"[a]);
                if (!same_hit(fw, &want, fg, &got))
                    fail_msg(
                        "grid_intersect(ray from sphere %d's centre (%.17g, %.17g, %.17g) along %c%c, t_min = "
                        "%g) through a grid of %d x %d x %d cells\n    expected sphere %d at t = %.17g\n"
                        "    got      %s\n    likely mistake: dda_step along %c with step %+d: "
                        "the index i_%c moves by step, and next_%c is the crossing of plane i_%c%s, recomputed each "
                        "step",
                        s, (double)r.p.x, (double)r.p.y, (double)r.p.z, sign > 0 ? '+' : '-', "xyz"[a],
                        (double)(2 * radius), g.n[0], g.n[1], g.n[2], want.surface, (double)want.t,
                        found_what(fg, &got), "xyz"[a], sign, "xyz"[a], "xyz"[a], "xyz"[a], sign > 0 ? " + 1" : "");
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
        const grid_options opt = {.density = 5000, .max_cells = 1L << 20};
        grid g;
        build_grid(&g, &list, opt);
        expect_counts(&g, g.n[0] > 100000 && g.n[1] == 1 && g.n[2] == 1,
                      describe("%d spheres in a box %.9g x 0.002 x 0.002, density 5000, cap 2^20", 2 + 4 * PLANES,
                               (double)L + 0.002),
                      "over 100000 x 1 x 1 cells (across, 0.002 is a fraction of a cell: one)");
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
        expect_same_cells(&g, 0, cells, lo, cell, /* the same grid */
                          describe("%d surfaces in the same box %.9g long, density 5000", 2 + 4 * PLANES, (double)L));
        for (int q = 0; q < 2 * PLANES; q++) {
            hit_record want, got;
            bool fw = surfaces_intersect(&list, rays[q], 0, REAL_INFINITY, &want);
            bool fg = grid_intersect(&g, rays[q], 0, REAL_INFINITY, &got);
            assert_true(fw && want.surface == 2 + 2 * q); /* B is the closest */
            if (!same_hit(fw, &want, fg, &got))
                fail_msg("grid_intersect(ray from (%.17g, %.17g, %.17g) along %cx) through %ld cells of %.17g along "
                         "x\n    expected the small sphere (surface %d) at t = %.17g, just past the boundary of cell "
                         "%ld\n    got      %s\n    likely mistake: next_x gathered rounding: compute "
                         "it from the plane at each step (crossing(g, a, plane, r, inv_d)), not by adding a t step "
                         "per cell; or the march stopped at the first cell holding a hit (test_stop_rule tells "
                         "which)",
                         (double)rays[q].p.x, (double)rays[q].p.y, (double)rays[q].p.z, q % 2 ? '-' : '+', cells,
                         (double)cell, want.surface, (double)want.t, q % 2 ? cells - planes[q / 2] : planes[q / 2],
                         found_what(fg, &got));
        }
        grid_free(&g);
        surface_list_free(&list);
    }
}

/* The march of r through the grid of `list` (freed here), which has g's
 * cells along axis a; the linear scan's hit must be surface `expected`. */
static bool march_in_row(surface_list *list, const grid *g, int a, ray r, int expected, hit_record *want,
                         hit_record *got, grid_counts *counts)
{
    grid h;
    build_grid(&h, list, grid_default_options());
    expect_same_cells(&h, a, g->n[a], vec3_axis(g->lo, a), vec3_axis(g->cell, a), /* the same cells */
                      "the stop rule's case: the same box, two surfaces added");
    assert_true(surfaces_intersect(list, r, 0, REAL_INFINITY, want) && want->surface == expected);
    *counts = (grid_counts){0, 0};
    bool found = grid_intersect_counted(&h, r, 0, REAL_INFINITY, got, counts);
    grid_free(&h);
    surface_list_free(list);
    return found;
}

/* The stop rule tests the far boundary of the cell being visited, not the
 * next cell's: in the row of cells of `g` (built from 10 surfaces in the
 * box of row_of_cells, as here), a triangle A listed from cell 1 on is hit a
 * fraction 0.7 into cell 4, a small sphere B a fraction 0.3 into it (B lies
 * in cell 4 alone).  Visiting cell 3 the march knows A's hit, beyond cell
 * 3's boundary but before cell 4's: it must go on to cell 4 and find B. */
static void expect_stop_in_this_cell(const grid *g)
{
    const real lo = g->lo.x, cell = g->cell.x, b = lo + 4 * cell; /* cell 3's far boundary */
    const real x_A = b + (real)0.7 * cell, x_B = b + (real)0.3 * cell;
    surface_list list;
    row_of_cells(&list, TRIANGLE_WATERTIGHT, false);
    /* A: from x = 1.2 at z = 0 to x = 2 x_A - 1.2 at z = 1, hit at y = z = 1/2 at x_A */
    surface_list_add_triangle(&list, (triangle){{(real)1.2, 0, 0}, {(real)1.2, 1, 0}, {2 * x_A - (real)1.2, (real)0.5, 1}},
                              0, 8);
    surface_list_add_sphere(&list, (sphere){{x_B + (real)0.1 * cell, (real)0.5, (real)0.5}, (real)0.1 * cell}, 0, 9);
    hit_record want, got;
    grid_counts counts;
    bool found = march_in_row(&list, g, 0, (ray){{-1, (real)0.5, (real)0.5}, {1, 0, 0}}, 9, &want, &got, &counts);
    if (!same_hit(true, &want, found, &got) || counts.cells != 5)
        fail_msg("grid_intersect_counted(ray along +x through a row of %d cells of %.17g: a triangle hit at x = %.17g "
                 "and a sphere hit at x = %.17g, both in cell 4)\n    expected sphere 9 at t = %.17g, 5 cells "
                 "visited\n    got      %s, %llu cells\n    likely mistake: %s",
                 g->n[0], (double)cell, (double)x_A, (double)x_B, (double)want.t, found_what(found, &got),
                 (unsigned long long)counts.cells,
                 found && got.surface == 8 && counts.cells == 4
                     ? "the stop rule tested the next cell's far boundary: the march ends once the best hit lies "
                       "before the far boundary of the cell being visited (next_a of this cell, minus the slack)"
                 : found && got.surface == 8 ? "the march stopped at the first cell holding a hit: a hit counts only "
                                               "once it lies in the cell being visited"
                                             : "the march ends in the cell that holds the best hit, cell 4 here");
}

/* The point `along` axis a (x or y) at (u, v) across it. */
static vec3 on_axis(int a, real along, real u, real v) { return a ? vec3_make(u, along, v) : vec3_make(along, u, v); }

/* A column of cells along y: tiny spheres at the corners of the box [0, 1] x
 * [0, 10] x [0, 1] (surfaces 0-7), row_of_cells's box turned. */
static void column_of_cells(surface_list *list)
{
    surface_list_init(list, SPHERE_ROBUST, TRIANGLE_WATERTIGHT);
    for (int k = 0; k < 8; k++) /* the corners, x, y, z from bits 0, 1, 2 */
        surface_list_add_sphere(
            list, (sphere){on_axis(1, (real)(10 * ((k >> 1) & 1)), (real)(k & 1), (real)(k >> 2)), (real)0.001}, 0, k);
}

/* The stop rule allows for the boundary's slack: in the row of cells of `g`
 * along axis a (10 surfaces in row_of_cells's box, or column_of_cells's
 * along y, as here), a triangle across the ray along +a is hit half a slack
 * before cell 3's far boundary (slack[a] of box_ray_slack, 176 REAL_EPSILON
 * here, far more than the few roundings of the hit's t and of the crossing,
 * far less than the margin, so the triangle is listed in cells 3 and 4).
 * Within the slack the hit may be the rounding of a point beyond the
 * boundary: the march visits cell 4 too, 5 cells; a rule without the slack,
 * or with it added, stops after 4.  Along y, x's slack is 0 (d_x = 0): a
 * rule that takes x's slack for every axis stops after 4 too.  The ray starts
 * at `from` along the axis: at -1, or far away, where slack_a (which grows
 * with the origin's distance) is larger than a fixed epsilon that a rule might
 * take for it. */
static void expect_stop_slack(const grid *g, int a, real from)
{
    const ray r = {on_axis(a, from, (real)0.5, (real)0.5), on_axis(a, 1, 0, 0)};
    real inv_d[3], slack[3];
    (void)box_ray_slack((box){g->lo, g->hi}, r, inv_d, slack);
    const real next = (vec3_axis(g->lo, a) + 4 * vec3_axis(g->cell, a) - vec3_axis(r.p, a)) * inv_d[a]; /* crossing() */
    const real x = vec3_axis(r.p, a) + (next - slack[a] / 2);
    surface_list list;
    if (a)
        column_of_cells(&list);
    else
        row_of_cells(&list, TRIANGLE_WATERTIGHT, false);
    surface_list_add_triangle(&list,
                              (triangle){on_axis(a, x, (real)0.3, (real)0.3), on_axis(a, x, (real)0.8, (real)0.4),
                                         on_axis(a, x, (real)0.4, (real)0.8)},
                              0, 8);
    surface_list_add_sphere(&list, (sphere){on_axis(a, 9, (real)0.1, (real)0.1), (real)0.01}, 0, 9); /* off the ray */
    hit_record want, got;
    grid_counts counts;
    bool found = march_in_row(&list, g, a, r, 8, &want, &got, &counts);
    if (!same_hit(true, &want, found, &got) || counts.cells != 5)
        fail_msg(
            "grid_intersect_counted(ray along +%c from %g through a row of %d cells: a triangle hit at t = %.17g, "
            "half the slack %.3g before cell 3's far boundary at t = %.17g)\n    expected the triangle at t = %.17g, "
            "5 cells visited (cell 4 too)\n    got      %s, %llu cells\n    likely mistake: %s",
            "xy"[a], (double)from, g -> n[a], (double)want.t, (double)slack[a], (double)next, (double)want.t,
            found_what(found, &got), (unsigned long long)counts.cells,
            counts.cells == 4 ? a ? "the stop rule with another axis's slack: the slack is slack_a of the axis a "
                                    "the cell ends by (here y; x's is 0 along y); or without the slack (or with "
                                    "it added): stop only once t_best <= next_a - slack_a"
                              : from < -1 ? "the stop rule with a slack of its own (a fixed epsilon) for slack_x: "
                                            "the rounding of t grows with the ray's origin (box_ray_slack), here "
                                            "far away; stop only once t_best <= next_a - slack_a"
                                          : "the stop rule without the slack (or with it added): a hit within the "
                                            "slack of the boundary may be a point beyond it, rounded; stop only "
                                            "once t_best <= next_a - slack_a"
                              : "the march ends in the cell that holds the best hit, allowing for the slack: "
                                "t_best <= next_a - slack_a");
}

/* The stop rule: corner spheres fix the grid's box [0, 10] x [0, 1] x [0, 1]
 * (a row of cells along x), a big tilted triangle A spans x = 1.2 .. 8.8 (so
 * it is listed from cell 1 on) and is hit at x = 5, and a small sphere B is
 * hit at x = 2.9.  A ray along +x meets A's cells first and B's hit first:
 * the answer is B, and the march ends in B's cell.  A ray beside the box,
 * parallel to x, visits no cell at all. */
static void test_stop_rule(void **state)
{
    (void)state;
    surface_list list;
    row_of_cells(&list, TRIANGLE_WATERTIGHT, false);
    surface_list_add_triangle(&list, (triangle){{(real)1.2, 0, 0}, {(real)1.2, 1, 0}, {(real)8.8, (real)0.5, 1}}, 0, 8);
    surface_list_add_sphere(&list, (sphere){{3, (real)0.5, (real)0.5}, (real)0.1}, 0, 9);
    grid g;
    build_grid(&g, &list, grid_default_options());
    const ray r = {{-1, (real)0.5, (real)0.5}, {1, 0, 0}};
    hit_record want, got;
    grid_counts counts = {0, 0};
    assert_true(surfaces_intersect(&list, r, 0, REAL_INFINITY, &want) && want.surface == 9);
    bool found = grid_intersect_counted(&g, r, 0, REAL_INFINITY, &got, &counts);
    const uint64_t cells = (uint64_t)((real)2.9 / g.cell.x) + 1; /* cells 0 .. B's, the first at x = -margin */
    if (!same_hit(true, &want, found, &got))
        fail_msg("grid_intersect(ray along +x through a grid of %d cells along x)\n    expected sphere 9 at t = %.17g "
                 "(x = 2.9)\n    got      %s\n    likely mistake: %s",
                 g.n[0], (double)want.t, found_what(found, &got),
                 found && got.surface == 8 ? "the march stopped at the first cell holding a hit (the triangle, listed "
                                             "from cell 1 on, is hit at x = 5); a hit counts only once it lies in "
                                             "the cell being visited"
                                           : "the march ended before the sphere's cell: it ends once the best hit "
                                             "so far lies in the cell being visited, t_best <= next_a - slack_a for "
                                             "the axis a the cell ends by (with no hit yet, t_best is t_max), or "
                                             "at the grid's end");
    if (counts.cells != cells)
        fail_msg("grid_intersect_counted(ray along +x, hit at x = 2.9 in cell %llu of %d)\n    expected %llu cells "
                 "visited\n    got      %llu\n    likely mistake: %s",
                 (unsigned long long)(cells - 1), g.n[0], (unsigned long long)cells, (unsigned long long)counts.cells,
                 counts.cells > cells ? "the march goes on after the best hit lies in the cell being visited "
                                        "(stop once t_best <= the cell's far boundary)"
                                      : "the march ends before the hit's cell");
    expect_stop_in_this_cell(&g);
    expect_stop_slack(&g, 0, -1);
    /* from far away along the row (1.8e6 in double; -1 in float, the case above): slack_x grows with the
     * origin's distance, to 6.4e-9 here, still far below a cell, and the hit lies half of it before the boundary */
    expect_stop_slack(&g, 0, -real_fmax(1, (real)4e-10 / REAL_EPSILON));
    /* the same along y, in a column of cells of 10 surfaces (two stand-ins inside) */
    surface_list column;
    column_of_cells(&column);
    surface_list_add_sphere(&column, (sphere){{(real)0.5, 5, (real)0.5}, (real)0.001}, 0, 8);
    surface_list_add_sphere(&column, (sphere){{(real)0.5, 6, (real)0.5}, (real)0.001}, 0, 9);
    grid g_column;
    build_grid(&g_column, &column, grid_default_options());
    expect_stop_slack(&g_column, 1, -1);
    grid_free(&g_column);
    surface_list_free(&column);
    /* the window ends at x = 2 (t = 3), before any surface: no hit, and the march ends in the window's last
     * cell, as t_best starts at t_max; a rule that waits for a hit goes on to the grid's end */
    counts = (grid_counts){0, 0};
    found = grid_intersect_counted(&g, r, 0, 3, &got, &counts);
    const uint64_t window_cells = (uint64_t)((2 - g.lo.x) / g.cell.x) + 1;
    if (found || counts.cells != window_cells)
        fail_msg("grid_intersect_counted(ray along +x from x = -1 with the window (0, 3), which ends at x = 2 in cell "
                 "%llu of %d, before any surface)\n    expected no hit, %llu cells visited\n    got      %s, %llu "
                 "cells\n    likely mistake: %s",
                 (unsigned long long)(window_cells - 1), g.n[0], (unsigned long long)window_cells,
                 found ? "a hit" : "no hit", (unsigned long long)counts.cells,
                 counts.cells > window_cells ? "the stop rule waits for a hit: with no hit yet t_best is t_max, and "
                                               "the march ends in the cell where the window ends (a shadow ray that "
                                               "reaches its light stops there)"
                                             : "the march ends in the cell where the window ends (t_best, t_max "
                                               "before any hit, <= next_a - slack_a of the cell being visited)");
    /* beside the box (y = 2), parallel to x: no slab of y is ever crossed */
    counts = (grid_counts){0, 0};
    found = grid_intersect_counted(&g, (ray){{-1, 2, (real)0.5}, {1, 0, 0}}, 0, REAL_INFINITY, &got, &counts);
    if (found || counts.cells != 0)
        fail_msg("grid_intersect_counted(ray at y = 2 along +x, beside the grid's box 0 <= y <= 1)\n    expected no "
                 "hit and 0 cells visited\n    got      %s, %llu cells\n    likely mistake: enter: a ray with d_a = "
                 "0 never crosses a face of axis a, so it misses the box unless lo_a <= p_a <= hi_a",
                 found ? "a hit" : "no hit", (unsigned long long)counts.cells);
    grid_free(&g);
    surface_list_free(&list);
}

static const graded_test tests[] = {
    GRADED(test_cell_range, 4),
    GRADED(test_dda_cells, 4),
    GRADED(test_dda_axis_steps, 2),
    GRADED(test_dda_no_accumulation, 1),
    GRADED(test_stop_rule, 2),
    GRADED(test_random_scenes, 3),
    GRADED(test_zero_components, 2),
    GRADED(test_origins_on_the_grid, 2),
    GRADED(test_flat_scenes, 2),
    GRADED(test_huge_among_tiny, 2),
    GRADED(test_start_inside_spanning_cells, 2),
    GRADED(test_ties_first_in_list, 2),
    GRADED(test_resolution, 1),
    GRADED(test_march_counts, 1),
    GRADED(test_empty_and_single, 1),
    GRADED(test_cornell_scenes, 0),
    GRADED(test_builtin_scenes_as_chapter_10, 0),
};

SUITE_MAIN("11_grid", tests)
