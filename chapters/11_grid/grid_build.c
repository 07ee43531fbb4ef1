/* grid_build.c - chapter 11: the grid's cells and the surfaces listed in each. */
#include "11_grid/grid.h"
#include "exercise.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

grid_options grid_default_options(void)
{
    return (grid_options){.density = GRID_DEFAULT_DENSITY, .max_cells = GRID_DEFAULT_MAX_CELLS};
}

static real get(vec3 v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }
static vec3 widen(vec3 v, real m) { return vec3_make(v.x + m, v.y + m, v.z + m); }

/* A surface's bounding box: a sphere's centre +- R, a triangle's vertices' extremes. */
static void surface_bounds(const surface *s, vec3 *lo, vec3 *hi)
{
    if (s->kind == SHAPE_SPHERE) {
        real r = real_abs(s->sphere.radius);
        vec3 c = s->sphere.center;
        *lo = vec3_make(c.x - r, c.y - r, c.z - r);
        *hi = vec3_make(c.x + r, c.y + r, c.z + r);
        return;
    }
    const triangle *t = &s->triangle;
    *lo = vec3_make(real_fmin(t->a.x, real_fmin(t->b.x, t->c.x)), real_fmin(t->a.y, real_fmin(t->b.y, t->c.y)),
                    real_fmin(t->a.z, real_fmin(t->b.z, t->c.z)));
    *hi = vec3_make(real_fmax(t->a.x, real_fmax(t->b.x, t->c.x)), real_fmax(t->a.y, real_fmax(t->b.y, t->c.y)),
                    real_fmax(t->a.z, real_fmax(t->b.z, t->c.z)));
}

static bool bounded(const surface *s)
{
    vec3 lo, hi;
    surface_bounds(s, &lo, &hi);
    return vec3_is_finite(lo) && vec3_is_finite(hi);
}

/* snippet: resolution */
void grid_resolution(const double extent[3], long surfaces, double density, long max_cells, int n[3])
{
    /* TODO resolution: the cells along each axis from the density (README, "The grid's box and
     * resolution"): about density x surfaces cells in all, cubic cells over the box's spanned axes,
     * never more than max_cells; an axis of zero extent gets one cell. */
    EXERCISE_STUB("11_grid", "grid_build.c", "resolution"); /* delete this line when done */
    (void)extent;
    (void)surfaces;
    (void)density;
    (void)max_cells;
    n[0] = n[1] = n[2] = 1;
}
/* end snippet */

/* A cell coordinate clamped to [lowest, highest] before it becomes an int,
 * so that a far or non-finite coordinate never overflows the conversion. */
static int clamp_index(real f, int lowest, int highest)
{
    if (!(f >= (real)lowest)) /* also NaN */
        return lowest;
    if (f >= (real)highest)
        return highest;
    return (int)f;
}

/* snippet: cell_range */
void grid_cell_range(const grid *g, vec3 box_lo, vec3 box_hi, int first[3], int last[3])
{
    /* TODO cell_range: the cells the box overlaps along each axis (README, "Listing the
     * surfaces"), boundaries counting for the cells on both sides, clamped to the grid with
     * clamp_index. */
    EXERCISE_STUB("11_grid", "grid_build.c", "cell_range"); /* delete this line when done */
    (void)g;
    (void)box_lo;
    (void)box_hi;
    (void)clamp_index;
    (void)get;
    for (int a = 0; a < 3; a++) {
        first[a] = 0;
        last[a] = -1;
    }
}
/* end snippet */

/* Lists surface k in every cell its box (widened by the margin) overlaps:
 * counts it there (fill NULL) or writes k at fill[cell]++. */
static void bin_surface(grid *g, int k, uint32_t *count, uint32_t *fill)
{
    vec3 lo, hi;
    surface_bounds(&g->list->items[k], &lo, &hi);
    int first[3], last[3];
    grid_cell_range(g, widen(lo, -g->margin), widen(hi, g->margin), first, last);
    for (int z = first[2]; z <= last[2]; z++)
        for (int y = first[1]; y <= last[1]; y++)
            for (int x = first[0]; x <= last[0]; x++) {
                long c = x + (long)g->n[0] * (y + (long)g->n[1] * z);
                if (fill)
                    g->refs[fill[c]++] = (uint32_t)k;
                else
                    count[c]++;
            }
}

