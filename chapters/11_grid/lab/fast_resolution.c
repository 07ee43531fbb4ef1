/* fast_resolution.c - chapter 11's lab: how many cells a fast grid (or a cell's own grid) gets along each axis. */
#include "11_grid/lab/fast_build.h"

#include <math.h>
#include <stdbool.h>

/* snippet: resolution */
/* Cells along each axis: about density x N cells in all, as cubic as the box
 * allows (n_a proportional to the box's extent e_a).  An axis of zero extent
 * (a flat scene) gets one cell and the others share the count. */
void fast_grid_resolution(const double extent[3], long surfaces, double density, long max_cells, int n[3])
{
    /* s cells per largest extent along every spanned axis: prod (e_a s) = wanted.
     * An axis too thin for one cell at that spacing (e_a s < 1/2) gets one,
     * and the others share the cells: so a box that is thin but not quite
     * flat (a cell of floor in a grid of two levels) is not cut into
     * millions of slivers. */
    double wanted = fmin(density * (double)surfaces, (double)max_cells), s = 0;
    /* in units of the largest extent, as the lesson's grid_resolution: no product of extents that
     * overflows or underflows at a scene's extreme scale */
    const double largest = fmax(fmax(extent[0], extent[1]), extent[2]);
    double e[3];
    bool spans[3];
    for (int a = 0; a < 3; a++) {
        spans[a] = extent[a] > 0;
        e[a] = spans[a] ? extent[a] / largest : 0;
    }
    int spanned;
    for (bool thinned = true; thinned;) {
        double volume = 1;
        spanned = 0;
        for (int a = 0; a < 3; a++)
            if (spans[a]) {
                volume *= e[a];
                spanned++;
            }
        s = spanned ? fmin(pow(fmax(wanted, 1) / volume, 1.0 / spanned), 1e300) : 0;
        thinned = false;
        for (int a = 0; a < 3; a++)
            if (spans[a] && spanned > 1 && e[a] * s < 0.5) {
                spans[a] = false;
                thinned = true;
            }
    }
    for (;;) {
        double cells = 1;
        for (int a = 0; a < 3; a++) {
            double na = spans[a] ? fmin(fmax(round(e[a] * s), 1), 1 << 20) : 1;
            n[a] = (int)na;
            cells *= na;
        }
        if (cells <= (double)max_cells)
            return;
        s *= 0.99 * pow((double)max_cells / cells, 1.0 / (spanned ? spanned : 1));
    }
}
/* end snippet */
