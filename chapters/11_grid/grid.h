/* grid.h - chapter 11: a uniform grid over the scene, marched by a 3D-DDA.
 *
 * The lecture's "Acceleration and Regular Grids" (README, "The grid"): the
 * scene's box split into n_x x n_y x n_z equal cells, each listing the
 * surfaces whose bounding boxes overlap it; a ray visits the cells it
 * pierces in order and tests only their surfaces, and a hit counts once it
 * lies in the cell being visited.
 *
 * grid_intersect answers chapter 04's question, surfaces_intersect's: the
 * same surface and bit for bit the same t, the first in the list among
 * equal t.  So a renderer swaps the one for the other in one line.
 */
#ifndef CH11_GRID_H
#define CH11_GRID_H

#include <stddef.h>
#include <stdint.h>

#include "04_many_shapes/surface.h"

/* snippet: grid */
typedef struct {
    double density; /* cells per surface: n_x n_y n_z is about density x (number of surfaces) */
    long max_cells; /* the cap on n_x n_y n_z */
} grid_options;

typedef struct {
    const surface_list *list; /* the surfaces; the grid holds their indices only */
    vec3 lo, hi;              /* the grid's box: the surfaces' bounding box, widened by `margin` */
    vec3 cell;                /* the size of one cell along x, y and z */
    int n[3];                 /* cells along x, y and z */
    long n_cells, n_refs;
    /* Cell c = i + n_x (j + n_y k) lists refs[start[c]] .. refs[start[c + 1] - 1]. */
    uint32_t *start;          /* n_cells + 1 offsets */
    uint32_t *refs;           /* surface indices, cell after cell, each cell's in increasing order */
    uint32_t *unbinned;       /* surfaces without finite bounds: tested for every ray */
    long n_unbinned;
    real margin;              /* every box is widened by this: more than rounding moves a point */
} grid;
/* end snippet */

/* What a march did: added to by grid_intersect_counted. */
typedef struct {
    uint64_t cells; /* cells visited */
    uint64_t tests; /* surface_intersect calls */
} grid_counts;

#define GRID_DEFAULT_DENSITY 2.0
#define GRID_DEFAULT_MAX_CELLS (1L << 24)

grid_options grid_default_options(void);

/* Builds the grid of `list`, which must outlive it and not change.  Returns
 * 0, or -1 with the problem in err (out of memory, a bad knob). */
int grid_build(grid *g, const surface_list *list, grid_options opt, char *err, size_t err_size);
void grid_free(grid *g);
size_t grid_memory(const grid *g);

/* Cells along each axis for `surfaces` surfaces in a box of the given
 * extents: about density x surfaces cells, as cubic as the box allows, at
 * most max_cells; an axis of zero extent gets one cell. */
void grid_resolution(const double extent[3], long surfaces, double density, long max_cells, int n[3]);

/* The cells a box [box_lo, box_hi] overlaps: first[a] .. last[a] along each
 * axis a, clamped to the grid; first[a] > last[a] on some axis when the box
 * lies wholly outside.  A box that touches a cell boundary overlaps the
 * cells on both sides. */
void grid_cell_range(const grid *g, vec3 box_lo, vec3 box_hi, int first[3], int last[3]);

/* The hit with the smallest t in (t_min, t_max), as surfaces_intersect
 * finds it over g->list; grid_intersect_counted adds what the march did to
 * *counts (when not NULL). */
bool grid_intersect(const grid *g, ray r, real t_min, real t_max, hit_record *hit);
bool grid_intersect_counted(const grid *g, ray r, real t_min, real t_max, hit_record *hit, grid_counts *counts);

#endif
