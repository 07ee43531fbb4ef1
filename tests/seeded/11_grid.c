/* Chapter 11's checks of inputs drawn at grading time (tests/answers.h): the
 * cells of boxes drawn from the grader's seed in grids of inexact cell
 * sizes drawn from it (exact integers), and the closest hits of rays drawn
 * from it through the grid of a scene drawn from it (seeded_surfaces.h
 * says why that tolerance). */
#include "11_grid/grid.h"
#include "grid_resolution_range.h"
#include "seeded_surfaces.h"

static void seeded_cell_range(unsigned long *rng)
{
    for (int k = 0; k < 12; k++) {
        grid g = {.lo = seeded_point(rng, 20)};
        for (int a = 0; a < 3; a++)
            g.n[a] = 1 + (int)seeded_between(rng, 0, 30);
        g.cell = vec3_make((real)seeded_between(rng, 0.05, 2), (real)seeded_between(rng, 0.05, 2),
                           (real)seeded_between(rng, 0.05, 2));
        g.hi = vec3_add(g.lo, vec3_make(g.cell.x * (real)g.n[0], g.cell.y * (real)g.n[1], g.cell.z * (real)g.n[2]));
        vec3 size = vec3_sub(g.hi, g.lo); /* corners mostly inside the grid, some beyond it */
        vec3 a = vec3_add(g.lo, vec3_make(size.x * (real)seeded_between(rng, -0.2, 1.2),
                                          size.y * (real)seeded_between(rng, -0.2, 1.2),
                                          size.z * (real)seeded_between(rng, -0.2, 1.2)));
        vec3 b = vec3_add(a, seeded_point(rng, 5));
        vec3 box_lo = vec3_make(real_fmin(a.x, b.x), real_fmin(a.y, b.y), real_fmin(a.z, b.z));
        vec3 box_hi = vec3_make(real_fmax(a.x, b.x), real_fmax(a.y, b.y), real_fmax(a.z, b.z));
        int first[3], last[3];
        grid_cell_range(&g, box_lo, box_hi, first, last);
        const char *in = describe("grid_cell_range(grid from (%.9g, %.9g, %.9g), cells %.9g x %.9g x %.9g, n = %d x "
                                  "%d x %d; box (%.9g, %.9g, %.9g) to (%.9g, %.9g, %.9g))",
                                  g.lo.x, g.lo.y, g.lo.z, g.cell.x, g.cell.y, g.cell.z, g.n[0], g.n[1], g.n[2],
                                  box_lo.x, box_lo.y, box_lo.z, box_hi.x, box_hi.y, box_hi.z);
        for (int axis = 0; axis < 3; axis++) {
            suite_answer(describe("%s: first[%d]", in, axis), first[axis], 0);
            suite_answer(describe("%s: last[%d]", in, axis), last[axis], 0);
        }
    }
}

/* The resolution of boxes drawn from the seed, one axis flat now and then,
 * the cap binding now and then: integers.  When the first try fits the cap,
 * the README's formula gives them exactly, so they must equal the
 * reference's; after a shrink the README allows any of a range
 * (grid_resolution_range.h), so the answers are how far each count lies
 * outside its range and how far the product exceeds the cap: 0, exactly. */
static void seeded_resolution(unsigned long *rng)
{
    for (int k = 0; k < 12; k++) {
        double extent[3];
        for (int a = 0; a < 3; a++)
            extent[a] = k % 4 == a ? 0 : seeded_between(rng, 0.01, 50);
        long surfaces = 1 + (long)seeded_between(rng, 0, 5000);
        double density = seeded_between(rng, 0.2, 10);
        long cap = k % 3 == 0 ? 1 + (long)seeded_between(rng, 0, 2000) : 1L << 24;
        int n[3];
        grid_resolution(extent, surfaces, density, cap, n);
        const char *in = describe("grid_resolution(extent %.9g x %.9g x %.9g, %ld surfaces, density %.9g, cap %ld)",
                                  extent[0], extent[1], extent[2], surfaces, density, cap);
        const grid_resolution_range allowed = grid_resolution_allowed(extent, surfaces, density, cap);
        for (int a = 0; a < 3; a++)
            if (allowed.capped)
                suite_answer(describe("%s: how far n[%d] lies outside %d .. %d, the counts of a shrink by 0.9 to 1 a "
                                      "try",
                                      in, a, allowed.lowest[a], allowed.highest[a]),
                             fmax(0, fmax(allowed.lowest[a] - n[a], n[a] - allowed.highest[a])), 0);
            else
                suite_answer(describe("%s: n[%d]", in, a), n[a], 0);
        if (allowed.capped)
            suite_answer(describe("%s: cells above the cap", in), fmax(0, (double)n[0] * n[1] * n[2] - (double)cap), 0);
    }
}

static void seeded_grid(unsigned long *rng)
{
    for (int n = 0; n < 3; n++) {
        surface_list list;
        int count = 5 + (int)seeded_between(rng, 0, 40);
        seeded_surfaces(rng, &list, count, 2);
        grid g;
        char err[256];
        if (grid_build(&g, &list, grid_default_options(), err, sizeof err) != 0)
            fail_msg("grid_build: %s", err);
        for (int k = 0; k < 12; k++) {
            ray r = seeded_ray(rng);
            hit_record hit = {0};
            bool found = grid_intersect(&g, r, 0, REAL_INFINITY, &hit);
            seeded_answer_hit(describe("grid_intersect(scene %d of %d surfaces, ray %d: p = (%.9g, %.9g, %.9g), d = "
                                       "(%.9g, %.9g, %.9g))",
                                       n + 1, count, k + 1, r.p.x, r.p.y, r.p.z, r.d.x, r.d.y, r.d.z),
                              r, found, &hit);
        }
        grid_free(&g);
        surface_list_free(&list);
    }
}

SEEDED_CHECKS(SEEDED(test_cell_range, seeded_cell_range), SEEDED(test_dda_cells, seeded_grid),
              SEEDED(test_dda_axis_steps, seeded_grid), SEEDED(test_dda_no_accumulation, seeded_grid),
              SEEDED(test_stop_rule, seeded_grid), SEEDED(test_random_scenes, seeded_grid),
              SEEDED(test_zero_components, seeded_grid), SEEDED(test_origins_on_the_grid, seeded_grid),
              SEEDED(test_flat_scenes, seeded_grid), SEEDED(test_huge_among_tiny, seeded_grid),
              SEEDED(test_start_inside_spanning_cells, seeded_grid), SEEDED(test_ties_first_in_list, seeded_grid),
              SEEDED(test_resolution, seeded_resolution), SEEDED(test_march_counts, seeded_grid),
              SEEDED(test_empty_and_single, seeded_grid))
