/* fast_build.h - chapter 11's lab: the parts of the fast grid's build that both levels use.
 *
 * fast_build.c builds a grid's cells over a box and a set of surfaces;
 * fast_levels.c gives a crowded cell a grid of its own with the same parts.
 */
#ifndef CH11_LAB_FAST_BUILD_H
#define CH11_LAB_FAST_BUILD_H

#include "11_grid/lab/fast_grid.h"

/* fmin and fmax without the library's call, which the build made twelve
 * times a triangle: the other value where one is NaN, as they do (the sign
 * of a zero bound is the only difference, and no bound reads it). */
static inline real lesser(real x, real y) { return x < y || y != y ? x : y; }
static inline real greater(real x, real y) { return x > y || y != y ? x : y; }

/* A surface's bounding box: a sphere's centre +- R, a triangle's vertices' extremes (fast_bounds.c). */
void fast_grid_surface_bounds(const surface *s, vec3 *lo, vec3 *hi);

/* The bounds of what entry k of a cell stands for: surface k, or, where g->boxes
 * has k as a box's first triangle, that box (a box is listed once, by its first). */
void fast_grid_entry_bounds(const fast_grid *g, uint32_t k, vec3 *lo, vec3 *hi);

/* The part of the box [lo, hi] (widened by the margin) inside cell (i, j, k), for culling: fast_build.c's cull_box. */
void fast_grid_cull_box(const fast_grid *g, vec3 lo, vec3 hi, int i, int j, int k, uint8_t box[6]);

struct fast_box;
/* The culling box of box b's entry in cell (i, j, k): the parts of its triangles' boxes there (fast_bounds.c). */
void fast_grid_box_cull_box(const fast_grid *g, const struct fast_box *b, int i, int j, int k, uint8_t box[6]);

/* Cells along each axis for a box of these extents holding `surfaces`:
 * about density x surfaces in all, at most max_cells, as cubic as the box allows. */
void fast_grid_resolution(const double extent[3], long surfaces, double density, long max_cells, int n[3]);

/* The cells of g, whose list, box (lo, hi), n, margin and scale are set:
 * the cell sizes, the table of planes, each cell's list of the surfaces
 * `subset` (n of them; NULL: the list's surfaces 0 .. n - 1, those with
 * finite bounds) and, with `leap`, the empty cubes.  0, or -1 with the
 * problem in err; what it allocated is then g's, for fast_grid_free. */
int fast_grid_fill(fast_grid *g, const uint32_t *subset, long n, bool leap, char *err, size_t err_size);

/* The leap table g->empty (allocated, n_cells x 8 bytes) of a grid whose
 * lists are filled: fast_empty.c.  False when out of memory. */
bool fast_grid_empty_distances(fast_grid *g);

/* Two levels: each cell of g that lists more than opt.split surfaces gets a
 * grid of its own over its box and those surfaces but the ones that span
 * the cell along two axes (a floor), and lists that grid (an entry
 * FAST_GRID_SUB + its index in g->subs) and then those.  0, or -1 with the
 * problem in err. */
int fast_grid_split(fast_grid *g, fast_grid_options opt, char *err, size_t err_size);

/* The lists of g and of its sub-grids packed for the march (fast_pack.c):
 * g->lists from g->refs, in the same memory.  False when out of memory. */
bool fast_grid_pack(fast_grid *g);

/* A scene of few surfaces, a list: g->units (n_units entries, a surface or
 * FAST_GRID_BOX + a box of g->boxes) when the units with finite bounds cost
 * a ray at most up_to triangle tests, boxes and spheres by their measured
 * weight (fast_few.c); else g is left as it is.  False when out of memory. */
bool fast_grid_few_units(fast_grid *g, const surface_list *list, int up_to);

/* The cells of a grid that is not a list, before fast_grid_fill: the few
 * large surfaces of the scene set apart (g->apart, tested for every ray:
 * fast_few.c says which), the cells' box (g->lo, g->hi: the others' box,
 * widened by the margin) and resolution (g->n) for the box [lo, hi] of the
 * `binned` surfaces with finite bounds (`widest`: their largest extent along
 * each axis), and the boxes kept (fast_boxes_keep_small).
 * *subset and *n are then the surfaces to bin (NULL and list->n: all of
 * them); *subset is the caller's to free.  False when out of memory. */
bool fast_grid_fit(fast_grid *g, const surface_list *list, fast_grid_options opt, vec3 lo, vec3 hi, vec3 widest,
                   long binned, uint32_t **subset, long *n);

/* The memory of g's sub-grids. */
size_t fast_grid_subs_memory(const fast_grid *g);

#endif
