/* grid_build.c - chapter 11: the grid's cells and the surfaces listed in each. */
#include "11_grid/grid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

void grid_resolution(const double extent[3], long surfaces, double density, long max_cells, int n[3])
{
    /* EXERCISE resolution: the cells along each axis from the density (README, "The grid's box and
     * resolution"): about density x surfaces cells in all, cubic cells over the box's spanned axes,
     * never more than max_cells; an axis of zero extent gets one cell. */
    /* the extents relative to the largest, e_a / e_max: the same counts, and a product that neither
     * overflows (a scene 1e103 across) nor underflows (one 1e-300 across) */
    const double largest = fmax(fmax(extent[0], extent[1]), extent[2]);
    double e[3], volume = 1;
    int spanned = 0;
    for (int a = 0; a < 3; a++) {
        e[a] = extent[a] > 0 ? extent[a] / largest : 0;
        if (extent[a] > 0) {
            volume *= e[a];
            spanned++;
        }
    }
    double wanted = fmin(density * (double)surfaces, (double)max_cells);
    /* s cells per largest extent on every spanned axis: the product of e_a s is `wanted` */
    double s = spanned ? fmin(pow(fmax(wanted, 1) / volume, 1.0 / spanned), 1e300) : 0;
    for (;;) {
        double cells = 1;
        for (int a = 0; a < 3; a++) {
            double na = extent[a] > 0 ? fmin(fmax(round(e[a] * s), 1), 1 << 20) : 1;
            n[a] = (int)na;
            cells *= na;
        }
        if (cells <= (double)max_cells)
            return;
        /* too many cells: shrink s, by a tenth at most, and round again */
        s *= fmax(0.9, 0.99 * pow((double)max_cells / cells, 1.0 / (spanned ? spanned : 1)));
    }
    /* STUB
    (void)extent, (void)surfaces, (void)density, (void)max_cells;
    n[0] = n[1] = n[2] = 1;
    END EXERCISE */
}

void grid_cell_range(const grid *g, vec3 box_lo, vec3 box_hi, int first[3], int last[3])
{
    /* EXERCISE cell_range: the cells the box overlaps along each axis (README, "Listing the
     * surfaces"), boundaries counting for the cells on both sides, clamped to the grid with
     * real_to_index (common/box.h). */
    for (int a = 0; a < 3; a++) {
        /* where the box starts and ends, in cells from the grid's low corner */
        real f_lo = (vec3_axis(box_lo, a) - vec3_axis(g->lo, a)) / vec3_axis(g->cell, a);
        real f_hi = (vec3_axis(box_hi, a) - vec3_axis(g->lo, a)) / vec3_axis(g->cell, a);
        first[a] = real_to_index(real_ceil(f_lo) - 1, 0, g->n[a]);
        last[a] = real_to_index(real_floor(f_hi), -1, g->n[a] - 1);
    }
    /* STUB
    (void)g, (void)box_lo, (void)box_hi;
    first[0] = first[1] = first[2] = 0, last[0] = last[1] = last[2] = -1;
    END EXERCISE */
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
