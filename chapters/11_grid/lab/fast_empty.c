/* fast_empty.c - chapter 11's lab: the empty cubes ahead of each cell, for leaping. */
#include <stdlib.h>
#include <string.h>

#include "11_grid/lab/fast_build.h"

/* empty[o n_cells + c]: for a ray in cell c heading into octant o (bit 0: x
 * decreasing, bit 1: y, bit 2: z), the side s of the largest cube of empty
 * cells that has c as its corner and lies ahead of c in that octant: cells
 * i .. i + (s - 1) sgn_x along x, and so along y and z.  0 for a cell with
 * surfaces; at most g->beyond (255, or less for a small grid); cells beyond the grid count as empty (a ray that
 * leaves the grid is done).  The classic "largest empty square" recurrence in
 * 3D: s = 1 + the least s of the 7 neighbours one step ahead (and at most
 * g->beyond), filled in the order in which those neighbours come first.
 * Each octant is filled in its own copy of the cells, `side`, indexed so
 * that the cells ahead are those of higher index (f_a = i_a, or n_a - 1 - i_a
 * for a decreasing axis), with one more layer past the far faces that holds
 * g->beyond - 1: the 7 neighbours are then at fixed offsets, without a test
 * for the grid's end, and 6 of them lie in rows already done.  False when
 * out of memory. */
bool fast_grid_empty_distances(fast_grid *g)
{
    const int n0 = g->n[0], n1 = g->n[1], n2 = g->n[2];
    const long m0 = n0 + 1, m01 = m0 * (n1 + 1); /* the strides of `side` */
    const size_t count = (size_t)m01 * (size_t)(n2 + 1);
    uint8_t *side = malloc(count), *occupied = malloc((size_t)g->n_cells), *least = malloc((size_t)n0);
    if (!side || !occupied || !least) {
        free(side);
        free(occupied);
        free(least);
        return false;
    }
    for (long c = 0; c < g->n_cells; c++)
        occupied[c] = g->start[c + 1] != g->start[c];
    const uint8_t far = (uint8_t)(g->beyond - 1);
    for (int o = 0; o < 8; o++) {
        memset(side, far, count); /* the layer past the far faces: empty as far as any cube goes */
        for (int f2 = n2 - 1; f2 >= 0; f2--)
            for (int f1 = n1 - 1; f1 >= 0; f1--) {
                uint8_t *s = side + m0 * f1 + m01 * f2; /* the row (f_1, f_2) */
                /* The 6 neighbours in the rows ahead along f_1 and f_2, done, for the whole row at once
                 * (loads that no step of the row waits for)... */
                const uint8_t *y = s + m0, *z = s + m01, *yz = s + m01 + m0;
#pragma omp simd /* least does not overlap the rows it reads: sixteen cells to an instruction */
                for (int f0 = 0; f0 < n0; f0++) {
                    uint8_t l = far;
                    l = y[f0] < l ? y[f0] : l;
                    l = y[f0 + 1] < l ? y[f0 + 1] : l;
                    l = z[f0] < l ? z[f0] : l;
                    l = z[f0 + 1] < l ? z[f0 + 1] : l;
                    l = yz[f0] < l ? yz[f0] : l;
                    l = yz[f0 + 1] < l ? yz[f0 + 1] : l;
                    least[f0] = l;
                }
                /* ... then the row itself, against f_0: the seventh neighbour is the cell before. */
                const int j = o & 2 ? n1 - 1 - f1 : f1, k = o & 4 ? n2 - 1 - f2 : f2;
                const long di = o & 1 ? 1 : -1; /* what a step to the next lower f_0 adds to c */
                long c = (o & 1 ? 0 : n0 - 1) + n0 * (j + (long)n1 * k);
                uint8_t v = far; /* the cell before, s[f0 + 1], kept in a register: a store and a load of it
                                  * would make every step wait for the one before */
                for (int f0 = n0 - 1; f0 >= 0; f0--, c += di) {
                    const uint8_t l = v < least[f0] ? v : least[f0];
                    v = occupied[c] ? 0 : (uint8_t)(l + 1);
                    s[f0] = v;
                    g->empty[(long)o * g->n_cells + c] = v;
                }
            }
    }
    free(side);
    free(occupied);
    free(least);
    size_t held = fast_grid_memory(g) + count + (size_t)g->n_cells + (size_t)n0; /* the grid and the copies */
    g->peak_bytes = held > g->peak_bytes ? held : g->peak_bytes;
    return true;
}