/* The box of the surfaces with finite bounds; the others go to g->unbinned. */
static long bound_all(grid *g, vec3 *lo, vec3 *hi)
{
    const surface_list *list = g->list;
    *lo = vec3_make(REAL_INFINITY, REAL_INFINITY, REAL_INFINITY);
    *hi = vec3_neg(*lo);
    long binned = 0;
    for (int k = 0; k < list->n; k++) {
        vec3 slo, shi;
        surface_bounds(&list->items[k], &slo, &shi);
        if (!bounded(&list->items[k])) {
            g->unbinned[g->n_unbinned++] = (uint32_t)k;
            continue;
        }
        *lo = vec3_make(real_fmin(lo->x, slo.x), real_fmin(lo->y, slo.y), real_fmin(lo->z, slo.z));
        *hi = vec3_make(real_fmax(hi->x, shi.x), real_fmax(hi->y, shi.y), real_fmax(hi->z, shi.z));
        binned++;
    }
    return binned;
}

int grid_build(grid *g, const surface_list *list, grid_options opt, char *err, size_t err_size)
{
    *g = (grid){.list = list};
    if (!(opt.density > 0) || opt.max_cells < 1 || opt.max_cells > (1L << 30)) {
        snprintf(err, err_size, "grid: density must be > 0 and the cell cap 1 .. 2^30 (got %g, %ld)", opt.density,
                 opt.max_cells);
        return -1;
    }
    g->unbinned = malloc((size_t)(list->n ? list->n : 1) * sizeof *g->unbinned);
    if (!g->unbinned)
        goto out_of_memory;
    vec3 lo, hi;
    long binned = bound_all(g, &lo, &hi);
    if (binned == 0)
        return 0; /* no cells: every ray misses the (empty) grid */

    /* snippet: margin */
    /* The margin: rounding moves a computed point (a hit, a cell boundary) by
     * a few REAL_EPSILON times its coordinates; every box is widened by far
     * more, so a surface is listed in every cell its hits can be computed to
     * lie in.  It also gives a flat scene's box a thickness. */
    real scale = real_fmax(vec3_max_abs(lo), vec3_max_abs(hi));
    g->margin = 64 * REAL_EPSILON * scale;
    if (!(g->margin > 0))
        g->margin = 1; /* every surface is a point at the origin */
    /* end snippet */
    double extent[3] = {(double)hi.x - (double)lo.x, (double)hi.y - (double)lo.y, (double)hi.z - (double)lo.z};
    grid_resolution(extent, binned, opt.density, opt.max_cells, g->n);
    g->lo = widen(lo, -g->margin);
    g->hi = widen(hi, g->margin);
    vec3 size = vec3_sub(g->hi, g->lo);
    g->cell = vec3_make(size.x / (real)g->n[0], size.y / (real)g->n[1], size.z / (real)g->n[2]);
    g->n_cells = (long)g->n[0] * g->n[1] * g->n[2];

    /* Count each cell's surfaces, sum the counts into offsets, then write the indices. */
    uint32_t *count = calloc((size_t)g->n_cells, sizeof *count);
    g->start = malloc(((size_t)g->n_cells + 1) * sizeof *g->start);
    if (!count || !g->start) {
        free(count);
        goto out_of_memory;
    }
    for (int k = 0; k < list->n; k++)
        if (bounded(&list->items[k]))
            bin_surface(g, k, count, NULL);
    uint64_t total = 0;
    for (long c = 0; c <= g->n_cells; c++) {
        g->start[c] = (uint32_t)total;
        total += c < g->n_cells ? count[c] : 0;
        if (total > UINT32_MAX) {
            free(count);
            grid_free(g);
            snprintf(err, err_size, "grid: more than 2^32 cell entries; lower the density or the cell cap");
            return -1;
        }
    }
    g->n_refs = (long)total;
    g->refs = malloc((total ? (size_t)total : 1) * sizeof *g->refs);
    if (!g->refs) {
        free(count);
        goto out_of_memory;
    }
    for (long c = 0; c < g->n_cells; c++)
        count[c] = g->start[c]; /* now where each cell's next index goes */
    for (int k = 0; k < list->n; k++)
        if (bounded(&list->items[k]))
            bin_surface(g, k, NULL, count);
    free(count);
    return 0;

out_of_memory:
    grid_free(g);
    snprintf(err, err_size, "grid: out of memory");
    return -1;
}

void grid_free(grid *g)
{
    free(g->start);
    free(g->refs);
    free(g->unbinned);
    g->start = g->refs = g->unbinned = NULL;
    g->n_cells = g->n_refs = g->n_unbinned = 0;
}

size_t grid_memory(const grid *g)
{
    size_t cells = g->start ? (size_t)g->n_cells + 1 : 0;
    return sizeof *g + (cells + (size_t)g->n_unbinned + (size_t)g->n_refs) * sizeof(uint32_t);
}
