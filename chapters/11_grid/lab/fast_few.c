/* fast_few.c - chapter 11's lab: surfaces tested for every ray: a scene of few surfaces as a list,
 * without cells, and the few large surfaces of a scene (a floor) apart from the cells of the rest. */
#include <math.h>
#include <stdlib.h>

#include "11_grid/lab/fast_boxes.h"
#include "11_grid/lab/fast_build.h"

/* What a ray's test of each kind of unit costs, in quarters of a triangle
 * test: the lab's times of scenes of a floor and k boxes, spheres or
 * triangles, listed and gridded (the lab's README, "Few surfaces"). */
enum { QUARTERS_TRIANGLE = 4, QUARTERS_BOX = 5, QUARTERS_SPHERE = 16 };

/* The entry of surface k in the list, as the packed lists have it (k, or
 * FAST_GRID_BOX + its box, by the box's first triangle), or FAST_BOX_NONE
 * for no entry: a box's other triangles, a surface without finite bounds
 * (g->unbinned, tested apart). */
static uint32_t unit_entry(const fast_grid *g, const surface_list *list, long k)
{
    vec3 lo, hi;
    fast_grid_surface_bounds(&list->items[k], &lo, &hi);
    const uint32_t b = g->boxes ? g->boxes->of[k] : FAST_BOX_NONE;
    if (!vec3_is_finite(lo) || !vec3_is_finite(hi) || (b != FAST_BOX_NONE && g->boxes->box[b].first != (uint32_t)k))
        return FAST_BOX_NONE;
    return b == FAST_BOX_NONE ? (uint32_t)k : FAST_GRID_BOX + b;
}

/* A unit's cost in quarters of a triangle test. */
static long long unit_quarters(const surface_list *list, uint32_t e)
{
    if (e >= FAST_GRID_BOX)
        return QUARTERS_BOX;
    return list->items[e].kind == SHAPE_SPHERE ? QUARTERS_SPHERE : QUARTERS_TRIANGLE;
}

bool fast_grid_few_units(fast_grid *g, const surface_list *list, int up_to)
{
    /* the units and their cost */
    long n = 0;
    long long quarters = 0;
    for (long k = 0; k < list->n; k++) {
        const uint32_t e = unit_entry(g, list, k);
        if (e == FAST_BOX_NONE)
            continue;
        n++;
        quarters += unit_quarters(list, e);
        if (quarters > 4 * (long long)up_to)
            return true; /* too many: cells */
    }
    if (n == 0)
        return true;
    g->units = malloc((size_t)n * sizeof *g->units);
    if (!g->units)
        return false;
    for (long k = 0; k < list->n; k++) {
        const uint32_t e = unit_entry(g, list, k);
        if (e != FAST_BOX_NONE)
            g->units[g->n_units++] = e;
    }
    g->peak_bytes = fast_grid_memory(g);
    g->n[0] = g->n[1] = g->n[2] = 0; /* no cells; the box, for the rays that miss it */
    g->lo_a[0] = g->lo.x, g->lo_a[1] = g->lo.y, g->lo_a[2] = g->lo.z;
    g->hi_a[0] = g->hi.x, g->hi_a[1] = g->hi.y, g->hi_a[2] = g->hi.z;
    return true;
}

/* Every box is widened by the margin of the whole scene's size: the cells of
 * the surfaces not set apart must be at least this many margins wide, or
 * each surface would be listed in many of them, their count growing as the
 * square of the surfaces' (a cluster a few margins wide beside a floor far
 * larger).  Then nothing is set apart. */
#define MARGINS_A_CELL 16

/* The cells along axis a, of n_a over lo_a .. lo_a + e_a, that x0 .. x1 overlaps. */
static double cells_over(double x0, double x1, double lo_a, double e_a, int n_a)
{
    if (!(e_a > 0))
        return 1;
    const double first = floor((x0 - lo_a) / e_a * n_a), last = floor((x1 - lo_a) / e_a * n_a);
    return fmin(last, n_a - 1) - fmax(first, 0) + 1;
}

/* Large surfaces apart: of the units with finite bounds, those whose box
 * reaches over more than half the scene's box [*lo, *hi] along an axis at
 * least a quarter as long as its longest (a floor under the scene; not a
 * stick as tall as a flat scene), when they cost a ray at most up_to
 * triangle tests and the others would lie in at most a quarter of the cells
 * the whole box would get.  Then apart[k] is true for each of their
 * surfaces (false on entry), *lo and *hi are the others' box and *rest their
 * count, and it returns true; else (or where their cells would be narrower
 * than MARGINS_A_CELL margins) false, everything as it was.  The boxes
 * of g are those fast_boxes_find found. */
