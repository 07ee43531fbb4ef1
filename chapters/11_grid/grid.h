/* grid.h - chapter 11: a uniform grid over the scene, marched by a 3D-DDA (README, "The grid"), whose
 * grid_intersect gives surfaces_intersect's hit bit for bit, the first in the list among equal t. */
#ifndef CH11_GRID_H
#define CH11_GRID_H

#include "04_many_shapes/surface.h"
#include "box.h"
#include "index_lists.h"

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
    uint32_t *start, *refs;   /* cell c = i + n_x (j + n_y k) lists refs[start[c]] .. refs[start[c + 1] - 1] */
    real margin;              /* every box is widened by this: more than rounding moves a point */
} grid;
/* end snippet */

/* What marches did: cells visited, surface_intersect calls (the suite checks the march by them). */
typedef struct { uint64_t cells, tests; } grid_counts;

#define GRID_DEFAULT_DENSITY 2.0
#define GRID_DEFAULT_MAX_CELLS (1L << 24)
static inline grid_options grid_default_options(void) { return (grid_options){GRID_DEFAULT_DENSITY, GRID_DEFAULT_MAX_CELLS}; }

/* The grid of `list` (which must outlive it, unchanged): 0, or -1 with the problem in err. */
int grid_build(grid *g, const surface_list *list, grid_options opt, char *err, size_t err_size);
void grid_free(grid *g);
static inline size_t grid_memory(const grid *g) { return sizeof *g + (g->start ? (size_t)(g->n_cells + 2 + g->n_refs) * 4 : 0); }

/* Cells along each axis: about density x surfaces in all, as cubic as a box of these
 * extents allows, at most max_cells; one on an axis of zero extent. */
void grid_resolution(const double extent[3], long surfaces, double density, long max_cells, int n[3]);

/* The cells first[a] .. last[a] along each axis a that the box overlaps (a boundary
 * counts for both its cells), clamped to the grid: first > last when it lies outside. */
void grid_cell_range(const grid *g, vec3 box_lo, vec3 box_hi, int first[3], int last[3]);

/* The hit with the smallest t in (t_min, t_max), as surfaces_intersect finds it over
 * g->list; the counted one adds what the march did to *counts (when not NULL). */
bool grid_intersect_counted(const grid *g, ray r, real t_min, real t_max, hit_record *hit, grid_counts *counts);
static inline bool grid_intersect(const grid *g, ray r, real t_min, real t_max, hit_record *hit)
{
    return grid_intersect_counted(g, r, t_min, t_max, hit, NULL);
}

#endif
