/* grid_build.c - chapter 11: the grid's cells and the surfaces listed in each. */
#include "11_grid/grid.h"
#include "exercise.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

void grid_resolution(const double extent[3], long surfaces, double density, long max_cells, int n[3])
{
    /* TODO resolution: the cells along each axis from the density (README, "The grid's box and
     * resolution"): about density x surfaces cells in all, cubic cells over the box's spanned axes,
     * never more than max_cells; an axis of zero extent gets one cell. */
    EXERCISE_STUB("11_grid", "grid_build.c", "resolution"); /* delete this line when done */
    (void)extent, (void)surfaces, (void)density, (void)max_cells;
    n[0] = n[1] = n[2] = 1;
}

void grid_cell_range(const grid *g, vec3 box_lo, vec3 box_hi, int first[3], int last[3])
{
    /* TODO cell_range: the cells the box overlaps along each axis (README, "Listing the
     * surfaces"), boundaries counting for the cells on both sides, clamped to the grid with
     * real_to_index (common/box.h). */
    EXERCISE_STUB("11_grid", "grid_build.c", "cell_range"); /* delete this line when done */
    (void)g, (void)box_lo, (void)box_hi;
    first[0] = first[1] = first[2] = 0, last[0] = last[1] = last[2] = -1;
}

static box surface_box(const surface *s)
{
    const triangle *t = &s->triangle;
    return s->kind == SHAPE_SPHERE ? box_of_sphere(s->sphere.center, s->sphere.radius) : box_of_triangle(t->a, t->b, t->c);
}

/* Surface k goes in every cell its box, widened by the margin, overlaps; without finite bounds, in
 * the last list, which every ray tests. */
static void list_surface(void *ctx, long k, index_lists_fill *fill)
{
    const grid *g = ctx;
    box b = surface_box(&g->list->items[k]);
    if (!box_is_finite(b)) {
        index_lists_put(fill, g->n_cells);
        return;
    }
    b = box_widen(b, g->margin);
    int first[3], last[3];
    grid_cell_range(g, b.lo, b.hi, first, last);
    for (int z = first[2]; z <= last[2]; z++)
        for (int y = first[1]; y <= last[1]; y++)
            for (int x = first[0]; x <= last[0]; x++)
                index_lists_put(fill, x + (long)g->n[0] * (y + (long)g->n[1] * z));
}

int grid_build(grid *g, const surface_list *list, grid_options opt, char *err, size_t err_size)
{
    *g = (grid){.list = list};
    if (!(opt.density > 0) || opt.max_cells < 1 || opt.max_cells > (1L << 30)) {
        snprintf(err, err_size, "grid: --grid-density must be above 0, --grid-cells 1 .. 2^30 (got %g, %ld)",
                 opt.density, opt.max_cells);
        return -1;
    }
    /* The box of the surfaces with finite bounds, widened by the margin (none: no cells). */
    box all = box_empty();
    long bounded = 0;
    for (int k = 0; k < list->n; k++) {
        box b = surface_box(&list->items[k]);
        if (box_is_finite(b))
            all = box_union(all, b), bounded++;
    }
    if (bounded) {
        g->margin = box_margin(all);
        double extent[3] = {(double)all.hi.x - (double)all.lo.x, (double)all.hi.y - (double)all.lo.y,
                            (double)all.hi.z - (double)all.lo.z};
        grid_resolution(extent, bounded, opt.density, opt.max_cells, g->n);
        all = box_widen(all, g->margin);
        g->lo = all.lo, g->hi = all.hi;
        vec3 size = vec3_sub(g->hi, g->lo);
        g->cell = vec3_make(size.x / (real)g->n[0], size.y / (real)g->n[1], size.z / (real)g->n[2]);
        g->n_cells = (long)g->n[0] * g->n[1] * g->n[2];
    }
    g->n_refs = index_lists_build(g->n_cells + 1, list->n, list_surface, g, &g->start, &g->refs, "grid", err, err_size);
    return g->n_refs < 0 ? -1 : 0;
}

void grid_free(grid *g)
{
    free(g->start), free(g->refs);
    *g = (grid){.list = g->list};
}