static bool find_apart(const fast_grid *g, const surface_list *list, int up_to, double density, long max_cells,
                       bool *apart, vec3 *lo, vec3 *hi, long *rest)
{
    const double box_lo[3] = {lo->x, lo->y, lo->z}, extent[3] = {hi->x - lo->x, hi->y - lo->y, hi->z - lo->z};
    const double longest = fmax(extent[0], fmax(extent[1], extent[2]));
    /* the large units (more than half the box along an axis at least a quarter of its longest) and their
     * cost; the others' box and count */
    long long quarters = 0;
    long large = 0, others = 0, surfaces = 0;
    double rest_lo[3] = {INFINITY, INFINITY, INFINITY}, rest_hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (long k = 0; k < list->n; k++) {
        const uint32_t e = unit_entry(g, list, k);
        if (e == FAST_BOX_NONE)
            continue;
        vec3 ulo, uhi;
        fast_grid_entry_bounds(g, (uint32_t)k, &ulo, &uhi);
        const double u_lo[3] = {ulo.x, ulo.y, ulo.z}, u_hi[3] = {uhi.x, uhi.y, uhi.z};
        bool is_large = false;
        for (int a = 0; a < 3; a++)
            is_large = is_large || (extent[a] >= longest / 4 && u_hi[a] - u_lo[a] > extent[a] / 2);
        const long count = e >= FAST_GRID_BOX ? 12 : 1;
        surfaces += count;
        if (is_large) {
            large++;
            quarters += unit_quarters(list, e);
            for (long t = k; t < k + count; t++)
                apart[t] = true;
            continue;
        }
        others += count;
        for (int a = 0; a < 3; a++) {
            rest_lo[a] = fmin(rest_lo[a], u_lo[a]);
            rest_hi[a] = fmax(rest_hi[a], u_hi[a]);
        }
    }
    /* worth it: the others would lie in at most a quarter of the cells the whole box would get */
    int n[3];
    fast_grid_resolution(extent, surfaces, density, max_cells, n);
    double covered = 1;
    for (int a = 0; a < 3; a++)
        covered *= cells_over(rest_lo[a], rest_hi[a], box_lo[a], extent[a], n[a]);
    /* and possible: the others' cells at least MARGINS_A_CELL margins wide along each axis they span */
    const double rest_extent[3] = {rest_hi[0] - rest_lo[0], rest_hi[1] - rest_lo[1], rest_hi[2] - rest_lo[2]};
    int n_rest[3];
    fast_grid_resolution(rest_extent, others, density, max_cells, n_rest);
    bool wide = true;
    for (int a = 0; a < 3; a++)
        wide = wide && (n_rest[a] == 1 || rest_extent[a] >= MARGINS_A_CELL * (double)g->margin * n_rest[a]);
    if (large == 0 || others == 0 || quarters > 4 * (long long)up_to || !wide ||
        !(4 * covered <= (double)n[0] * n[1] * (double)n[2])) {
        for (long k = 0; k < list->n; k++)
            apart[k] = false;
        return false;
    }
    *lo = vec3_make((real)rest_lo[0], (real)rest_lo[1], (real)rest_lo[2]);
    *hi = vec3_make((real)rest_hi[0], (real)rest_hi[1], (real)rest_hi[2]);
    *rest = others;
    return true;
}

/* g->apart from the flags, after fast_boxes_keep_small (which keeps their boxes).  False when out of memory. */
static bool keep_apart(fast_grid *g, const surface_list *list, const bool *apart)
{
    long n = 0;
    for (long k = 0; k < list->n; k++)
        n += apart[k] && unit_entry(g, list, k) != FAST_BOX_NONE;
    g->apart = malloc((size_t)(n ? n : 1) * sizeof *g->apart);
    if (!g->apart)
        return false;
    for (long k = 0; k < list->n; k++) {
        const uint32_t e = apart[k] ? unit_entry(g, list, k) : FAST_BOX_NONE;
        if (e != FAST_BOX_NONE)
            g->apart[g->n_apart++] = e;
    }
    return true;
}

/* Whether some surface's box reaches over more than half the scene's box [lo, hi] along an axis at least a
 * quarter of its longest, by the widest extent of any surface along each axis: a box of twelve triangles
 * is as wide along each axis as the widest of them, so where this is false no unit is large. */
static bool may_be_large(vec3 lo, vec3 hi, vec3 widest)
{
    const double extent[3] = {(double)hi.x - lo.x, (double)hi.y - lo.y, (double)hi.z - lo.z},
                 wide[3] = {widest.x, widest.y, widest.z};
    const double longest = fmax(extent[0], fmax(extent[1], extent[2]));
    bool may = false;
    for (int a = 0; a < 3; a++)
        may = may || (extent[a] >= longest / 4 && wide[a] > extent[a] / 2);
    return may;
}

bool fast_grid_fit(fast_grid *g, const surface_list *list, fast_grid_options opt, vec3 lo, vec3 hi, vec3 widest,
                   long binned, uint32_t **subset, long *n)
{
    bool *apart = calloc((size_t)list->n, sizeof *apart);
    if (!apart)
        return false;
    if (opt.list_up_to > 0 && may_be_large(lo, hi, widest) &&
        find_apart(g, list, opt.list_up_to, opt.density, opt.max_cells, apart, &lo, &hi, &binned)) {
        g->lo = vec3_sub(lo, vec3_make(g->margin, g->margin, g->margin));
        g->hi = vec3_add(hi, vec3_make(g->margin, g->margin, g->margin));
        *subset = malloc((size_t)list->n * sizeof **subset);
        *n = 0;
        for (long k = 0; *subset && k < list->n; k++)
            if (!apart[k])
                (*subset)[(*n)++] = (uint32_t)k;
    }
    const double extent[3] = {(double)hi.x - (double)lo.x, (double)hi.y - (double)lo.y, (double)hi.z - (double)lo.z};
    fast_grid_resolution(extent, binned, opt.density, opt.max_cells, g->n);
    const real w = 2 * g->margin, cell[3] = {(hi.x - lo.x + w) / (real)g->n[0], (hi.y - lo.y + w) / (real)g->n[1],
                                             (hi.z - lo.z + w) / (real)g->n[2]};
    fast_boxes_keep_small(&g->boxes, cell, apart);
    const bool kept = *n == list->n || (*subset && keep_apart(g, list, apart));
    free(apart);
    if (!kept) {
        free(*subset);
        *subset = NULL;
    }
    return kept;
}
